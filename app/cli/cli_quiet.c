#define _GNU_SOURCE /* fopencookie */
#include "cli_quiet.h"

static int quiet;

void cli_set_quiet(int q)
{
	quiet = q;
}

int cli_quiet(void)
{
	return quiet;
}

static ssize_t discard(void *cookie, const char *buf, size_t size)
{
	(void)cookie;
	(void)buf;
	return (ssize_t)size;
}

/* A stream with no file behind it: nothing to open that could be missing
 * (a chroot without /dev/null) and nothing to close. */
static FILE *null_stream(void)
{
	static FILE *null;
	if (!null) {
		cookie_io_functions_t io = { .write = discard };
		null = fopencookie(NULL, "w", io);
	}
	return null ? null : stderr;
}

FILE *cli_note(void)
{
	return quiet ? null_stream() : stderr;
}

FILE *cli_summary(void)
{
	return quiet ? null_stream() : stdout;
}
