#include "test_run.h"

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

static char dir[64];

int test_scratch_setup(void **state)
{
	(void)state;
	strcpy(dir, "/tmp/skp_test_XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

int test_scratch_teardown(void **state)
{
	(void)state;
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : -1;
}

const char *test_scratch_dir(void)
{
	return dir;
}

const char *test_scratch(const char *name)
{
	static char buf[64][512];
	static int next;
	char *out = buf[next++ % 64];
	snprintf(out, sizeof buf[0], "%s/%s", dir, name);
	return out;
}

int test_run(const char *fmt, ...)
{
	char cmd[4096];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(cmd, sizeof cmd, fmt, ap);
	va_end(ap);
	int st = system(cmd);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

void test_skip_threads_if_emulated(void)
{
	const char *emulator = getenv("SKP_TEST_EMULATED");
	if (emulator && *emulator) {
		print_message("skipped: threads under %s\n", emulator);
		skip();
	}
}
