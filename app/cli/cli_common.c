#include "cli_common.h"

#include <stdio.h>
#include <string.h>

#include "cli_program.h"
#include "skp_format.h"
#include "text_tokens.h"

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

int cli_take_positional(const char *cmd, const char **const *slots, int n, const char *arg)
{
	for (int k = 0; k < n; k++)
		if (!*slots[k]) {
			*slots[k] = arg;
			return 0;
		}
	fprintf(stderr, "%s: unexpected argument '%s'\n", cmd, cli_shown(arg));
	return -1;
}

const char *cli_basename(const char *path)
{
	const char *s = strrchr(path, '/');
	return s ? s + 1 : path;
}

int cli_parse_long(const char *opt, const char *text, long *out)
{
	if (!text || tok_parse_long(text, out) != 0) {
		fprintf(stderr, "%s: %s expects an integer, got '%s'\n", cli_program(), opt, text ? text : "");
		return -1;
	}
	return 0;
}
