/* The README's command blocks run as written: every ```sh block, in order,
 * in one shell from the repository root (its first block sets PATH to the
 * built programs and D to ../shared/data), stopping at the first failure.
 * Skips without ../shared/data or without build/skintool (a cross build). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test_paths.h"
#include "test_run.h"

/* The ```sh blocks of text, joined; NULL-safe counts in *blocks, *lines. */
static char *sh_blocks(const char *text, int *blocks, int *lines)
{
	size_t cap = strlen(text) + 1, n = 0;
	char *out = malloc(cap);
	assert_non_null(out);
	int in = 0;
	*blocks = *lines = 0;
	for (const char *p = text; *p;) {
		const char *e = strchr(p, '\n');
		size_t len = e ? (size_t)(e - p) : strlen(p);
		if (!in && len >= 5 && !strncmp(p, "```sh", 5) && len == 5) {
			in = 1;
			++*blocks;
		} else if (in && len == 3 && !strncmp(p, "```", 3)) {
			in = 0;
		} else if (in) {
			memcpy(out + n, p, len);
			n += len;
			out[n++] = '\n';
			++*lines;
		}
		p = e ? e + 1 : p + len;
	}
	out[n] = '\0';
	assert_false(in);
	return out;
}

static void test_readme_blocks_run(void **state)
{
	(void)state;
	if (access("../shared/data/mocap/cmu/02.asf", R_OK) != 0 || access("build/skintool", X_OK) != 0) {
		print_message("README blocks: need ../shared/data and build/skintool (make): skipped\n");
		skip();
	}
	char *readme = test_read_file("README.md", NULL);
	assert_non_null(readme);
	int blocks, lines;
	char *script = sh_blocks(readme, &blocks, &lines);
	free(readme);
	assert_true(blocks >= 5);
	const char *path = test_scratch("readme.sh"), *log = test_scratch("readme.log");
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	fputs(script, f);
	fclose(f);
	free(script);
	int rc = test_run("timeout 900 sh -e -x %s > %s 2>&1", path, log);
	if (rc != 0) {
		char *text = test_read_file(log, NULL);
		size_t len = text ? strlen(text) : 0;
		fail_msg("README block failed (exit %d); the end of its log:\n%s", rc,
			 text ? text + (len > 3000 ? len - 3000 : 0) : "(none)");
	}
	printf("README: %d blocks, %d lines ran\n", blocks, lines);
	/* what they say they make */
	assert_int_equal(access("out/walk/frame_000001.png", R_OK), 0);
	assert_int_equal(access("out/report/index.html", R_OK), 0);
	assert_int_equal(access("out/glb_report/index.html", R_OK), 0);
	assert_int_equal(access("out/135_06.bvh", R_OK), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_readme_blocks_run),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
