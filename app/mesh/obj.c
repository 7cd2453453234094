#include "obj.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "mesh_normals.h"
#include "skp_format.h"
#include "text_tokens.h"

typedef struct obj_state {
	mesh *m;
	obj_work *w;
	skp_error *err;
	long line;
	const char *group;
	int max_verts, max_tris;
	int in_object, in_group;  /* the current o / g names match the filter */
	long kept_verts;          /* vertices used by kept faces so far */
} obj_state;

/* White space only: commas and parentheses are legal in OBJ names. */
static int obj_split(char *p, char **toks, int max)
{
	int n = 0;
	for (;;) {
		while (*p == ' ' || *p == '\t' || *p == '\v' || *p == '\f')
			p++;
		if (*p == '\0' || *p == '#')
			return n;
		if (n == max)
			return -1;
		toks[n++] = p;
		while (*p && *p != ' ' && *p != '\t' && *p != '\v' && *p != '\f')
			p++;
		if (*p == '\0')
			return n;
		*p++ = '\0';
	}
}

static skp_status parse_coords(obj_state *st, char **t, int n, int min, int max, vec3 *out)
{
	if (n - 1 < min || n - 1 > max)
		return skp_syntax(st->err, st->line, "'%s' expects %d to %d numbers, found %d", t[0], min, max, n - 1);
	float c[3] = { 0.0f, 0.0f, 0.0f };
	for (int i = 1; i < n; i++) {
		double v;
		if (tok_parse_double(t[i], &v) != 0 || !isfinite(v))
			return skp_syntax(st->err, st->line, "'%s': expected a finite number, found '%s'", t[0], t[i]);
		if (fabs(v) > FLT_MAX)
			return skp_fail(st->err, SKP_ERR_RANGE, st->line, "'%s': value '%s' is beyond a float's range", t[0], t[i]);
		if (i <= 3)
			c[i - 1] = (float)v;
	}
	if (out)
		*out = vec3_make(c[0], c[1], c[2]);
	return SKP_OK;
}

static skp_status vertex_line(obj_state *st, char **t, int n)
{
	obj_work *w = st->w;
	if (w->file_verts >= OBJ_MAX_FILE_VERTS)
		return skp_fail(st->err, SKP_ERR_LIMIT, st->line,
				"more than %d vertices in the file (OBJ_MAX_FILE_VERTS = 2 * SKP_MAX_VERTS)",
				OBJ_MAX_FILE_VERTS);
	if (!st->group && w->file_verts >= st->max_verts)
		return skp_fail(st->err, SKP_ERR_LIMIT, st->line,
				"more than %d vertices (board limit SKP_MAX_VERTS)", st->max_verts);
	/* x y z, an optional w, or x y z r g b (vertex colours) */
	skp_status rc = parse_coords(st, t, n, 3, 7, &w->pos[w->file_verts]);
	if (rc)
		return rc;
	w->nsum[w->file_verts] = vec3_make(0.0f, 0.0f, 0.0f);
	w->kept[w->file_verts] = st->group ? -1 : 0;
	w->file_verts++;
	return SKP_OK;
}

static skp_status normal_line(obj_state *st, char **t, int n)
{
	obj_work *w = st->w;
	if (w->file_normals >= OBJ_MAX_FILE_NORMALS)
		return skp_fail(st->err, SKP_ERR_LIMIT, st->line,
				"more than %d normals in the file (OBJ_MAX_FILE_NORMALS = 2 * SKP_MAX_VERTS)",
				OBJ_MAX_FILE_NORMALS);
	/* unit on the way in: the sums over a vertex's corners cannot overflow */
	vec3 vn;
	skp_status rc = parse_coords(st, t, n, 3, 3, &vn);
	if (!rc)
		w->vn[w->file_normals++] = mesh_unit(vn);
	return rc;
}

static skp_status texcoord_line(obj_state *st, char **t, int n)
{
	obj_work *w = st->w;
	vec3 c = vec3_make(0.0f, 0.0f, 0.0f);
	skp_status rc = parse_coords(st, t, n, 1, 3, &c);
	if (rc)
		return rc;
	if (w->file_texcoords < OBJ_MAX_FILE_TEXCOORDS) {
		w->vt[w->file_texcoords][0] = c.x;
		w->vt[w->file_texcoords][1] = c.y;
	}
	w->file_texcoords++;
	return SKP_OK;
}

/* 1-based, or negative counting back from the last one defined so far */
static skp_status resolve(obj_state *st, const char *tok, const char *what, long count, long *out)
{
	long i;
	if (tok_parse_long(tok, &i) != 0)
		return skp_syntax(st->err, st->line, "'f': expected a %s index, found '%s'", what, tok);
	if (i == 0)
		return skp_syntax(st->err, st->line, "'f': %s index 0 (OBJ indices start at 1)", what);
	long r = i > 0 ? i - 1 : count + i;
	if (r < 0 || r >= count)
		return skp_syntax(st->err, st->line, "'f': %s index %ld out of range (%ld defined so far)", what, i, count);
	*out = r;
	return SKP_OK;
}

/* v, v/vt, v/vt/vn or v//vn, split in place at the slashes */
static skp_status parse_corner(obj_state *st, char *tok, obj_corner *c)
{
	char *part[3] = { tok, NULL, NULL };
	int parts = 1;
	for (const char *p = tok, *slash = NULL; (slash = strchr(p, '/')) != NULL; p = slash + 1)
		if (++parts > 3)
			return skp_syntax(st->err, st->line, "'f': corner '%s' has more than two '/'", tok);
	for (int i = 1; i < parts; i++) {
		char *slash = strchr(part[i - 1], '/');
		*slash = '\0';
		part[i] = slash + 1;
	}
	long v = 0, vt = -1, vn = -1; /* set on every path: c is filled even on error */
	skp_status rc = resolve(st, part[0], "vertex", st->w->file_verts, &v);
	if (!rc && parts >= 2 && (parts == 2 || part[1][0] != '\0'))
		rc = resolve(st, part[1], "texture", st->w->file_texcoords, &vt);
	if (!rc && parts == 3)
		rc = resolve(st, part[2], "normal", st->w->file_normals, &vn);
	c->v = (uint32_t)v;
	c->vn = (int32_t)vn;
	c->vt = vt < OBJ_MAX_FILE_TEXCOORDS ? (int32_t)vt : -1;
	return rc;
}

static int face_kept(const obj_state *st)
{
	return !st->group || st->in_object || st->in_group;
}

static skp_status use_corner(obj_state *st, const obj_corner *c)
{
	obj_work *w = st->w;
	if (w->kept[c->v] < 0) {
		if (st->kept_verts >= st->max_verts)
			return skp_fail(st->err, SKP_ERR_LIMIT, st->line,
					"group '%s' uses more than %d vertices (board limit SKP_MAX_VERTS)",
					st->group, st->max_verts);
		w->kept[c->v] = 0;
		st->kept_verts++;
	}
	if (c->vn < 0)
		w->normals_from_file = 0;
	else
		w->nsum[c->v] = vec3_add(w->nsum[c->v], w->vn[c->vn]);
	return SKP_OK;
}

static skp_status add_tri(obj_state *st, const obj_corner *a, const obj_corner *b, const obj_corner *c)
{
	mesh *m = st->m;
	if (m->tri_count >= st->max_tris)
		return skp_fail(st->err, SKP_ERR_LIMIT, st->line,
				"more than %d triangles (board limit SKP_MAX_TRIS)", st->max_tris);
	obj_work *w = st->w;
	w->tri_vt[m->tri_count][0] = a->vt;
	w->tri_vt[m->tri_count][1] = b->vt;
	w->tri_vt[m->tri_count][2] = c->vt;
	w->tri_mtl[m->tri_count] = (int16_t)w->current_mtl;
	uint32_t *t = m->tri[m->tri_count++];
	t[0] = a->v;
	t[1] = b->v;
	t[2] = c->v;
	return SKP_OK;
}

static float dist2(const obj_work *w, const obj_corner *a, const obj_corner *b)
{
	vec3 d = vec3_sub(w->pos[a->v], w->pos[b->v]);
	return vec3_dot(d, d);
}

/* Quads along the shorter diagonal (better shaped triangles); the rest
 * as a fan from the first corner. */
static skp_status triangulate(obj_state *st, const obj_corner *c, int n)
{
	skp_status rc = SKP_OK;
	if (n == 4 && dist2(st->w, &c[1], &c[3]) < dist2(st->w, &c[0], &c[2])) {
		rc = add_tri(st, &c[0], &c[1], &c[3]);
		return rc ? rc : add_tri(st, &c[1], &c[2], &c[3]);
	}
	for (int i = 1; !rc && i + 1 < n; i++)
		rc = add_tri(st, &c[0], &c[i], &c[i + 1]);
	return rc;
}

static skp_status face_line(obj_state *st, char **t, int n)
{
	obj_work *w = st->w;
	if (n - 1 < 3)
		return skp_syntax(st->err, st->line, "'f' needs at least 3 corners, found %d", n - 1);
	for (int i = 1; i < n; i++) {
		skp_status rc = parse_corner(st, t[i], &w->corner[i - 1]);
		if (rc)
			return rc;
	}
	w->file_faces++;
	if (w->current_group >= 0)
		w->group[w->current_group].faces++;
	if (!face_kept(st))
		return SKP_OK;
	w->kept_faces++;
	for (int i = 0; i < n - 1; i++) {
		skp_status rc = use_corner(st, &w->corner[i]);
		if (rc)
			return rc;
	}
	return triangulate(st, w->corner, n - 1);
}

static int names_match(const obj_state *st, char **t, int n)
{
	for (int i = 1; i < n; i++)
		if (strcmp(t[i], st->group) == 0)
			return 1;
	return 0;
}

/* The table of names for listing: the first name of a `g` or `o` line
 * (names too long for the table are cut). */
static void note_group(obj_work *w, const char *raw)
{
	char name[SKP_MAX_NAME];
	skp_escape_name(name, sizeof name, raw);   /* listed on terminals */
	for (int i = 0; i < w->group_count; i++)
		if (strcmp(w->group[i].name, name) == 0) {
			w->current_group = i;
			return;
		}
	if (w->group_count == OBJ_MAX_GROUPS) {
		w->group_overflow = 1;
		w->current_group = -1;
		return;
	}
	obj_group *g = &w->group[w->group_count];
	memcpy(g->name, name, sizeof name);
	g->faces = 0;
	w->current_group = w->group_count++;
}

/* `g a b`: the next faces belong to every group listed; a bare `g` is the
 * default group. `o` starts an object, whose faces are in its name. */
static skp_status group_line(obj_state *st, char **t, int n)
{
	note_group(st->w, n > 1 ? t[1] : "default");
	if (!st->group)
		return SKP_OK;
	if (t[0][0] == 'o') {
		st->in_object = names_match(st, t, n);
		st->in_group = 0;
	} else {
		st->in_group = n > 1 ? names_match(st, t, n) : strcmp(st->group, "default") == 0;
	}
	return SKP_OK;
}

/* A material's name: the words after the keyword, one space between
 * (names with spaces are written so); 0 when there are none or too many. */
static int material_name(char **t, int n, char *out)
{
	size_t len = 0;
	for (int i = 1; i < n; i++) {
		size_t k = strlen(t[i]);
		if (len + k + 2 > SKP_MAX_NAME)
			return 0;
		if (i > 1)
			out[len++] = ' ';
		memcpy(out + len, t[i], k);
		len += k;
	}
	out[len] = '\0';
	return len > 0;
}

/* `usemtl NAME`: the next faces' material; `mtllib FILE`: the first
 * library named is kept (a bare one, or a name too long, says nothing). */
static void material_line(obj_state *st, char **t, int n)
{
	obj_work *w = st->w;
	char name[SKP_MAX_NAME];
	int named = material_name(t, n, name);
	if (t[0][0] == 'm') {
		if (named && !w->mtllib[0])
			memcpy(w->mtllib, name, sizeof name);
		return;
	}
	w->current_mtl = -1;
	for (int i = 0; named && i < w->mtl_count; i++)
		if (strcmp(w->mtl_name[i], name) == 0) {
			w->current_mtl = i;
			return;
		}
	if (named && w->mtl_count < OBJ_MAX_MATERIALS) {
		memcpy(w->mtl_name[w->mtl_count], name, sizeof name);
		w->current_mtl = w->mtl_count++;
	}
}

static int ignored(const char *k)
{
	static const char *const names[] = {
		"s", "l", "p", "vp", "cstype", "deg", "bmat",
		"step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv",
		"sp", "end", "con", "mg", "bevel", "c_interp", "d_interp", "lod",
		"shadow_obj", "trace_obj", "ctech", "stech", "maplib", "usemap",
	};
	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
		if (strcmp(k, names[i]) == 0)
			return 1;
	return 0;
}

static skp_status dispatch(obj_state *st, char **t, int n)
{
	const char *k = t[0];
	if (strcmp(k, "v") == 0)
		return vertex_line(st, t, n);
	if (strcmp(k, "vn") == 0)
		return normal_line(st, t, n);
	if (strcmp(k, "vt") == 0)
		return texcoord_line(st, t, n);
	if (strcmp(k, "f") == 0)
		return face_line(st, t, n);
	if (strcmp(k, "g") == 0 || strcmp(k, "o") == 0)
		return group_line(st, t, n);
	if (strcmp(k, "usemtl") == 0 || strcmp(k, "mtllib") == 0) {
		material_line(st, t, n);
		return SKP_OK;
	}
	if (ignored(k))
		return SKP_OK;
	return skp_syntax(st->err, st->line, "unknown statement '%s' (expected v, vt, vn, f, g, o, s, usemtl, ...)", k);
}

/* Mesh vertices in ascending file order; triangles still hold file indices. */
static void renumber(obj_state *st)
{
	obj_work *w = st->w;
	mesh *m = st->m;
	int k = 0;
	for (long i = 0; i < w->file_verts; i++) {
		if (w->kept[i] < 0)
			continue;
		w->kept[i] = k;
		w->source[k] = (uint32_t)i;
		m->pos[k++] = w->pos[i];
	}
	m->vert_count = k;
	for (int t = 0; t < m->tri_count; t++)
		for (int j = 0; j < 3; j++)
			m->tri[t][j] = (uint32_t)w->kept[m->tri[t][j]];
}

static int unit(vec3 n)
{
	return vec3_dot(n, n) > 0.5f;
}

/* The file's normals where every kept corner had one; a vertex whose
 * normals cancel out (or that no face uses) takes the computed one. */
static void set_normals(obj_state *st)
{
	obj_work *w = st->w;
	mesh *m = st->m;
	int from_file = w->normals_from_file, gap = !from_file;
	for (int k = 0; from_file && k < m->vert_count; k++) {
		m->normal[k] = mesh_unit(w->nsum[w->source[k]]);
		if (!unit(m->normal[k]))
			gap = 1;
	}
	if (!gap)
		return;
	mesh_compute_normals(m);
	for (int k = 0; from_file && k < m->vert_count; k++) {
		vec3 n = mesh_unit(w->nsum[w->source[k]]);
		if (unit(n))
			m->normal[k] = n;
	}
}

static skp_status finish(obj_state *st)
{
	if (st->w->kept_faces == 0) {
		if (st->group)
			return skp_fail(st->err, SKP_ERR_RANGE, 0, "no faces in group '%s'", st->group);
		return skp_fail(st->err, SKP_ERR_RANGE, 0, "no faces");
	}
	renumber(st);
	set_normals(st);
	return SKP_OK;
}

static int limit_or(int want, int board)
{
	return want > 0 && want < board ? want : board;
}

static void init_state(obj_state *st, mesh *out, obj_work *w, const obj_options *opt, skp_error *err)
{
	memset(st, 0, sizeof *st);
	st->m = out;
	st->w = w;
	st->err = err;
	st->group = opt && opt->group ? opt->group : NULL;
	st->max_verts = limit_or(opt ? opt->max_verts : 0, SKP_MAX_VERTS);
	st->max_tris = limit_or(opt ? opt->max_tris : 0, SKP_MAX_TRIS);
	st->in_group = st->group && strcmp(st->group, "default") == 0;
	w->file_verts = w->file_normals = w->file_texcoords = 0;
	w->file_faces = w->kept_faces = 0;
	w->normals_from_file = 1;
	w->group_count = 0;
	w->group_overflow = 0;
	w->current_group = -1;
	w->mtl_count = 0;
	w->current_mtl = -1;
	w->mtllib[0] = '\0';
	out->vert_count = out->tri_count = out->coloured = out->textured = 0;
}

skp_status obj_parse(mesh *out, obj_work *w, text_lines *tl, const obj_options *opt, skp_error *err)
{
	obj_state st;
	init_state(&st, out, w, opt, err);
	skp_error_clear(err);

	char *line;
	int r;
	while ((r = text_lines_next(tl, &line, NULL, err)) > 0) {
		st.line = tl->line_no;
		int n = obj_split(line, w->tok, OBJ_MAX_CORNERS + 1);
		if (n < 0)
			return skp_syntax(st.err, st.line, "more than %d corners on a line", OBJ_MAX_CORNERS);
		if (n == 0)
			continue;
		skp_status rc = dispatch(&st, w->tok, n);
		if (rc)
			return rc;
	}
	if (r < 0)
		return (skp_status)-r;
	return finish(&st);
}
