#include "parts.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


#define PARTS_MAX_TESTED 64   /* larger parts a part is tested against: the largest first */

typedef struct part_info {
	double volume;
	vec3 centroid;
	int verts, tris, open_edges;
	int counted;
} part_info;

static int root_of(int *up, int v)
{
	while (up[v] != v) {
		up[v] = up[up[v]];
		v = up[v];
	}
	return v;
}

/* Each vertex's part (0..count-1, -1 for a vertex on no triangle). */
static int label_parts(const mesh *m, int *up, int *part)
{
	for (int v = 0; v < m->vert_count; v++)
		up[v] = v, part[v] = -1;
	for (int t = 0; t < m->tri_count; t++)
		for (int k = 1; k < 3; k++) {
			int a = root_of(up, (int)m->tri[t][0]), b = root_of(up, (int)m->tri[t][k]);
			if (a != b)
				up[a] = b;
		}
	int count = 0;
	for (int t = 0; t < m->tri_count; t++) {
		int r = root_of(up, (int)m->tri[t][0]);
		if (part[r] < 0)
			part[r] = count++;
	}
	for (int v = 0; v < m->vert_count; v++)
		part[v] = part[root_of(up, v)];
	return count;
}

static int cmp_edge(const void *a, const void *b)
{
	const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
	return x < y ? -1 : x > y;
}

/* Edges met by one triangle only (as directed edges, each with no
 * opposite), added to their part's count. */
static int count_open_edges(const mesh *m, const int *part, part_info *info)
{
	size_t n = 3 * (size_t)m->tri_count;
	uint64_t *e = malloc(sizeof *e * (n ? n : 1));
	if (!e)
		return -1;
	for (int t = 0; t < m->tri_count; t++)
		for (int k = 0; k < 3; k++) {
			uint64_t a = m->tri[t][k], b = m->tri[t][(k + 1) % 3];
			e[3 * (size_t)t + (size_t)k] = a < b ? (a << 32 | b) << 1 : (b << 32 | a) << 1 | 1;
		}
	qsort(e, n, sizeof *e, cmp_edge);
	for (size_t i = 0; i < n;) {
		size_t j = i;
		int fwd = 0, back = 0;
		for (; j < n && e[j] >> 1 == e[i] >> 1; j++)
			*(e[j] & 1 ? &back : &fwd) += 1;
		if (fwd != back)
			info[part[(int)(e[i] >> 33)]].open_edges += abs(fwd - back);
		i = j;
	}
	free(e);
	return 0;
}

/* The solid angle of triangle abc seen from p, over 4 pi (Van Oosterom and
 * Strackee): summed over a closed surface, 1 inside and 0 outside. */
static double winding(const mesh *m, const uint32_t *tri, vec3 p)
{
	vec3 a = vec3_sub(m->pos[tri[0]], p), b = vec3_sub(m->pos[tri[1]], p), c = vec3_sub(m->pos[tri[2]], p);
	double la = vec3_length(a), lb = vec3_length(b), lc = vec3_length(c);
	double det = vec3_dot(a, vec3_cross(b, c));
	double div = la * lb * lc + vec3_dot(a, b) * lc + vec3_dot(b, c) * la + vec3_dot(c, a) * lb;
	return atan2(det, div) / (2.0 * 3.14159265358979323846);
}

/* Six times the signed volume of the tetrahedron o, a, b, c, in double. */
static double tetra6(vec3 o, vec3 a, vec3 b, vec3 c)
{
	double ax = a.x - o.x, ay = a.y - o.y, az = a.z - o.z, bx = b.x - o.x, by = b.y - o.y, bz = b.z - o.z;
	double cx = c.x - o.x, cy = c.y - o.y, cz = c.z - o.z;
	return ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
}

/* Each part's centroid, then its volume about it; first[p]..first[p+1]
 * in by_part: part p's triangles. */
static void measure_parts(const mesh *m, const int *part, part_info *info, int count, int *first, int *by_part)
{
	for (int v = 0; v < m->vert_count; v++)
		if (part[v] >= 0) {
			info[part[v]].centroid = vec3_add(info[part[v]].centroid, m->pos[v]);
			info[part[v]].verts++;
		}
	for (int p = 0; p < count; p++)
		info[p].centroid = vec3_scale(info[p].centroid, 1.0f / (float)info[p].verts);
	for (int t = 0; t < m->tri_count; t++) {
		part_info *pi = &info[part[m->tri[t][0]]];
		pi->volume += tetra6(pi->centroid, m->pos[m->tri[t][0]], m->pos[m->tri[t][1]], m->pos[m->tri[t][2]]) / 6.0;
		pi->tris++;
	}
	first[0] = 0;
	for (int p = 0; p < count; p++)
		first[p + 1] = first[p] + info[p].tris;
	for (int p = 0; p < count; p++)
		info[p].tris = 0;
	for (int t = 0; t < m->tri_count; t++) {
		int p = part[m->tri[t][0]];
		by_part[first[p] + info[p].tris++] = t;
	}
}

static const part_info *sort_info;  /* cmp_volume_desc's parts (qsort has no context) */

static int cmp_volume_desc(const void *a, const void *b)
{
	double x = sort_info[*(const int *)a].volume, y = sort_info[*(const int *)b].volume;
	return x > y ? -1 : x < y;
}

/* Counted: closed, enclosing a volume, inside no larger counted part. */
static void choose(const mesh *m, const int *first, const int *by_part, part_info *info, int count, int *order,
		   parts_summary *out)
{
	for (int p = 0; p < count; p++)
		order[p] = p;
	sort_info = info;
	qsort(order, (size_t)count, sizeof *order, cmp_volume_desc);
	int tested[PARTS_MAX_TESTED], n_tested = 0;
	for (int i = 0; i < count; i++) {
		part_info *pi = &info[order[i]];
		if (pi->open_edges) {
			out->open++;
			continue;
		}
		if (!(pi->volume > 0.0))
			continue;
		int inside = 0;
		for (int k = 0; k < n_tested && !inside; k++) {
			double w = 0.0;
			for (int i2 = first[tested[k]]; i2 < first[tested[k] + 1]; i2++)
				w += winding(m, m->tri[by_part[i2]], pi->centroid);
			inside = fabs(w) > 0.5;
		}
		if (inside) {
			out->inner++;
			continue;
		}
		pi->counted = 1;
		out->counted++;
		if (n_tested < PARTS_MAX_TESTED)
			tested[n_tested++] = order[i];
	}
}

int parts_for_volume(const mesh *m, uint32_t (*tri_out)[3], parts_summary *out)
{
	memset(out, 0, sizeof *out);
	int n = m->vert_count > 0 ? m->vert_count : 1;
	int *up = malloc(sizeof *up * (size_t)n), *part = malloc(sizeof *part * (size_t)n);
	int *order = malloc(sizeof *order * (size_t)n), *first = malloc(sizeof *first * ((size_t)n + 1));
	int *by_part = malloc(sizeof *by_part * (size_t)(m->tri_count > 0 ? m->tri_count : 1));
	part_info *info = calloc((size_t)n, sizeof *info);
	int rc = -1;
	if (!up || !part || !order || !first || !by_part || !info)
		goto done;
	out->parts = label_parts(m, up, part);
	if (count_open_edges(m, part, info) < 0)
		goto done;
	measure_parts(m, part, info, out->parts, first, by_part);
	for (int p = 0; p < out->parts; p++)
		out->open_edges += info[p].open_edges;
	choose(m, first, by_part, info, out->parts, order, out);
	for (int t = 0; t < m->tri_count; t++)
		if (info[part[m->tri[t][0]]].counted)
			memcpy(tri_out[out->counted_tris++], m->tri[t], sizeof tri_out[0]);
	rc = 0;
done:
	free(up);
	free(part);
	free(order);
	free(first);
	free(by_part);
	free(info);
	return rc;
}
