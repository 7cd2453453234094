/* No input lost: every command that writes refuses an output that is one
 * of its inputs - by the same name, another spelling (./x), a hard link or
 * a symbolic link, and the names a command makes itself (convert's .amc
 * beside its .asf, skinplay's contact sheet) - with exit 1, a message
 * naming the input, and the input byte for byte as it was. repair, which
 * replaces its input by design, still does. An output that is a symbolic
 * link is written through (the link stays, the target keeps its mode); a
 * FIFO, a directory or a character device is refused and left as it was;
 * an image goes onto a block device in place (as root, on a loop device). */
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

/* cd scratch && the command: its exit status */
static int in_scratch(const char *fmt, const char *arg)
{
	char cmd[2048];
	snprintf(cmd, sizeof cmd, fmt, arg);
	return test_run("cd '%s' && %s", test_scratch_dir(), cmd);
}

static void test_links_devices_and_fifos(void **state)
{
	(void)state;
	const char *t = tool("skintool");
	char cmd[1400];
	/* through a link: the target replaced, its mode kept, the link a link */
	snprintf(cmd, sizeof cmd, "%s pack tiny.asf tiny.amc -q -o real.skn && chmod 640 real.skn && "
		 "ln -s real.skn link.skn && %s pack tiny.asf tiny.amc -q --sequence 9 -o link.skn && test -L link.skn && "
		 "test \"$(stat -c %%a real.skn)\" = 640 && %s info link.skn | grep -q 'sequence    9' && "
		 "%s repair link.skn >/dev/null && test -L link.skn && test \"$(stat -c %%a real.skn)\" = 640", t, t, t, t);
	assert_int_equal(in_scratch("%s", cmd), 0);
	/* what is not a file: refused, left as it was */
	const char *log = test_scratch("kinds.txt");
	snprintf(cmd, sizeof cmd, "mkfifo fifo.skn && mkdir dir.csv && { %s pack tiny.asf tiny.amc -o fifo.skn; "
		 "echo $? > rc1; %s bind tiny.asf body.obj -o dir.csv; echo $? > rc2; } >'%s' 2>&1; "
		 "test -p fifo.skn && test -d dir.csv && test \"$(cat rc1 rc2)\" = \"$(printf '1\\n1')\"", t, t, log);
	assert_int_equal(in_scratch("%s", cmd), 0);
	static const char *const said[] = { "fifo.skn is a FIFO", "dir.csv is a directory", NULL };
	test_assert_contains_all(log, said);
	if (geteuid() != 0) {
		print_message("not root: character and block devices not tried\n");
		return;
	}
	snprintf(cmd, sizeof cmd, "mknod null.skn c 1 3 && %s pack tiny.asf tiny.amc -o null.skn 2>'%s'; test $? = 1 && "
		 "test -c null.skn", t, log);
	assert_int_equal(in_scratch("%s", cmd), 0);
	static const char *const chr[] = { "null.skn is a character device", NULL };
	test_assert_contains_all(log, chr);
	/* a raw slot: a loop device over a file */
	snprintf(cmd, sizeof cmd, "truncate -s 4M slot.img && dev=$(losetup -f --show slot.img 2>/dev/null) || exit 77; "
		 "%s pack tiny.asf tiny.amc -q --sequence 11 -o \"$dev\" && %s info \"$dev\" > info.txt; rc=$?; "
		 "%s bind tiny.asf body.obj -o \"$dev\" 2>>info.txt; rc2=$?; losetup -d \"$dev\"; "
		 "test $rc = 0 && test $rc2 = 1 && grep -q 'sequence    11' info.txt && grep -q 'is a block device' info.txt",
		 t, t, t);
	int rc = in_scratch("%s", cmd);
	if (rc == 77) {
		print_message("no loop device here: the block device not tried\n");
		return;
	}
	assert_int_equal(rc, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_command_refuses),
		cmocka_unit_test(test_repair_still_replaces),
		cmocka_unit_test(test_links_devices_and_fifos),
	};
	return cmocka_run_group_tests(tests, setup, test_scratch_teardown);
}
