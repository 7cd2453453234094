/* Every input kept under tests/fuzz/regressions/<target>/ (crashes the
 * fuzzers found, once fixed, and hand-made edge cases) goes through the same
 * harness as the libFuzzer target (tests/fuzz/fuzz_harness.c): a crash, an
 * ASan/UBSan report (SANITIZE=1) or a hang fails `make test`. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_paths.h"

/* One translation unit: the harness is not part of the test support lib. */
#include "../fuzz/fuzz_harness.c"

static void run_target(void **state)
{
	const fuzz_target *t = *state;
	char dir[256], path[512];
	snprintf(dir, sizeof dir, "tests/fuzz/regressions/%s", t->name);
	DIR *d = opendir(dir);
	if (!d)
		fail_msg("%s: missing (every fuzz target keeps its regression inputs there)", dir);
	int n = 0;
	struct dirent *e;
	while ((e = readdir(d)) != NULL) {
		if (e->d_name[0] == '.')
			continue;
		snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
		size_t size = 0;
		char *data = test_read_file(path, &size);
		if (!data)
			fail_msg("%s: cannot read", path);
		t->run((const uint8_t *)data, size);
		free(data);
		n++;
	}
	closedir(d);
	printf("fuzz regressions: %s: %d input(s) ran cleanly\n", t->name, n);
	assert_true(n > 0);
}

int main(void)
{
	struct CMUnitTest tests[16];
	int n = 0;
	for (const fuzz_target *t = fuzz_targets; t->name && n < 16; t++) {
		struct CMUnitTest c = { t->name, run_target, NULL, NULL, (void *)t };
		tests[n++] = c;
	}
	return _cmocka_run_group_tests("fuzz_regressions", tests, (size_t)n, NULL, NULL);
}
