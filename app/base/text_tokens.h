/* Tokenising and number parsing shared by the text formats (ASF, AMC, OBJ,
 * CSV, INI). Locale-independent and allocation-free: strtod is neither on
 * every libc (newlib's allocates). */
#ifndef TEXT_TOKENS_H
#define TEXT_TOKENS_H

#include <stddef.h>

/* Splits line in place at white space, commas and parentheses; a '#'
 * outside a token ends the line. Returns the token count, or -1 when the
 * line has more than max tokens. */
int tok_split(char *line, char **toks, int max);

/* Whole-token parses; return 0 on success, -1 when the token is not a
 * number. Doubles accept [+-]digits[.digits][e[+-]digits], "inf" and
 * "infinity" (any case); exponents may have any number of digits. */
int tok_parse_double(const char *s, double *out);
int tok_parse_long(const char *s, long *out);

/* ASCII case-insensitive equality (Acclaim keywords may be in any case). */
int tok_ieq(const char *a, const char *b);

#endif
