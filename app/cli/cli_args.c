#include "cli_args.h"

#include <stdio.h>

#include "cli_error.h"
#include "cli_program.h"
#include "text_tokens.h"

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

int cli_parse_long(const char *opt, const char *text, long *out)
{
	if (!text || tok_parse_long(text, out) != 0) {
		fprintf(stderr, "%s: %s expects an integer, got '%s'\n", cli_program(), opt, text ? text : "");
		return -1;
	}
	return 0;
}
