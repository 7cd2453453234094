#include "cli_error.h"

#include <stdio.h>
#include <string.h>

#include "skp_format.h"

const char *cli_shown(const char *text)
{
	static char buf[4][1024];
	static int next;
	char *out = buf[next++ % 4];
	skp_escape_name(out, sizeof buf[0], text ? text : "");
	return out;
}

void cli_error(const char *path, const skp_error *err)
{
	path = cli_shown(path);
	if (err->line > 0)
		fprintf(stderr, "%s:%ld: %s\n", path, err->line, err->msg);
	else if (err->block >= 0)
		fprintf(stderr, "%s: block %ld: %s\n", path, err->block, err->msg);
	else
		fprintf(stderr, "%s: %s\n", path, err->msg);
}

void cli_error_errno(const char *path, const char *doing, int rc)
{
	fprintf(stderr, "%s: cannot %s: %s\n", cli_shown(path), doing, strerror(-rc));
}

const char *cli_basename(const char *path)
{
	const char *s = strrchr(path, '/');
	return s ? s + 1 : path;
}
