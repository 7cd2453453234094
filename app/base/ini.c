#include "ini.h"

#include <string.h>

static int is_space(char c)
{
	return c == ' ' || c == '\t';
}

static char *trim(char *s)
{
	while (is_space(*s))
		s++;
	size_t n = strlen(s);
	while (n && is_space(s[n - 1]))
		s[--n] = '\0';
	return s;
}

/* A comment starts a line or follows white space (paths may hold '#'
 * inside a word). */
static void cut_comment(char *s)
{
	for (char *p = s; *p; p++)
		if ((*p == '#' || *p == ';') && (p == s || is_space(p[-1]))) {
			*p = '\0';
			return;
		}
}

void ini_init(ini_reader *r, skp_reader rd)
{
	text_lines_init(&r->lines, rd);
	r->section[0] = '\0';
	r->stuck = 0;
}

int ini_can_go_on(const ini_reader *r)
{
	return !r->stuck;
}

static int header(ini_reader *r, char *s, skp_error *err)
{
	long ln = r->lines.line_no;
	size_t n = strlen(s);
	memcpy(r->section, "?", 2);   /* until this header is known good */
	if (s[n - 1] != ']')
		return -(int)skp_fail(err, SKP_ERR_SYNTAX, ln, "expected ']' to close the section header");
	s[n - 1] = '\0';
	s = trim(s + 1);
	if (!*s)
		return -(int)skp_fail(err, SKP_ERR_SYNTAX, ln, "empty section name");
	if (strlen(s) >= sizeof r->section)
		return -(int)skp_fail(err, SKP_ERR_LIMIT, ln, "section name longer than %d characters (SKP_MAX_NAME)",
				 (int)sizeof r->section - 1);
	memcpy(r->section, s, strlen(s) + 1);
	return 0;
}

int ini_next(ini_reader *r, ini_entry *e, skp_error *err)
{
	char *line;
	int rc;
	while ((rc = text_lines_next(&r->lines, &line, NULL, err)) > 0) {
		/* a byte order mark from a Windows editor */
		if (r->lines.line_no == 1 && !strncmp(line, "\xef\xbb\xbf", 3))
			line += 3;
		cut_comment(line);
		char *s = trim(line);
		if (!*s)
			continue;
		if (*s == '[') {
			if ((rc = header(r, s, err)) < 0)
				return rc;
			continue;
		}
		char *eq = strchr(s, '=');
		if (!eq)
			return -(int)skp_fail(err, SKP_ERR_SYNTAX, r->lines.line_no, "expected 'key = value', found '%s'", s);
		*eq = '\0';
		e->key = trim(s);
		e->value = trim(eq + 1);
		if (!*e->key)
			return -(int)skp_fail(err, SKP_ERR_SYNTAX, r->lines.line_no, "missing key before '='");
		e->section = r->section;
		e->line = r->lines.line_no;
		return 1;
	}
	r->stuck = rc < 0;   /* text_lines cannot go past a long line or a NUL */
	return rc;
}
