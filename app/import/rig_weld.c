#include "rig_weld.h"

#include <stdlib.h>
#include <string.h>

static const rig_scene *sort_scene;  /* qsort has no context argument */

static int cmp_float(float a, float b)
{
	return a < b ? -1 : a > b;
}

static int same_weights(const rig_scene *r, int a, int b)
{
	if (r->infl_count[a] != r->infl_count[b])
		return 0;
	for (int k = 0; k < r->infl_count[a]; k++) {
		int found = 0;
		for (int l = 0; l < r->infl_count[b] && !found; l++)
			found = r->infl_joint[a][k] == r->infl_joint[b][l] &&
				r->infl_weight[a][k] == r->infl_weight[b][l];
		if (!found)
			return 0;
	}
	return 1;
}

static int by_place(const void *pa, const void *pb)
{
	const vec3 *p = sort_scene->mesh->pos;
	int a = *(const int *)pa, b = *(const int *)pb;
	int c = cmp_float(p[a].x, p[b].x);
	if (!c)
		c = cmp_float(p[a].y, p[b].y);
	if (!c)
		c = cmp_float(p[a].z, p[b].z);
	return c ? c : (a > b) - (a < b);
}

static int same_place(vec3 a, vec3 b)
{
	return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* Whether two vertices show the same texels: neither samples the GPU's
 * texture, or both do at the same UV (a seam's two sides do not). */
static int same_surface(const mesh *m, int a, int b)
{
	if (m->sampled[a] != m->sampled[b])
		return 0;
	return !m->sampled[a] || (m->uv[a][0] == m->uv[b][0] && m->uv[a][1] == m->uv[b][1]);
}

/* remap[v]: the kept vertex v becomes (first of its place, weights and
 * texels); lead[v]: the first kept one of its place and weights. */
static void find_twins(rig_scene *r, const int *order, int *remap, int *lead)
{
	const vec3 *p = r->mesh->pos;
	int n = r->mesh->vert_count;
	for (int i = 0; i < n; i++) {
		int v = order[i];
		remap[v] = lead[v] = v;
		for (int k = i - 1; k >= 0 && same_place(p[order[k]], p[v]); k--) {
			int u = order[k];
			if (remap[u] != u || !same_weights(r, u, v))
				continue;
			lead[v] = u; /* ties sort by index: the last one met is the lowest */
			if (same_surface(r->mesh, u, v)) {
				remap[v] = u;
				break;
			}
		}
	}
}

static void compact(rig_scene *r, int *remap, const int *lead)
{
	mesh *m = r->mesh;
	int n = m->vert_count, kept = 0;
	int *slot = malloc((size_t)n * sizeof *slot);
	if (!slot)
		return;
	r->seams = 0;
	for (int v = 0; v < n; v++) {
		if (remap[v] != v)
			continue;
		slot[v] = kept;
		r->seam_lead[kept] = slot[lead[v]];
		r->seams += lead[v] != v;
		m->pos[kept] = m->pos[v];
		memcpy(m->colour[kept], m->colour[v], sizeof m->colour[v]);
		memcpy(m->uv[kept], m->uv[v], sizeof m->uv[v]);
		m->sampled[kept] = m->sampled[v];
		r->infl_count[kept] = r->infl_count[v];
		r->held[kept] = r->held[v];
		memcpy(r->infl_joint[kept], r->infl_joint[v], sizeof r->infl_joint[v]);
		memcpy(r->infl_weight[kept], r->infl_weight[v], sizeof r->infl_weight[v]);
		kept++;
	}
	for (int t = 0; t < m->tri_count; t++)
		for (int k = 0; k < 3; k++) {
			int v = (int)m->tri[t][k];
			m->tri[t][k] = (uint32_t)slot[remap[v]];
		}
	r->welded = n - kept;
	m->vert_count = kept;
	free(slot);
}

void rig_weld(rig_scene *r)
{
	int n = r->mesh->vert_count;
	int *order = malloc((size_t)n * sizeof *order), *remap = malloc((size_t)n * sizeof *remap);
	int *lead = malloc((size_t)n * sizeof *lead);
	if (order && remap && lead) {
		for (int v = 0; v < n; v++)
			order[v] = v;
		sort_scene = r;
		qsort(order, (size_t)n, sizeof *order, by_place);
		find_twins(r, order, remap, lead);
		compact(r, remap, lead);
	}
	free(order);
	free(remap);
	free(lead);
}
