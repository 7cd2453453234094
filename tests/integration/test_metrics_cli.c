/* `skintool metrics` through the real command line: the synthetic twist
 * reproduces the known LBS/DQBS radii, a CMU clip on the generated body
 * gives one row per frame per algorithm under the documented header, and
 * bad arguments fail cleanly. */
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
#include <unistd.h>

#include "test_paths.h"
#include "test_run.h"

#define HEADER "frame,algo,volume_ratio,min_radius_ratio,max_radius_ratio"

typedef struct row {
	long frame;
	char algo[16];
	double volume, rmin, rmax;
} row;

/* Runs cmd with stdout into a file; returns its text (caller frees) and
 * the exit status in *status. */
static char *run(const char *cmd, int *status)
{
	char out_path[] = "/tmp/skp_metrics_XXXXXX", full[4096];
	int fd = mkstemp(out_path);
	assert_true(fd >= 0);
	close(fd);
	snprintf(full, sizeof full, "%s >%s 2>/dev/null", cmd, out_path);
	int st = system(full);
	assert_true(WIFEXITED(st));
	*status = WEXITSTATUS(st);
	char *text = test_read_file(out_path, NULL);
	unlink(out_path);
	assert_non_null(text);
	return text;
}

/* Checks the header line and parses the rows after it; returns their count. */
static int parse_rows(char *text, row *rows, int max)
{
	char *save, *line = strtok_r(text, "\n", &save);
	assert_non_null(line);
	assert_string_equal(line, HEADER);
	int n = 0;
	while ((line = strtok_r(NULL, "\n", &save))) {
		assert_true(n < max);
		row *r = &rows[n++];
		if (sscanf(line, "%ld,%15[^,],%lf,%lf,%lf", &r->frame, r->algo, &r->volume, &r->rmin,
			   &r->rmax) != 5)
			fail_msg("bad row '%s'", line);
	}
	return n;
}

static void test_scene_twist_90(void **state)
{
	(void)state;
	char cmd[1024];
	int status;
	row rows[8];
	snprintf(cmd, sizeof cmd, "%s metrics --scene twist --angle 90", test_tool_path("skintool"));
	char *text = run(cmd, &status);
	assert_int_equal(status, 0);
	int n = parse_rows(text, rows, 8);
	free(text);
	assert_int_equal(n, 3);
	const double c45 = cos(M_PI / 4);
	for (int i = 0; i < n; i++) {
		print_message("twist 90: %-10s volume %.6f, radius %.6f..%.6f\n", rows[i].algo,
			      rows[i].volume, rows[i].rmin, rows[i].rmax);
		assert_int_equal(rows[i].frame, 0);
	}
	assert_string_equal(rows[0].algo, "lbs");
	assert_string_equal(rows[1].algo, "dqbs");
	assert_string_equal(rows[2].algo, "dqbs-fixed");
	assert_true(fabs(rows[0].rmin - c45) < 1e-2);
	assert_true(rows[0].volume < 0.95);
	for (int i = 1; i < 3; i++) {
		assert_true(fabs(rows[i].rmin - 1) < 1e-2 && fabs(rows[i].rmax - 1) < 1e-2);
		assert_true(fabs(rows[i].volume - 1) < 1e-2);
	}
}

static void test_scene_algo_list(void **state)
{
	(void)state;
	char cmd[1024];
	int status;
	row rows[8];
	snprintf(cmd, sizeof cmd, "%s metrics --scene bend --angle 135 --algo dqbs,lbs", test_tool_path("skintool"));
	char *text = run(cmd, &status);
	assert_int_equal(status, 0);
	int n = parse_rows(text, rows, 8);
	free(text);
	assert_int_equal(n, 2);
	assert_string_equal(rows[0].algo, "dqbs");
	assert_string_equal(rows[1].algo, "lbs");
	assert_true(rows[1].volume < rows[0].volume);
}

static void test_cmu_clip_rows(void **state)
{
	(void)state;
	const char *asf = test_data_path("mocap/cmu/09.asf"), *amc = test_data_path("mocap/cmu/09_06.amc");
	if (!asf)
		skip();
	static row rows[1024];
	char dir[] = "/tmp/skp_metrics_XXXXXX", body[256], cmd[2048];
	int status;
	assert_non_null(mkdtemp(dir));
	snprintf(body, sizeof body, "%s/body.obj", dir);
	/* under the sanitizers or an emulator a coarser body (the default
	 * one's bind and 423 skinned frames took 20 s under qemu) */
	snprintf(cmd, sizeof cmd, "%s mannequin %s %s -o %s", test_tool_path("skintool"), asf,
		 test_mannequin_detail(), body);
	free(run(cmd, &status));
	assert_int_equal(status, 0);
	snprintf(cmd, sizeof cmd, "%s metrics %s %s %s", test_tool_path("skintool"), asf, amc, body);
	char *text = run(cmd, &status);
	unlink(body);
	rmdir(dir);
	assert_int_equal(status, 0);
	int n = parse_rows(text, rows, 1024);
	free(text);
	static const char *const algos[3] = { "lbs", "dqbs", "dqbs-fixed" };
	assert_int_equal(n, 141 * 3);
	double vmin = 1e9, vmax = 0;
	for (int i = 0; i < n; i++) {
		assert_int_equal(rows[i].frame, 1 + i / 3);
		assert_string_equal(rows[i].algo, algos[i % 3]);
		assert_true(rows[i].volume > 0.8 && rows[i].volume < 1.2);
		assert_true(rows[i].rmin >= 0 && rows[i].rmin <= rows[i].rmax);
		vmin = fmin(vmin, rows[i].volume);
		vmax = fmax(vmax, rows[i].volume);
	}
	print_message("09_06.amc: %d rows, volume ratio %.4f..%.4f\n", n, vmin, vmax);
}

static void expect_fail(const char *args)
{
	char cmd[1024];
	snprintf(cmd, sizeof cmd, "%s %s >/dev/null 2>&1", test_tool_path("skintool"), args);
	int st = system(cmd);
	if (!WIFEXITED(st) || WEXITSTATUS(st) != 1)
		fail_msg("'skintool %s' should exit 1", args);
}

static void test_bad_arguments(void **state)
{
	(void)state;
	expect_fail("metrics");
	expect_fail("metrics --scene screw --angle 90");
	expect_fail("metrics --scene twist");
	expect_fail("metrics --scene twist --angle ninety");
	expect_fail("metrics --scene twist --angle 90 --algo lbs,fast");
	expect_fail("metrics tests/data/tiny.asf tests/data/tiny.amc missing.obj");
	expect_fail("skin tests/data/tiny.asf tests/data/tiny.amc missing.obj --frame 1 --algo lbs -o /dev/null");
	expect_fail("skin tests/data/tiny.asf tests/data/tiny.amc x.obj --algo lbs -o /dev/null");
	expect_fail("skin tests/data/tiny.asf tests/data/tiny.amc x.obj --frame 1 --algo slow -o /dev/null");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_scene_twist_90),
		cmocka_unit_test(test_scene_algo_list),
		cmocka_unit_test(test_cmu_clip_rows),
		cmocka_unit_test(test_bad_arguments),
	};
	return cmocka_run_group_tests_name("metrics_cli", tests, NULL, NULL);
}
