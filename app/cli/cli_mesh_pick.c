#include "cli_mesh_pick.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli_mesh_io.h"
#include "cli_scratch.h"

static void list_groups(const char *path, const obj_work *w)
{
	if (w->group_count == 0) {
		fprintf(stderr, "%s: the file has no g or o names: leave --group out\n", path);
		return;
	}
	fprintf(stderr, "%s: its groups:", path);
	for (int i = 0; i < w->group_count; i++)
		fprintf(stderr, "%s %s (%ld faces)", i ? "," : "", w->group[i].name, w->group[i].faces);
	fprintf(stderr, "%s\n", w->group_overflow ? ", and more" : "");
}

static const obj_group *body_group(const obj_work *w)
{
	for (int i = 0; i < w->group_count; i++)
		if (strcasecmp(w->group[i].name, "body") == 0 && w->group[i].faces > 0 &&
		    w->group[i].faces < w->file_faces)
			return &w->group[i];
	return NULL;
}

static int pick_body_group(const char *path, const obj_work *w, mesh *out)
{
	static char name[SKP_MAX_NAME];
	const obj_group *g = body_group(w);
	long all_verts = w->file_verts, other_faces = w->file_faces - g->faces;
	snprintf(name, sizeof name, "%s", g->name);
	int others = w->group_count - 1;
	if (!cli_load_obj(path, name, out, NULL))
		return -1;
	fprintf(stderr, "%s: using group '%s' (%d vertices); left out %d other group%s (%ld faces, %ld vertices",
		path, name, out->vert_count, others, others == 1 ? "" : "s", other_faces,
		all_verts - out->vert_count);
	w = &cli_scratch_area()->obj;
	for (int i = 0, shown = 0; i < w->group_count && shown < 4; i++)
		if (strcmp(w->group[i].name, name) != 0 && w->group[i].faces > 0)
			fprintf(stderr, "%s %s", shown++ ? "," : ":", w->group[i].name);
	fprintf(stderr, "%s); --group NAME picks another\n", others > 4 ? ", ..." : "");
	return 0;
}

/* ---- connected parts ---- */

static int find_root(int *up, int v)
{
	while (up[v] != v)
		v = up[v] = up[up[v]];
	return v;
}

static int cmp_u64(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
	return x < y ? -1 : x > y;
}

typedef struct parts {
	int *up;             /* union-find over vertices */
	long *tris, *verts;  /* per root */
	char *open;          /* per root: an edge not shared by exactly two triangles */
} parts;

static void mark_open_parts(const mesh *m, parts *p)
{
	uint64_t *e = malloc(sizeof *e * (size_t)m->tri_count * 3);
	if (!e)
		return;
	long n = 0;
	for (int t = 0; t < m->tri_count; t++)
		for (int k = 0; k < 3; k++) {
			uint64_t a = m->tri[t][k], b = m->tri[t][(k + 1) % 3];
			e[n++] = a < b ? a << 32 | b : b << 32 | a;
		}
	qsort(e, (size_t)n, sizeof *e, cmp_u64);
	for (long i = 0, j; i < n; i = j) {
		for (j = i; j < n && e[j] == e[i]; j++)
			;
		if (j - i != 2)
			p->open[find_root(p->up, (int)(e[i] >> 32))] = 1;
	}
	free(e);
}

/* The largest closed part's root, else the largest part's. */
static int best_part(const mesh *m, const parts *p, int *count)
{
	int best = -1, closed = 0;
	*count = 0;
	for (int v = 0; v < m->vert_count; v++) {
		if (p->up[v] != v)
			continue;
		(*count)++;
		int c = !p->open[v];
		if (best < 0 || c > closed || (c == closed && p->tris[v] > p->tris[best])) {
			best = v;
			closed = c;
		}
	}
	return best;
}

static void keep_part(mesh *m, const parts *p, int root)
{
	int *to = malloc(sizeof *to * (size_t)m->vert_count), n = 0, t2 = 0;
	if (!to)
		return;
	for (int v = 0; v < m->vert_count; v++) {
		to[v] = find_root(p->up, v) == root ? n : -1;
		if (to[v] >= 0) {
			m->pos[n] = m->pos[v];
			m->normal[n++] = m->normal[v];
		}
	}
	for (int t = 0; t < m->tri_count; t++)
		if (to[m->tri[t][0]] >= 0) {
			for (int k = 0; k < 3; k++)
				m->tri[t2][k] = (uint32_t)to[m->tri[t][k]];
			t2++;
		}
	m->vert_count = n;
	m->tri_count = t2;
	free(to);
}

static void pick_largest_part(const char *path, mesh *m)
{
	parts p;
	size_t nv = (size_t)m->vert_count;
	p.up = malloc(sizeof *p.up * nv);
	p.tris = calloc(nv, sizeof *p.tris);
	p.verts = calloc(nv, sizeof *p.verts);
	p.open = calloc(nv, 1);
	if (p.up && p.tris && p.verts && p.open) {
		for (size_t v = 0; v < nv; v++)
			p.up[v] = (int)v;
		for (int t = 0; t < m->tri_count; t++) {
			int a = find_root(p.up, (int)m->tri[t][0]);
			for (int k = 1; k < 3; k++) {
				int b = find_root(p.up, (int)m->tri[t][k]);
				if (a != b)
					p.up[b] = a;
			}
		}
		for (size_t v = 0; v < nv; v++)
			p.verts[find_root(p.up, (int)v)]++;
		for (int t = 0; t < m->tri_count; t++)
			p.tris[find_root(p.up, (int)m->tri[t][0])]++;
		mark_open_parts(m, &p);
		int count, best = best_part(m, &p, &count);
		if (count > 1 && best >= 0) {
			long kept = p.verts[best];
			keep_part(m, &p, best);
			fprintf(stderr, "%s: using its largest %sconnected part (%ld vertices); left out %d other part%s "
				"(%ld vertices)\n", path, p.open[best] ? "" : "closed ", kept, count - 1,
				count == 2 ? "" : "s", (long)nv - kept);
		}
	}
	free(p.up);
	free(p.tris);
	free(p.verts);
	free(p.open);
}

int cli_pick_mesh(const char *path, const char *group, mesh *out)
{
	int missing;
	const obj_work *w = cli_load_obj(path, group, out, &missing);
	if (!w && missing) {
		list_groups(path, &cli_scratch_area()->obj);
		return -1;
	}
	if (!w)
		return -1;
	if (group)
		return 0;
	if (body_group(w))
		return pick_body_group(path, w, out);
	pick_largest_part(path, out);
	return 0;
}
