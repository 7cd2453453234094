/* The documentation's command blocks run as written: every ```sh block of
 * README.md, then of the folder docs (app/NAME/README.md, board/NAME/README.md,
 * tests/README.md, assets/README.md, each group in name order), in one shell
 * from the repository root (README's first block sets PATH to the built
 * programs and D to ../shared/data), stopping at the first failure.
 * Skips without ../shared/data or without build/skintool and build/skinplay
 * (a cross build, or the sanitizer build's tests alone: `make` first). */
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

/* README.md first: its first block sets what the others use. */
static const char *const doc_globs = "README.md app/*/README.md board/*/README.md tests/README.md assets/README.md";

/* Appends the ```sh blocks of one file to script; counts docs with blocks. */
static void add_blocks(FILE *script, const char *path, int *docs, int *blocks, int *lines)
{
	char *text = test_read_file(path, NULL);
	assert_non_null(text);
	int b, l;
	char *sh = sh_blocks(text, &b, &l);
	free(text);
	if (b) {
		fprintf(script, "# %s\n%s", path, sh);
		++*docs;
	}
	*blocks += b;
	*lines += l;
	free(sh);
}

static void test_readme_blocks_run(void **state)
{
	(void)state;
	/* the README puts build/ on PATH: its programs, whichever build runs
	 * this test (the sanitizer build's tests use them too) */
	if (access("../shared/data/mocap/cmu/02.asf", R_OK) != 0 || access("build/skintool", X_OK) != 0 ||
	    access("build/skinplay", X_OK) != 0) {
		print_message("README blocks: need ../shared/data, build/skintool and build/skinplay (make): skipped\n");
		skip();
	}
	const char *list = test_scratch("docs.txt");
	assert_int_equal(test_run("for f in %s; do [ -f \"$f\" ] && echo \"$f\"; done > %s", doc_globs, list), 0);
	char *files = test_read_file(list, NULL);
	assert_non_null(files);
	const char *path = test_scratch("readme.sh"), *log = test_scratch("readme.log");
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	int docs = 0, blocks = 0, lines = 0, readme_blocks = -1;
	char *save;
	for (char *doc = strtok_r(files, "\n", &save); doc; doc = strtok_r(NULL, "\n", &save)) {
		add_blocks(f, doc, &docs, &blocks, &lines);
		if (readme_blocks < 0)
			readme_blocks = blocks;
	}
	fclose(f);
	free(files);
	/* the README's five tasks, and the folder docs' examples */
	assert_true(readme_blocks >= 6);
	assert_true(docs >= 4);
	/* under the sanitizers or an emulator the blocks are read, not run:
	 * they run build/'s programs (README's PATH), not this build's, which
	 * the native run's test_readme runs alike (111 s of CI's sanitizer
	 * run in which no sanitized code ran but the lines above) */
	if (test_slow()) {
		print_message("docs: %d blocks in %d files (%d in README.md) read; they run in the native build's "
			      "test_readme\n", blocks, docs, readme_blocks);
		return;
	}
	/* what the blocks make, made afresh */
	static const char *const made = "out/motion out/bvh out/walk out/glb out/kiosk out/report out/show-b.skn "
					"out/glb_report out/mh_report out/135_06.bvh";
	assert_int_equal(test_run("rm -rf %s", made), 0);
	int rc = test_run("timeout 900 sh -e -x %s > %s 2>&1", path, log);
	if (rc != 0) {
		char *text = test_read_file(log, NULL);
		size_t len = text ? strlen(text) : 0;
		fail_msg("a documentation block failed (exit %d); the end of its log:\n%s", rc,
			 text ? text + (len > 3000 ? len - 3000 : 0) : "(none)");
	}
	printf("docs: %d blocks in %d files (%d in README.md), %d lines ran\n", blocks, docs, readme_blocks, lines);
	/* what they say they make: README.md's tasks */
	assert_int_equal(access("out/motion/frame_000061.png", R_OK), 0);
	assert_int_equal(access("out/bvh/frame_000031.png", R_OK), 0);
	assert_int_equal(access("out/walk/frame_000001.png", R_OK), 0);
	assert_int_equal(access("out/glb/frame_000031.png", R_OK), 0);
	assert_int_equal(access("out/kiosk/frame_000046.png", R_OK), 0);
	assert_int_equal(access("out/report/index.html", R_OK), 0);
	assert_int_equal(access("out/show-b.skn", R_OK), 0);
	/* app/import's, app/motion's */
	assert_int_equal(access("out/glb_report/index.html", R_OK), 0);
	assert_int_equal(access("out/mh_report/index.html", R_OK), 0);
	assert_int_equal(access("out/135_06.bvh", R_OK), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_readme_blocks_run),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
