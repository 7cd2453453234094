/* No input lost: every command that writes refuses an output that is one
 * of its inputs - by the same name, another spelling (./x), a hard link or
 * a symbolic link, and the names a command makes itself (convert's .amc
 * beside its .asf, skinplay's contact sheet) - with exit 1, a message
 * naming the input, and the input byte for byte as it was. repair, which
 * replaces its input by design, still does. */
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

/* The tool's absolute path: the commands run in the scratch directory. */
static const char *tool(const char *prog)
{
	static char path[2][4096];
	char *p = path[prog[4] == 'p'];   /* skinplay, skintool */
	if (!realpath(test_tool_path(prog), p))
		fail_msg("%s: not built", test_tool_path(prog));
	return p;
}

static uint64_t hash_file(const char *path)
{
	size_t n;
	char *d = test_read_file(path, &n);
	assert_non_null(d);
	uint64_t h = 1469598103934665603ull;
	for (size_t i = 0; i < n; i++)
		h = (h ^ (uint8_t)d[i]) * 1099511628211ull;
	free(d);
	return h;
}

static int setup(void **state)
{
	if (test_scratch_setup(state))
		return -1;
	const char *d = test_scratch_dir(), *t = tool("skintool");
	return test_run("cp tests/data/tiny.asf tests/data/tiny.amc '%s'/ && cd '%s' && ln tiny.amc hard.amc && "
			"ln -s tiny.amc soft.amc && ln -s tiny.asf soft.asf && %s convert tiny.asf tiny.amc -o tiny.bvh >/dev/null && "
			"%s mannequin tiny.asf -o body.obj >/dev/null && %s bind tiny.asf body.obj -o w.csv >/dev/null",
			d, d, t, t, t);
}

/* Runs "cd scratch && PROG ARGS"; it must exit 1 saying that `input` is
 * also an input, and leave `input` as it was. */
static void refused(const char *prog, const char *args, const char *input)
{
	const char *log = test_scratch("log.txt");
	char path[512];
	snprintf(path, sizeof path, "%s/%s", test_scratch_dir(), input);
	uint64_t before = hash_file(path);
	int st = test_run("cd '%s' && %s %s >'%s' 2>&1", test_scratch_dir(), tool(prog), args, log);
	if (st != 1 || !test_file_contains(log, "is also an input") || !test_file_contains(log, "not written"))
		fail_msg("%s %s: exit %d, no refusal", prog, args, st);
	if (hash_file(path) != before)
		fail_msg("%s %s: %s changed", prog, args, input);
}

typedef struct attempt {
	const char *prog, *args, *input;
} attempt;

static const attempt attempts[] = {
	{ "skintool", "pack tiny.asf tiny.amc -o tiny.amc", "tiny.amc" },
	{ "skintool", "pack tiny.asf tiny.amc -o tiny.asf", "tiny.asf" },
	{ "skintool", "pack tiny.asf tiny.amc -o ./tiny.amc", "tiny.amc" },
	{ "skintool", "pack tiny.asf tiny.amc -o hard.amc", "tiny.amc" },
	{ "skintool", "pack tiny.asf tiny.amc -o soft.amc", "tiny.amc" },
	{ "skintool", "pack tiny.asf tiny.amc --mesh body.obj -o body.obj", "body.obj" },
	{ "skintool", "pack tiny.asf tiny.amc --mesh body.obj --weights w.csv --output=w.csv", "w.csv" },
	{ "skintool", "pack tiny.bvh -o tiny.bvh", "tiny.bvh" },
	{ "skintool", "convert tiny.bvh -o tiny.bvh", "tiny.bvh" },
	{ "skintool", "convert tiny.asf tiny.amc -o tiny.asf", "tiny.asf" },
	{ "skintool", "convert tiny.asf hard.amc -o ./tiny.asf", "tiny.asf" },
	/* the .amc convert makes beside OUT.asf */
	{ "skintool", "convert other.asf tiny.amc -o tiny.asf", "tiny.amc" },
	{ "skintool", "mannequin tiny.asf -o tiny.asf", "tiny.asf" },
	{ "skintool", "mannequin soft.asf -o tiny.asf", "tiny.asf" },
	{ "skintool", "bind tiny.asf body.obj -o body.obj", "body.obj" },
	{ "skintool", "bind tiny.asf body.obj --weights w.csv -o w.csv", "w.csv" },
	{ "skintool", "bind tiny.asf body.obj --bind-pose tiny.amc:1 -o tiny.amc", "tiny.amc" },
	{ "skintool", "skin tiny.asf tiny.amc -o tiny.amc", "tiny.amc" },
	{ "skintool", "compare tiny.asf tiny.amc -o tiny.amc", "tiny.amc" },
	{ "skinplay", "--asf tiny.asf --amc tiny.amc --platform surfaceless --size 64x36 --frames 2 --out . --sheet tiny.amc",
	  "tiny.amc" },
	{ "skinplay", "--asf tiny.asf --amc tiny.amc --platform surfaceless --size 64x36 --frames 2 --out hard.amc",
	  "tiny.amc" },
};

static void test_every_command_refuses(void **state)
{
	(void)state;
	assert_int_equal(test_run("cd '%s' && cp tiny.asf other.asf", test_scratch_dir()), 0);
	for (size_t i = 0; i < sizeof attempts / sizeof attempts[0]; i++)
		refused(attempts[i].prog, attempts[i].args, attempts[i].input);
}

/* repair writes over its input on purpose (atomically): not refused. */
static void test_repair_still_replaces(void **state)
{
	(void)state;
	const char *d = test_scratch_dir();
	assert_int_equal(test_run("cd '%s' && %s pack tiny.asf tiny.amc -o show.skn >/dev/null", d, tool("skintool")), 0);
	assert_int_equal(test_run("cd '%s' && %s repair show.skn >/dev/null", d, tool("skintool")), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_command_refuses),
		cmocka_unit_test(test_repair_still_replaces),
	};
	return cmocka_run_group_tests(tests, setup, test_scratch_teardown);
}
