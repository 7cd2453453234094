/* Bad input through the real command line: a clear FILE:LINE: message, exit
 * status 1, never a crash (the suite also runs under ASan+UBSan). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test_paths.h"

typedef struct cli_case {
	const char *asf, *amc;
	const char *want;     /* expected start of stderr's first line */
	const char *needle;   /* and something it must say */
} cli_case;

static const cli_case cases[] = {
	{ "bad/truncated.asf", "tiny.amc", "tests/data/bad/truncated.asf:20:", "missing 'end'" },
	{ "bad/garbled_number.asf", "tiny.amc", "tests/data/bad/garbled_number.asf:29:", "expected a number" },
	{ "bad/binary.asf", "tiny.amc", "tests/data/bad/binary.asf:3:", "NUL byte" },
	{ "bad/too_many_bones.asf", "tiny.amc", "tests/data/bad/too_many_bones.asf:", "SKP_MAX_BONES" },
	{ "bad/long_line.asf", "tiny.amc", "tests/data/bad/long_line.asf:4:", "SKP_MAX_LINE" },
	{ "tiny.asf", "bad/truncated.amc", "tests/data/bad/truncated.amc:8:", "expected 2 value(s), found 1" },
	{ "tiny.asf", "bad/unknown_bone.amc", "tests/data/bad/unknown_bone.amc:10:", "unknown bone 'elbow'" },
	{ "tiny.asf", "bad/wrong_count.amc", "tests/data/bad/wrong_count.amc:5:", "expected 3 value(s), found 4" },
	{ "tiny.asf", "bad/garbled_number.amc", "tests/data/bad/garbled_number.amc:8:", "found 'zero'" },
	{ "tiny.asf", "bad/long_line.amc", "tests/data/bad/long_line.amc:2:", "SKP_MAX_LINE" },
	{ "tiny.asf", "missing.amc", "tests/data/missing.amc: cannot open", "No such file" },
	{ "tiny.asf", "bad/empty.amc", "tests/data/bad/empty.amc: no frames", "at least one frame" },
	{ "tiny.asf", "tiny.amc --frame 9", "tests/data/tiny.amc: no frame 9", "1..2" },
	{ "tiny.asf", "tiny.amc --frame x", "skintool: --frame expects an integer", "'x'" },
};

static void run_case(const cli_case *c)
{
	char cmd[1024], err_path[] = "/tmp/skp_cli_XXXXXX";
	int fd = mkstemp(err_path);
	assert_true(fd >= 0);
	snprintf(cmd, sizeof cmd, "%s fk tests/data/%s tests/data/%s >/dev/null 2>%s", test_tool_path("skintool"),
		 c->asf, c->amc, err_path);
	int status = system(cmd);
	size_t n;
	char *err = test_read_file(err_path, &n);
	unlink(err_path);
	close(fd);
	assert_non_null(err);
	assert_true(WIFEXITED(status));
	if (WEXITSTATUS(status) != 1 || strncmp(err, c->want, strlen(c->want)) != 0 || !strstr(err, c->needle))
		fail_msg("%s %s: exit %d, stderr '%s'", c->asf, c->amc, WEXITSTATUS(status), err);
	free(err);
}

static void test_bad_inputs_fail_cleanly(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
		run_case(&cases[i]);
}

static void test_usage_errors(void **state)
{
	(void)state;
	char cmd[512];
	snprintf(cmd, sizeof cmd, "%s fk tests/data/tiny.asf >/dev/null 2>&1", test_tool_path("skintool"));
	int status = system(cmd);
	assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 1);
	snprintf(cmd, sizeof cmd, "%s nosuchcommand >/dev/null 2>&1", test_tool_path("skintool"));
	status = system(cmd);
	assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 1);
}

/* Motion through a pipe is read once, as motion (the image sniff does not
 * eat its first bytes); a header and no frame prints nothing on stdout. */
static void test_pipe_and_empty(void **state)
{
	(void)state;
	char fifo[] = "/tmp/skp_cli_fifo_XXXXXX", cmd[2400];
	assert_non_null(mkdtemp(fifo));
	snprintf(cmd, sizeof cmd, "cd %s && mkfifo m && (cat \"$OLDPWD/tests/data/tiny.amc\" > m &) && "
		 "timeout 300 \"$OLDPWD/%s\" fk \"$OLDPWD/tests/data/tiny.asf\" m > out.csv", fifo,
		 test_tool_path("skintool"));
	int status = system(cmd);
	char path[1100];
	snprintf(path, sizeof path, "%s/out.csv", fifo);
	size_t n;
	char *out = test_read_file(path, &n);
	assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
	assert_non_null(out);
	assert_non_null(strstr(out, "\n1,root,"));
	assert_non_null(strstr(out, "\n2,root,"));
	free(out);
	snprintf(cmd, sizeof cmd, "%s fk tests/data/tiny.asf tests/data/bad/empty.amc > %s 2>/dev/null",
		 test_tool_path("skintool"), path);
	status = system(cmd);
	assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 1);
	out = test_read_file(path, &n);
	assert_non_null(out);
	assert_int_equal(n, 0);
	free(out);
	snprintf(cmd, sizeof cmd, "rm -rf %s", fifo);
	assert_int_equal(system(cmd), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_bad_inputs_fail_cleanly),
		cmocka_unit_test(test_usage_errors),
		cmocka_unit_test(test_pipe_and_empty),
	};
	return cmocka_run_group_tests_name("cli_errors", tests, NULL, NULL);
}
