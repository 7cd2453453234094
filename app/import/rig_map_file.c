#include "rig_map_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAP_FILE_MAX (1L << 20)

/* Trims [*s, *e) of blanks; returns its length. */
static size_t trim(const char **s, const char **e)
{
	while (*s < *e && (**s == ' ' || **s == '\t'))
		(*s)++;
	while (*e > *s && ((*e)[-1] == ' ' || (*e)[-1] == '\t' || (*e)[-1] == '\r'))
		(*e)--;
	return (size_t)(*e - *s);
}

static skp_status take_name(const char *s, const char *e, char *dst, size_t cap, long line,
			    const char *what, skp_error *err)
{
	size_t n = trim(&s, &e);
	if (n == 0)
		return skp_syntax(err, line, "expected JOINT = BONE, the %s name is empty", what);
	if (n >= cap)
		return skp_fail(err, SKP_ERR_LIMIT, line, "%s name longer than %d bytes", what, (int)cap - 1);
	for (size_t i = 0; i < n; i++)
		if ((unsigned char)s[i] < 0x20 || s[i] == 0x7f)
			return skp_syntax(err, line, "control byte \\x%c%c in the %s name", "0123456789abcdef"[(unsigned char)s[i] >> 4],
					  "0123456789abcdef"[s[i] & 15], what);
	memcpy(dst, s, n);
	dst[n] = '\0';
	return SKP_OK;
}

static skp_status parse_line(const char *s, const char *e, long line, rig_map_file *out, skp_error *err)
{
	const char *hash = memchr(s, '#', (size_t)(e - s));
	if (hash)
		e = hash;
	if (trim(&s, &e) == 0)
		return SKP_OK;
	const char *eq = memchr(s, '=', (size_t)(e - s));
	if (!eq)
		return skp_syntax(err, line, "expected JOINT = BONE, found no '='");
	if (out->count >= RIG_MAP_MAX_ENTRIES)
		return skp_fail(err, SKP_ERR_LIMIT, line, "more than %d pairs", RIG_MAP_MAX_ENTRIES);
	rig_map_entry *en = &out->entry[out->count];
	skp_status rc = take_name(s, eq, en->joint, sizeof en->joint, line, "joint", err);
	if (rc == SKP_OK)
		rc = take_name(eq + 1, e, en->bone, sizeof en->bone, line, "bone", err);
	if (rc != SKP_OK)
		return rc;
	en->line = line;
	out->count++;
	return SKP_OK;
}

skp_status rig_map_file_parse(const char *text, size_t len, rig_map_file *out, skp_error *err)
{
	out->count = 0;
	const char *s = text, *end = text + len;
	for (long line = 1; s < end; line++) {
		const char *nl = memchr(s, '\n', (size_t)(end - s));
		const char *e = nl ? nl : end;
		if (memchr(s, '\0', (size_t)(e - s)))
			return skp_syntax(err, line, "unexpected NUL byte: not a text file");
		skp_status rc = parse_line(s, e, line, out, err);
		if (rc != SKP_OK)
			return rc;
		s = nl ? nl + 1 : end;
	}
	return SKP_OK;
}

skp_status rig_map_file_read(const char *path, rig_map_file *out, skp_error *err)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return skp_fail(err, SKP_ERR_IO, 0, "%s", strerror(errno));
	char *buf = malloc(MAP_FILE_MAX + 1);
	size_t n = buf ? fread(buf, 1, MAP_FILE_MAX + 1, f) : 0;
	int failed = !buf || ferror(f);
	fclose(f);
	skp_status rc = failed ? skp_fail(err, SKP_ERR_IO, 0, "cannot read it")
		: n > MAP_FILE_MAX ? skp_fail(err, SKP_ERR_LIMIT, 0, "larger than %ld bytes", MAP_FILE_MAX)
		: rig_map_file_parse(buf, n, out, err);
	free(buf);
	return rc;
}
