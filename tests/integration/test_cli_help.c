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
	if (strncmp(out, want, strlen(want)) != 0 || !strstr(out, "\nExit status:\n  0  done\n") || err[0])
		fail_msg("%s %s --help: stdout '%.80s...', stderr '%s'", tool, cmd, out, err);
	/* every option listed has its line of help */
	assert_non_null(strstr(out, "  -h, --help "));
	free(out);
	free(err);
	/* under the sanitizers or an emulator --version (the same code for
	 * every command) for the programs and their first command only */
	static int versions;
	if (test_slow() && versions++ >= 3)
		return;
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
		if (line[0] == ' ' && line[1] == ' ' && line[2] >= 'a' && line[2] <= 'z' &&
		    sscanf(line, " %31s", name) == 1) {
			char cmd[64];
			snprintf(cmd, sizeof cmd, "%s", name);
			expect_help("skintool", cmd);
			commands++;
		}
	}
	free(list);
	assert_int_equal(commands, 14);
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

/* -q before or after the command leaves stderr empty on a good run: no
 * notes on the choices made, no progress, no summary; the command's own
 * output (fk's rows, info) still on stdout. Without -q the same runs say
 * something (so the check can fail). */
static void run_quiet(const char *tool, const char *before, const char *cmd, const char *args, int expect_notes)
{
	char line[1024];
	snprintf(line, sizeof line, "%s%s%s %s", before, before[0] ? " " : "", cmd, args);
	if (run_tool(tool, line) != 0)
		fail_msg("%s %s: exit status not 0: %s", tool, line, slurp("err.txt"));
	char *err = slurp("err.txt");
	if (expect_notes ? !err[0] : err[0] != '\0')
		fail_msg("%s %s: stderr %s: '%s'", tool, line, expect_notes ? "empty" : "not empty", err);
	free(err);
}

static void test_quiet_everywhere(void **state)
{
	(void)state;
	static const struct {
		const char *cmd, *args;
		int notes; /* says something on stderr without -q */
	} runs[] = {
		{ "fk", "tests/data/tiny.asf tests/data/tiny.amc", 0 },
		{ "mannequin", "tests/data/tiny.asf -o %s/m.obj", 0 },
		{ "convert", "tests/data/tiny.asf tests/data/tiny.amc -o %s/t.bvh", 0 },
		{ "bind", "tests/data/tiny.asf %s/m.obj -o %s/w.csv", 1 },
		{ "skin", "tests/data/tiny.asf tests/data/tiny.amc %s/m.obj --frame 1 --algo dqbs -o %s/s.obj", 1 },
		{ "metrics", "tests/data/tiny.asf tests/data/tiny.amc %s/m.obj", 1 },
		{ "compare", "tests/data/tiny.asf tests/data/tiny.amc --renders 0 -o %s/report%d", 1 },
		{ "pack", "tests/data/tiny.asf tests/data/tiny.amc -o %s/t.skn", 0 },
		{ "info", "%s/t.skn", 0 },
		{ "repair", "%s/t.skn", 0 },
		{ "bench", "--verts 64 --rounds 1", 1 },
		{ "bench-parse", "tests/data/tiny.asf tests/data/tiny.amc --runs 1", 0 },
		{ "bench-image", "%s/t.skn --runs 1", 0 },
	};
	const char *dir = test_scratch_dir();
	int report = 0;
	for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
		char args[512];
		int uses = 0;
		for (const char *p = runs[i].args; (p = strstr(p, "%s")); p += 2)
			uses++;
		for (int form = 0; form < 3; form++) {
			/* under the sanitizers or an emulator (39 runs, 9 s under
			 * qemu) -q before and --quiet after take turns */
			if (test_slow() && form && form != 1 + (int)(i % 2))
				continue;
			/* compare writes a new folder each time */
			if (uses == 2)
				snprintf(args, sizeof args, runs[i].args, dir, dir);
			else if (strstr(runs[i].args, "%d"))
				snprintf(args, sizeof args, runs[i].args, dir, report++);
			else
				snprintf(args, sizeof args, runs[i].args, dir);
			if (form == 0)
				run_quiet("skintool", "", runs[i].cmd, args, runs[i].notes);
			else if (form == 1)
				run_quiet("skintool", "-q", runs[i].cmd, args, 0);
			else {
				strncat(args, " --quiet", sizeof args - strlen(args) - 1);
				run_quiet("skintool", "", runs[i].cmd, args, 0);
			}
		}
	}
	if (test_emulator()) {
		print_message("skinplay -q: no GPU under the emulator: skipped\n");
		return;
	}
	char args[512];
	snprintf(args, sizeof args, "--image %s/t.skn --platform surfaceless --size 64x64 --frames 2 -o %s/frames", dir, dir);
	run_quiet("skinplay", "", "", args, 1);
	run_quiet("skinplay", "-q", "", args, 0);
	snprintf(args, sizeof args, "--asf tests/data/tiny.asf --amc tests/data/tiny.amc --platform surfaceless --size 64x64 "
		 "--frames 2 --input script:/dev/null --quiet");
	run_quiet("skinplay", "", "", args, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_command_has_help),
		cmocka_unit_test(test_option_forms),
		cmocka_unit_test(test_quiet_everywhere),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
