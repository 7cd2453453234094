#include "rig_mtl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "skp_format.h"

static void warn(rig_mtl *m, long line, const char *fmt, ...)
{
	if (m->warnings < RIG_MTL_WARNINGS) {
		char *out = m->warning[m->warnings];
		int k = snprintf(out, sizeof m->warning[0], "%ld: ", line);
		va_list ap;
		va_start(ap, fmt);
		skp_vformat_escaped(out + k, sizeof m->warning[0] - (size_t)k, fmt, ap);
		va_end(ap);
	}
	m->warnings++;
}

static int is_space(char c)
{
	return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/* Splits at white space, in place; returns the number of words (at most max). */
static int split(char *p, char **tok, int max)
{
	int n = 0;
	for (;;) {
		while (is_space(*p))
			p++;
		if (!*p || *p == '#' || n == max)
			return n;
		tok[n++] = p;
		while (*p && !is_space(*p))
			p++;
		if (!*p)
			return n;
		*p++ = '\0';
	}
}

/* Words from the first on, one space apart, into out; 0 when none or too long. */
static int join(char **tok, int n, char *out, size_t cap)
{
	size_t len = 0;
	for (int i = 0; i < n; i++) {
		size_t k = strlen(tok[i]);
		if (len + k + 2 > cap)
			return 0;
		if (i)
			out[len++] = ' ';
		memcpy(out + len, tok[i], k);
		len += k;
	}
	out[len] = '\0';
	return len > 0;
}

static int number(const char *s, float *out)
{
	char *end;
	double v = strtod(s, &end);
	if (end == s || *end || !isfinite(v))
		return 0;
	*out = (float)(v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v);
	return 1;
}

static void kd_line(rig_mtl *m, rig_mtl_material *mat, long line, char **tok, int n)
{
	float c[3];
	if (n != 2 && n != 4) {
		warn(m, line, "material '%s': 'Kd' expects r g b (numbers from 0 to 1), found %d values", mat->name, n - 1);
		return;
	}
	for (int i = 1; i < n; i++)
		if (!number(tok[i], &c[i - 1])) {
			warn(m, line, "material '%s': 'Kd' expects r g b (numbers from 0 to 1), found '%s'", mat->name,
			     tok[i]);
			return;
		}
	if (n == 2)
		c[1] = c[2] = c[0];
	memcpy(mat->kd, c, sizeof c);
	mat->has_kd = 1;
}

/* map_Kd's options (-o 0 0 0, -clamp on, -imfchan r ...) before the file. */
static int skip_options(char **tok, int n)
{
	int i = 1;
	while (i < n - 1 && tok[i][0] == '-') {
		i++;
		float f;
		while (i < n - 1 && (number(tok[i], &f) || !strcmp(tok[i], "on") || !strcmp(tok[i], "off") ||
				     (strlen(tok[i]) == 1 && strchr("rgbmlz", tok[i][0]))))
			i++;
	}
	return i;
}

static void map_line(rig_mtl *m, rig_mtl_material *mat, long line, char **tok, int n)
{
	int first = skip_options(tok, n);
	if (first >= n || !join(tok + first, n - first, mat->map_kd, sizeof mat->map_kd)) {
		warn(m, line, "material '%s': 'map_Kd' expects a texture file", mat->name);
		mat->map_kd[0] = '\0';
		return;
	}
	for (char *p = mat->map_kd; *p; p++)
		if (*p == '\\')
			*p = '/';
}

static rig_mtl_material *new_material(rig_mtl *m, long line, char **tok, int n)
{
	char name[SKP_MAX_NAME];
	if (!join(tok + 1, n - 1, name, sizeof name)) {
		warn(m, line, "'newmtl' expects a material name (of fewer than %d bytes)", SKP_MAX_NAME);
		return NULL;
	}
	if (m->count == RIG_MTL_MAX) {
		warn(m, line, "material '%s': more than %d materials (the rest are left out)", name, RIG_MTL_MAX);
		return NULL;
	}
	rig_mtl_material *mat = &m->mat[m->count++];
	memset(mat, 0, sizeof *mat);
	memcpy(mat->name, name, sizeof name);
	return mat;
}

static void read_lines(FILE *f, rig_mtl *m)
{
	static char buf[4096];
	char *tok[64];
	rig_mtl_material *mat = NULL;
	int in_material = 0;
	for (long line = 1; fgets(buf, sizeof buf, f); line++) {
		size_t len = strlen(buf);
		if (len == sizeof buf - 1 && buf[len - 1] != '\n') {
			warn(m, line, "longer than %d bytes: left out", (int)sizeof buf - 2);
			int c;
			while ((c = fgetc(f)) != EOF && c != '\n')
				;
			continue;
		}
		int n = split(buf, tok, 64);
		if (!n)
			continue;
		if (!strcmp(tok[0], "newmtl")) {
			mat = new_material(m, line, tok, n);
			in_material = 1;
		} else if (!strcmp(tok[0], "Kd") || !strcmp(tok[0], "map_Kd")) {
			if (!in_material)
				warn(m, line, "'%s' before any 'newmtl': left out", tok[0]);
			else if (mat && tok[0][0] == 'K')
				kd_line(m, mat, line, tok, n);
			else if (mat)
				map_line(m, mat, line, tok, n);
		}
	}
}

int rig_mtl_read_stream(FILE *f, rig_mtl *out, const char **why)
{
	out->count = out->warnings = 0;
	/* a binary file (an image named .mtl) is no library: its NULs */
	char head[512];
	size_t got = fread(head, 1, sizeof head, f);
	if (memchr(head, '\0', got) || fseek(f, 0, SEEK_SET) != 0) {
		*why = "is not a text file";
		return 0;
	}
	read_lines(f, out);
	if (ferror(f)) {
		*why = "cannot be read";
		return 0;
	}
	return 1;
}

int rig_mtl_read(const char *path, rig_mtl *out, const char **why)
{
	out->count = out->warnings = 0;
	FILE *f = fopen(path, "rb");
	if (!f) {
		*why = access(path, F_OK) == 0 ? "cannot be read" : "is missing";
		return 0;
	}
	int ok = rig_mtl_read_stream(f, out, why);
	fclose(f);
	return ok;
}

const rig_mtl_material *rig_mtl_find(const rig_mtl *m, const char *name)
{
	for (int i = 0; i < m->count; i++)
		if (!strcmp(m->mat[i].name, name))
			return &m->mat[i];
	return NULL;
}
