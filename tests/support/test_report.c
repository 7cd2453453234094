#include "test_report.h"

#include "test_paths.h"

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>

static char workdir[] = "/tmp/skp_compare_XXXXXX";

int test_report_setup(void **state)
{
	(void)state;
	strcpy(workdir, "/tmp/skp_compare_XXXXXX");
	return mkdtemp(workdir) ? 0 : -1;
}

int test_report_teardown(void **state)
{
	(void)state;
	char cmd[1200];
	if (getenv("SKP_KEEP_REPORT")) {
		fprintf(stderr, "reports kept in %s\n", workdir);
		return 0;
	}
	snprintf(cmd, sizeof cmd, "rm -rf %s", workdir);
	return system(cmd) == 0 ? 0 : -1;
}

const char *test_report_dir(void)
{
	return workdir;
}

double test_report_now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

int test_report_sh(const char *cmd, const char *out)
{
	char full[8192];
	snprintf(full, sizeof full, "%s >%s 2>%s/stderr.txt", cmd, out ? out : "/dev/null", workdir);
	int st = system(full);
	assert_true(WIFEXITED(st));
	return WEXITSTATUS(st);
}

const char *test_report_compare(const char *asf, const char *amc, const char *options, const char *name)
{
	static char dir[1024];
	char cmd[4096];
	snprintf(dir, sizeof dir, "%s/%s", workdir, name);
	snprintf(cmd, sizeof cmd, "%s compare %s %s %s%s-o %s", test_tool_path("skintool"), asf, amc, options,
		 *options ? " " : "", dir);
	assert_int_equal(test_report_sh(cmd, NULL), 0);
	return dir;
}

char *test_report_slurp(const char *path)
{
	char *text = test_read_file(path, NULL);
	if (!text)
		fail_msg("cannot read %s", path);
	return text;
}

void test_report_first_five_columns(char *text)
{
	char *w = text;
	for (char *r = text; *r;) {
		int commas = 0;
		while (*r && *r != '\n') {
			if (*r == ',' && ++commas == 5) {
				while (*r && *r != '\n')
					r++;
				break;
			}
			*w++ = *r++;
		}
		if (*r == '\n')
			*w++ = *r++;
	}
	*w = '\0';
}

const char *test_report_element(const char *html, const char *id)
{
	char key[128];
	snprintf(key, sizeof key, "id=\"%s\"", id);
	const char *p = strstr(html, key);
	if (!p)
		fail_msg("the page has no element %s", id);
	return p;
}

double test_report_luminance_stddev(const uint8_t *px, int w, int x0, int x1, int y0, int y1)
{
	double sum = 0, sum2 = 0, n = 0;
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++) {
			const uint8_t *p = px + 4 * ((size_t)y * (size_t)w + (size_t)x);
			double l = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
			sum += l, sum2 += l * l, n++;
		}
	return sqrt(fmax(0, sum2 / n - (sum / n) * (sum / n)));
}
