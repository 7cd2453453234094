/* What the board config's key parsers share (board_config.c,
 * board_install.c): the message for a bad value, a word among names, a
 * yaw. */
#include "board_keys.h"

#include "text_tokens.h"

skp_status board_bad(skp_error *err, const ini_entry *e, const char *expected)
{
	return skp_fail(err, SKP_ERR_SYNTAX, e->line, "key '%s' in [%s]: expected %s, found '%s'", e->key,
			e->section, expected, e->value);
}

int board_pick(const char *v, const char *const *names, int n)
{
	for (int i = 0; i < n; i++)
		if (tok_ieq(v, names[i]))
			return i;
	return -1;
}

int board_yaw_parse(const char *word, float *deg)
{
	double v;
	if (word && tok_ieq(word, "auto"))
		return 0;
	if (!word || tok_parse_double(word, &v) != 0 || !(v >= -360.0 && v <= 360.0))
		return -1;
	*deg = (float)v;
	return 1;
}
