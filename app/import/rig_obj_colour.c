#include "rig_obj_colour.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "board_limits.h"
#include "rig_colour.h"
#include "rig_mtl.h"
#include "skp_format.h"

typedef struct obj_colour_work {
	const obj_work *w;
	rig_scene *r;
	rig_obj_colour_report *rep;
	rig_colour_work cw;
	const rig_mtl_material *mat[OBJ_MAX_MATERIALS]; /* per usemtl, NULL: not in the library */
	int gpu;                 /* the usemtl material whose texture the GPU draws, -1 none */
	int *twin;               /* per vertex: its next twin, -1 none */
	uint8_t *assigned;       /* per vertex: 1 once a corner set it */
	int owned;               /* vertices a material coloured */
} obj_colour_work;

static void warn(rig_obj_colour_report *rep, const char *fmt, ...)
{
	if (rep->warnings < RIG_OBJ_WARNINGS) {
		va_list ap;
		va_start(ap, fmt);
		skp_vformat_escaped(rep->warning[rep->warnings], sizeof rep->warning[0], fmt, ap);
		va_end(ap);
	}
	rep->warnings++;
}

/* name beside the file at, unless absolute; 0 when too long. */
static int beside(const char *at, const char *name, char *out, size_t cap)
{
	const char *slash = strrchr(at, '/');
	int dir = name[0] == '/' || !slash ? 0 : (int)(slash - at + 1);
	if ((size_t)snprintf(out, cap, "%.*s%s", dir, at, name) >= cap)
		return 0;
	for (char *p = out + dir; *p; p++)
		if (*p == '\\')
			*p = '/';   /* a Windows exporter's .\textures\skin.png */
	return 1;
}

/* The textured material on the most triangles, for the GPU. */
static int choose_gpu(const obj_colour_work *o)
{
	long tris[OBJ_MAX_MATERIALS] = { 0 }, most = 0;
	int best = -1;
	if (SKP_MAX_TEXTURE_SIDE <= 0)
		return -1; /* the board draws vertex colours alone: every texture baked */
	const mesh *m = o->r->mesh;
	for (int t = 0; t < m->tri_count; t++) {
		int i = o->w->tri_mtl[t];
		if (i >= 0 && o->mat[i] && o->mat[i]->map_kd[0] && o->w->tri_vt[t][0] >= 0)
			tris[i]++;
	}
	for (int i = 0; i < o->w->mtl_count; i++)
		if (tris[i] > most) {
			most = tris[i];
			best = i;
		}
	return best;
}

/* A corner's surface: colour, and the GPU's UV when it samples it. */
typedef struct corner_look {
	uint8_t colour[3];
	uint8_t sampled;
	float uv[2];
} corner_look;

/* The skin colour (MESH_SKIN_RGB, the renderer's), unsampled: the
 * vertices of a material that says nothing, beside ones that do. */
static corner_look skin_look(void)
{
	static const float skin[3] = MESH_SKIN_RGB;
	corner_look c = { { 0, 0, 0 }, 0, { 0.0f, 0.0f } };
	for (int ch = 0; ch < 3; ch++)
		c.colour[ch] = (uint8_t)(skin[ch] * 255.0f + 0.5f);
	return c;
}

static int same_surface(const mesh *m, int v, const corner_look *c)
{
	if (m->sampled[v] != c->sampled)
		return 0;
	return !c->sampled || (m->uv[v][0] == c->uv[0] && m->uv[v][1] == c->uv[1]);
}

static void set_vertex(mesh *m, int v, const corner_look *c)
{
	memcpy(m->colour[v], c->colour, 3);
	m->sampled[v] = c->sampled;
	m->uv[v][0] = c->uv[0];
	m->uv[v][1] = c->uv[1];
}

/* A twin of v with c's surface (the one it has, or a new one appended);
 * v itself when the board's vertices are all taken. */
static int twin_for(obj_colour_work *o, int v, const corner_look *c)
{
	rig_scene *r = o->r;
	mesh *m = r->mesh;
	int last = v;
	for (int u = o->twin[v]; u >= 0; u = o->twin[u]) {
		if (same_surface(m, u, c))
			return u;
		last = u;
	}
	if (m->vert_count >= SKP_MAX_VERTS)
		return v;
	int d = m->vert_count++;
	m->pos[d] = m->pos[v];
	m->normal[d] = m->normal[v];
	set_vertex(m, d, c);
	r->infl_count[d] = r->infl_count[v];
	r->held[d] = r->held[v];
	memcpy(r->infl_joint[d], r->infl_joint[v], sizeof r->infl_joint[v]);
	memcpy(r->infl_weight[d], r->infl_weight[v], sizeof r->infl_weight[v]);
	r->seam_lead[d] = v;
	r->seams++;
	o->rep->twins++;
	o->twin[d] = -1;
	o->assigned[d] = 1;
	o->twin[last] = d;
	return d;
}

/* Material i's triangles: each corner's look; the first corner at a
 * vertex sets it, a later one with other texels of the GPU's texture gets
 * a twin (as the glTF path's weld keeps one). */
static void colour_material(obj_colour_work *o, int i, int textured)
{
	const rig_mtl_material *mat = o->mat[i];
	const obj_work *w = o->w;
	mesh *m = o->r->mesh;
	int gpu = textured && i == o->gpu, own = mat && (mat->has_kd || textured);
	float base[3] = { 1.0f, 1.0f, 1.0f };
	if (mat && mat->has_kd)
		memcpy(base, mat->kd, sizeof base);
	const corner_look skin = skin_look();
	int tris = m->tri_count;
	for (int t = 0; t < tris; t++) {
		if (w->tri_mtl[t] != i)
			continue;
		for (int k = 0; k < 3; k++) {
			int v = (int)m->tri[t][k], vt = w->tri_vt[t][k];
			corner_look c = skin;
			if (own) {
				float rgb[3] = { base[0], base[1], base[2] }, tex[3];
				if (textured && vt >= 0 && !gpu) {
					rig_colour_texel(&o->cw, w->vt[vt][0], w->vt[vt][1], tex);
					for (int ch = 0; ch < 3; ch++)
						rgb[ch] *= tex[ch];
				}
				c.sampled = (uint8_t)(gpu && vt >= 0);
				if (c.sampled) {
					c.uv[0] = w->vt[vt][0];
					c.uv[1] = w->vt[vt][1];
				}
				for (int ch = 0; ch < 3; ch++)
					c.colour[ch] = rig_colour_srgb(rgb[ch]);
			}
			if (!o->assigned[v]) {
				set_vertex(m, v, &c);
				o->assigned[v] = 1;
				o->owned += own;
			} else if (!same_surface(m, v, &c)) {
				m->tri[t][k] = (uint32_t)twin_for(o, v, &c);
			}
		}
	}
}

/* The GPU's texture (the cache just decoded) to the scene. */
static void keep_for_gpu(obj_colour_work *o, int i)
{
	rig_scene *r = o->r;
	size_t bytes = 4 * (size_t)o->cw.w * (size_t)o->cw.h;
	r->texture_rgba = malloc(bytes);
	if (!r->texture_rgba) {
		o->gpu = -1; /* no memory for the copy: baked */
		return;
	}
	memcpy(r->texture_rgba, o->cw.rgba, bytes);
	r->texture_w = o->cw.w;
	r->texture_h = o->cw.h;
	skp_escape_name(r->texture_path, sizeof r->texture_path, o->mat[i]->map_kd);
	skp_escape_name(r->texture_material, sizeof r->texture_material, o->mat[i]->name);
}

/* Material i's texture in the colour work's cache: 1 when read, else a
 * warning naming texture and material. */
static int load_texture(obj_colour_work *o, int i)
{
	const rig_mtl_material *mat = o->mat[i];
	char file[1024];
	const char *why = "has too long a path";
	if (!mat || !mat->map_kd[0])
		return 0;
	if (beside(o->rep->library, mat->map_kd, file, sizeof file) && rig_colour_file(&o->cw, file, &why)) {
		o->rep->textures++;
		if (i == o->gpu)
			keep_for_gpu(o, i);
		return 1;
	}
	warn(o->rep, "material '%s' (%s): texture '%s' %s: drawn in the material's %s", mat->name, o->rep->library,
	     mat->map_kd, why, mat->has_kd ? "colour (Kd)" : "colour (none: the skin's)");
	return 0;
}

/* The library read, its materials matched to the OBJ's usemtl names;
 * 0 (warned) when it cannot be read. */
static int read_library(obj_colour_work *o, rig_mtl *lib)
{
	rig_obj_colour_report *rep = o->rep;
	const obj_work *w = o->w;
	const char *why = "has too long a path";
	char obj_path[sizeof rep->library];
	memcpy(obj_path, rep->library, sizeof obj_path);
	if (!beside(obj_path, w->mtllib, rep->library, sizeof rep->library) || !rig_mtl_read(rep->library, lib, &why)) {
		warn(rep, "mtllib '%s' %s: material%s '%s'%s drawn in the skin colour", rep->library, why,
		     w->mtl_count > 1 ? "s" : "", w->mtl_count ? w->mtl_name[0] : "(none used)",
		     w->mtl_count > 1 ? " and the others" : "");
		return 0;
	}
	for (int k = 0; k < lib->warnings && k < RIG_MTL_WARNINGS; k++)
		warn(rep, "%s:%s", rep->library, lib->warning[k]);
	if (lib->warnings > RIG_MTL_WARNINGS)
		warn(rep, "%s: %d more lines like these", rep->library, lib->warnings - RIG_MTL_WARNINGS);
	for (int i = 0; i < w->mtl_count; i++) {
		o->mat[i] = rig_mtl_find(lib, w->mtl_name[i]);
		rep->materials += o->mat[i] != NULL;
		if (!o->mat[i])
			warn(rep, "material '%s' is not in %s: drawn in the skin colour", w->mtl_name[i], rep->library);
	}
	return 1;
}

void rig_obj_colour(const char *obj_path, const obj_work *w, rig_scene *r, rig_obj_colour_report *rep)
{
	static rig_mtl lib;
	static obj_colour_work o;
	memset(rep, 0, sizeof *rep);
	if (!w->mtllib[0])
		return; /* as today */
	memset(&o, 0, sizeof o);
	o.w = w;
	o.r = r;
	o.rep = rep;
	snprintf(rep->library, sizeof rep->library, "%s", obj_path);
	if (!read_library(&o, &lib))
		return;
	mesh *m = r->mesh;
	o.twin = malloc(SKP_MAX_VERTS * sizeof *o.twin);
	o.assigned = calloc(SKP_MAX_VERTS, 1);
	if (!o.twin || !o.assigned) {
		warn(rep, "no memory for the materials of %s: drawn in the skin colour", rep->library);
		goto out;
	}
	for (int v = 0; v < SKP_MAX_VERTS; v++)
		o.twin[v] = -1;
	const corner_look skin = skin_look();
	for (int v = 0; v < m->vert_count; v++) {
		r->seam_lead[v] = v;
		set_vertex(m, v, &skin);
	}
	r->seams = 0;
	o.gpu = choose_gpu(&o);
	for (int i = 0; i < w->mtl_count; i++)
		colour_material(&o, i, load_texture(&o, i));
	m->coloured = o.owned > 0;
	m->textured = r->texture_rgba != NULL;
	r->textured = rep->textures;
out:
	rig_colour_done(&o.cw);
	free(o.twin);
	free(o.assigned);
}
