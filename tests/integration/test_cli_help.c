/* Both programs the GNU way (app/cli/cli_opts.c): every command answers
 * --help (usage, each option, exit codes; on stdout, exit 0) and
 * --version; --opt=value equals --opt value; a bad option says which and
 * points to --help (exit 1). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_paths.h"
#include "test_run.h"

static char *slurp(const char *name)
{
	char *text = test_read_file(test_scratch(name), NULL);
	assert_non_null(text);
	return text;
}

/* Runs "TOOL ARGS" with stdout and stderr kept; returns the exit status. */
static int run_tool(const char *tool, const char *args)
{
	return test_run("%s %s > %s 2> %s", test_tool_path(tool), args, test_scratch("out.txt"),
			test_scratch("err.txt"));
}

static void expect_help(const char *tool, const char *cmd)
{
	char args[128], want[128];
	snprintf(args, sizeof args, "%s --help", cmd);
	snprintf(want, sizeof want, "Usage: %s%s%s ", tool, cmd[0] ? " " : "", cmd);
	assert_int_equal(run_tool(tool, args), 0);
	char *out = slurp("out.txt"), *err = slurp("err.txt");
	if (strncmp(out, want, strlen(want)) != 0 || !strstr(out, "Exit status: 0") || err[0])
		fail_msg("%s %s --help: stdout '%.80s...', stderr '%s'", tool, cmd, out, err);
	/* every option listed has its line of help */
	assert_non_null(strstr(out, "  -h, --help "));
	free(out);
	free(err);
	snprintf(args, sizeof args, "%s --version", cmd);
	assert_int_equal(run_tool(tool, args), 0);
	out = slurp("out.txt");
	snprintf(want, sizeof want, "%s 0.", tool);
	if (strncmp(out, want, strlen(want)) != 0 || !strstr(out, "skinning kernels:"))
		fail_msg("%s %s --version: '%s'", tool, cmd, out);
	free(out);
}

static void test_every_command_has_help(void **state)
{
	(void)state;
	expect_help("skinplay", "");
	expect_help("skintool", "");
	/* the commands as skintool --help lists them */
	assert_int_equal(run_tool("skintool", "--help"), 0);
	char *list = slurp("out.txt");
	int commands = 0;
	for (char *line = strtok(list, "\n"); line; line = strtok(NULL, "\n")) {
		char name[32];
		if (line[0] == ' ' && line[1] == ' ' && line[2] != ' ' && line[2] != '-' &&
		    sscanf(line, " %31s", name) == 1) {
			char cmd[64];
			snprintf(cmd, sizeof cmd, "%s", name);
			expect_help("skintool", cmd);
			commands++;
		}
	}
	free(list);
	assert_int_equal(commands, 13);
}

static void test_option_forms(void **state)
{
	(void)state;
	/* --frame=2 and --frame 2 print the same rows */
	assert_int_equal(run_tool("skintool", "fk tests/data/tiny.asf tests/data/tiny.amc --frame=2"), 0);
	char *a = slurp("out.txt");
	assert_int_equal(run_tool("skintool", "fk --frame 2 --skeleton tests/data/tiny.asf --motion=tests/data/tiny.amc"),
			 0);
	char *b = slurp("out.txt");
	assert_string_equal(a, b);
	assert_non_null(strstr(a, "\n2,root,"));
	free(a);
	free(b);
	static const struct {
		const char *tool, *args, *err;
	} bad[] = {
		{ "skintool", "fk tests/data/tiny.asf tests/data/tiny.amc --frame=-1", "--frame expects a frame number" },
		{ "skintool", "fk --nosuch", "skintool fk: unknown option '--nosuch'\nTry 'skintool fk --help'" },
		{ "skintool", "bind tests/data/tiny.asf x.obj -o", "skintool bind: option needs a value: '-o'" },
		{ "skintool", "pack tests/data/tiny.asf tests/data/tiny.amc --sequence=-1 -o x.skn", "--sequence expects 0 to" },
		{ "skintool", "pack tests/data/tiny.asf tests/data/tiny.amc --fps 1e-30 -o x.skn", "--fps expects a rate" },
		{ "skintool", "nosuch", "skintool: unknown command 'nosuch'" },
		{ "skinplay", "--asf a --amc b --every 0", "skinplay: --every expects 1 or more, got 0" },
		{ "skinplay", "--asf a --amc b --frames=x", "skinplay: --frames expects an integer" },
		{ "skinplay", "--asf a --amc b --algo=best", "skinplay: unknown value 'best' for --algo; one of: lbs" },
		{ "skinplay", "--size", "skinplay: option needs a value: '--size'" },
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		assert_int_equal(run_tool(bad[i].tool, bad[i].args), 1);
		char *err = slurp("err.txt"), *out = slurp("out.txt");
		if (strncmp(err, bad[i].err, strlen(bad[i].err)) != 0 && !strstr(err, bad[i].err))
			fail_msg("%s %s: stderr '%s', want '%s'", bad[i].tool, bad[i].args, err, bad[i].err);
		assert_string_equal(out, "");
		free(err);
		free(out);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_command_has_help),
		cmocka_unit_test(test_option_forms),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
