#include "setup_mesh_pick.h"

#include <string.h>
#include <strings.h>

#include "setup_mesh_io.h"
#include "cli_say.h"
#include "setup_scratch.h"
#include "skp_format.h"

static void list_groups(const char *path, const obj_work *w)
{
	if (w->group_count == 0) {
		cli_warn("%s: the file has no g or o names: leave --group out\n", path);
		return;
	}
	cli_warn("%s: its groups:", path);
	for (int i = 0; i < w->group_count; i++)
		cli_warn("%s %s (%ld faces)", i ? "," : "", w->group[i].name, w->group[i].faces);
	cli_warn("%s\n", w->group_overflow ? ", and more" : "");
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
	skp_format(name, sizeof name, "%s", g->name);
	int others = w->group_count - 1;
	if (!setup_load_obj(path, name, out, NULL))
		return -1;
	cli_say("%s: using group '%s' (%d vertices); left out %d other group%s (%ld faces, %ld vertices",
		path, name, out->vert_count, others, others == 1 ? "" : "s", other_faces,
		all_verts - out->vert_count);
	w = &setup_scratch_area()->obj;
	for (int i = 0, shown = 0; i < w->group_count && shown < 4; i++)
		if (strcmp(w->group[i].name, name) != 0 && w->group[i].faces > 0)
			cli_say("%s %s", shown++ ? "," : ":", w->group[i].name);
	cli_say("%s); --group NAME picks another\n", others > 4 ? ", ..." : "");
	return 0;
}

/* ---- connected parts ---- */

static int find_root(int *up, int v)
{
	while (up[v] != v)
		v = up[v] = up[up[v]];
	return v;
}

/* Every edge of the mesh bucketed by its smaller vertex (a counting sort),
 * the part of each edge not shared by exactly two triangles marked open. */
static void mark_open_parts(const mesh *m, mesh_pick_work *p)
{
	uint32_t *start = p->edge_start;
	memset(start, 0, sizeof(uint32_t) * ((size_t)m->vert_count + 1));
	for (int t = 0; t < m->tri_count; t++)
		for (int k = 0; k < 3; k++) {
			uint32_t a = m->tri[t][k], b = m->tri[t][(k + 1) % 3];
			start[(a < b ? a : b) + 1]++;
		}
	for (int v = 0; v < m->vert_count; v++)
		start[v + 1] += start[v];
	for (int v = 0; v < m->vert_count; v++)
		p->fill[v] = start[v];
	for (int t = 0; t < m->tri_count; t++)
		for (int k = 0; k < 3; k++) {
			uint32_t a = m->tri[t][k], b = m->tri[t][(k + 1) % 3];
			p->edge_other[p->fill[a < b ? a : b]++] = a < b ? b : a;
		}
	for (int v = 0; v < m->vert_count; v++) {
		uint32_t *e = p->edge_other + start[v], n = start[v + 1] - start[v];
		for (uint32_t i = 1; i < n; i++) /* a vertex has a handful of edges */
			for (uint32_t j = i; j > 0 && e[j] < e[j - 1]; j--) {
				uint32_t x = e[j];
				e[j] = e[j - 1];
				e[j - 1] = x;
			}
		for (uint32_t i = 0, j; i < n; i = j) {
			for (j = i; j < n && e[j] == e[i]; j++)
				;
			if (j - i != 2)
				p->open[find_root(p->up, v)] = 1;
		}
	}
}

/* The largest closed part's root, else the largest part's. */
static int best_part(const mesh *m, const mesh_pick_work *p, int *count)
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

static void keep_part(mesh *m, mesh_pick_work *p, int root)
{
	int *to = p->to, n = 0, t2 = 0;
	for (int v = 0; v < m->vert_count; v++) {
		to[v] = find_root(p->up, v) == root ? n : -1;
		if (to[v] >= 0) {
			m->pos[n] = m->pos[v];
			memcpy(m->colour[n], m->colour[v], sizeof m->colour[v]);
			memcpy(m->uv[n], m->uv[v], sizeof m->uv[v]);
			m->sampled[n] = m->sampled[v];
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
}

/* Union-find over the triangles' vertices: each vertex's part. */
static void find_parts(const mesh *m, mesh_pick_work *p)
{
	for (int v = 0; v < m->vert_count; v++) {
		p->up[v] = v;
		p->tris[v] = p->verts[v] = 0;
		p->open[v] = 0;
	}
	for (int t = 0; t < m->tri_count; t++) {
		int a = find_root(p->up, (int)m->tri[t][0]);
		for (int k = 1; k < 3; k++) {
			int b = find_root(p->up, (int)m->tri[t][k]);
			if (a != b)
				p->up[b] = a;
		}
	}
	for (int v = 0; v < m->vert_count; v++)
		p->verts[find_root(p->up, v)]++;
	for (int t = 0; t < m->tri_count; t++)
		p->tris[find_root(p->up, (int)m->tri[t][0])]++;
}

/* In the start-up scratch (the OBJ's work space is free again by now):
 * no allocation in skinplay, which binds --mesh at start-up too. */
static void pick_largest_part(const char *path, mesh *m)
{
	mesh_pick_work *p = &setup_scratch_area()->pick;
	long all = m->vert_count;
	find_parts(m, p);
	mark_open_parts(m, p);
	int count, best = best_part(m, p, &count);
	if (count <= 1 || best < 0)
		return;
	long kept = p->verts[best];
	int closed = !p->open[best];
	keep_part(m, p, best);
	cli_say("%s: using its largest %sconnected part (%ld vertices); left out %d other part%s (%ld vertices)\n",
		path, closed ? "closed " : "", kept, count - 1, count == 2 ? "" : "s", all - kept);
}

int setup_pick_mesh(const char *path, const char *group, mesh *out)
{
	int missing;
	const obj_work *w = setup_load_obj(path, group, out, &missing);
	if (!w && missing) {
		list_groups(path, &setup_scratch_area()->obj);
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
