#include "rig_json.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static long line_at(const char *text, size_t offset)
{
	long line = 1;
	for (size_t i = 0; i < offset; i++)
		line += text[i] == '\n';
	return line;
}

static int only_space(const char *s, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (!strchr(" \t\r\n", s[i]))
			return 0;
	return 1;
}

_Static_assert(RIG_JSON_MAX_BYTES <= INT32_MAX, "json-c takes the length as an int");

json_object *rig_json_parse(const char *text, size_t len, skp_error *err)
{
	if (len > (size_t)RIG_JSON_MAX_BYTES) {
		skp_fail(err, SKP_ERR_LIMIT, 0, "larger than %ld bytes", RIG_JSON_MAX_BYTES);
		return NULL;
	}
	json_tokener *tok = json_tokener_new();
	if (!tok) {
		skp_fail(err, SKP_ERR_IO, 0, "out of memory");
		return NULL;
	}
	json_object *v = json_tokener_parse_ex(tok, text, (int)len);
	enum json_tokener_error e = json_tokener_get_error(tok);
	size_t end = json_tokener_get_parse_end(tok);
	json_tokener_free(tok);
	if (v && e == json_tokener_success && only_space(text + end, len - end))
		return v;
	json_object_put(v);
	if (e == json_tokener_continue || (!v && e == json_tokener_success))
		skp_syntax(err, line_at(text, len), "JSON: the file ends inside a value (or holds none)");
	else if (e == json_tokener_success)
		skp_syntax(err, line_at(text, end), "JSON: text after the value, expected the end of the file");
	else
		skp_syntax(err, line_at(text, end), "JSON: %s", json_tokener_error_desc(e));
	return NULL;
}

static char *read_all(const char *path, size_t *len, skp_error *err)
{
	FILE *f = fopen(path, "rb");
	if (!f) {
		skp_fail(err, SKP_ERR_IO, 0, "cannot open: %s", strerror(errno));
		return NULL;
	}
	size_t cap = 1 << 16, n = 0;
	char *buf = malloc(cap);
	while (buf) {
		n += fread(buf + n, 1, cap - n, f);
		if (n < cap || cap > (size_t)RIG_JSON_MAX_BYTES)
			break;
		char *more = realloc(buf, cap * 2);
		if (!more) {
			free(buf);
			buf = NULL;
			break;
		}
		buf = more;
		cap *= 2;
	}
	int bad = ferror(f);
	fclose(f);
	if (!buf || bad) {
		skp_fail(err, SKP_ERR_IO, 0, bad ? "cannot read" : "out of memory");
		free(buf);
		return NULL;
	}
	*len = n;
	return buf;
}

json_object *rig_json_load(const char *path, skp_error *err)
{
	size_t len = 0;
	char *text = read_all(path, &len, err);
	if (!text)
		return NULL;
	json_object *v = rig_json_parse(text, len, err);
	free(text);
	return v;
}

json_object *rig_json_get(json_object *o, const char *key, json_type type)
{
	json_object *m = NULL;
	if (!json_object_object_get_ex(o, key, &m))
		return NULL;
	if (json_object_is_type(m, type) || (type == json_type_double && json_object_is_type(m, json_type_int)))
		return m;
	return NULL;
}
