#include "measure.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

int measure_init(measure_state *t, const mesh *m, const skel_pose *bind, int bone_count,
		      const char *what)
{
	vec3 lo = m->pos[0], hi = m->pos[0];
	t->mesh = m;
	t->bone_count = bone_count;
	for (int v = 0; v < m->vert_count; v++) {
		vec3 p = m->pos[v];
		t->bind_xyz[3 * v] = p.x; t->bind_xyz[3 * v + 1] = p.y; t->bind_xyz[3 * v + 2] = p.z;
		lo = vec3_make(p.x < lo.x ? p.x : lo.x, p.y < lo.y ? p.y : lo.y, p.z < lo.z ? p.z : lo.z);
		hi = vec3_make(p.x > hi.x ? p.x : hi.x, p.y > hi.y ? p.y : hi.y, p.z > hi.z ? p.z : hi.z);
	}
	vec3 ext = vec3_sub(hi, lo);
	float size = ext.x > ext.y ? ext.x : ext.y;
	t->min_rest = 1e-4f * (size > ext.z ? size : ext.z);
	if (parts_for_volume(m, t->vol_tri, &t->parts) < 0) {
		fprintf(stderr, "%s: out of memory finding the mesh's parts\n", what);
		return -1;
	}
	t->volume_closed = t->parts.counted_tris > 0;
	t->vol_tri_count = t->parts.counted_tris;
	if (!t->volume_closed) {
		memcpy(t->vol_tri, m->tri, sizeof t->vol_tri[0] * (size_t)m->tri_count);
		t->vol_tri_count = m->tri_count;
	}
	t->rest_volume = metrics_mesh_volume(t->bind_xyz, (const uint32_t (*)[3])t->vol_tri, t->vol_tri_count);
	measure_pose(t, bind);
	metrics_distances(&t->seg, t->bind_xyz, m->vert_count, t->rest_dist);
	if (t->rest_volume == 0.0) {
		fprintf(stderr, "%s: the mesh encloses no volume\n", what);
		return -1;
	}
	return 0;
}

void measure_pose(measure_state *t, const skel_pose *pose)
{
	metrics_segments_from_pose(&t->seg, pose, t->bone_count);
}

/* Squared distance from each vertex to the nearest segment, 4 vertices at
 * a time: the arithmetic of metrics_segment_distance (metrics.c) step
 * for step, so the result is the same to the bit (no FMA: the host
 * compiler has none to contract to), only 3-4 times faster. */
typedef float v4f __attribute__((vector_size(16)));
typedef int32_t v4i __attribute__((vector_size(16)));

#define SELECT(m, a, b) ((v4f)(((v4i)(a) & (m)) | ((v4i)(b) & ~(m))))

static void nearest2(const metrics_segments *g, const float *xyz, int n, float *out)
{
	static float sx[SKP_MAX_VERTS + 4], sy[SKP_MAX_VERTS + 4], sz[SKP_MAX_VERTS + 4];
	for (int v = 0; v < n; v++)
		sx[v] = xyz[3 * v], sy[v] = xyz[3 * v + 1], sz[v] = xyz[3 * v + 2];
	for (int v = n; v < n + 4; v++)
		sx[v] = sy[v] = sz[v] = 0.0f;
	const v4f zero = { 0, 0, 0, 0 }, one = { 1, 1, 1, 1 };
	const v4f inf = { INFINITY, INFINITY, INFINITY, INFINITY };
	for (int v = 0; v < n; v += 4) {
		v4f qx, qy, qz, best = inf;
		memcpy(&qx, sx + v, sizeof qx);
		memcpy(&qy, sy + v, sizeof qy);
		memcpy(&qz, sz + v, sizeof qz);
		for (int i = 0; i < g->count; i++) {
			v4f ax = qx - g->head[i].x, ay = qy - g->head[i].y, az = qz - g->head[i].z;
			v4f s = (ax * g->axis[i].x + ay * g->axis[i].y + az * g->axis[i].z) * g->inv_len2[i];
			s = SELECT(s < zero, zero, s);
			s = SELECT(s > one, one, s);
			v4f ms = -s;
			v4f dx = ax + g->axis[i].x * ms, dy = ay + g->axis[i].y * ms, dz = az + g->axis[i].z * ms;
			v4f d2 = dx * dx + dy * dy + dz * dz;
			best = SELECT(d2 < best, d2, best);
		}
		float b[4];
		memcpy(b, &best, sizeof b);
		for (int k = 0; k < 4 && v + k < n; k++)
			out[v + k] = g->count ? b[k] : 0.0f;
	}
}

double measure_volume(const measure_state *t, const float *xyz)
{
	return metrics_mesh_volume(xyz, (const uint32_t (*)[3])t->vol_tri, t->vol_tri_count) / t->rest_volume;
}

/* metrics_radius_ratio's loop, keeping each ratio and the worst vertex. */
measure_row measure_skinned(const measure_state *t, const float *xyz, float *ratio)
{
	static float d2[SKP_MAX_VERTS + 4];
	const mesh *m = t->mesh;
	measure_row row = { 0.0, { INFINITY, -INFINITY, 0 }, -1 };
	row.volume_ratio = measure_volume(t, xyz);
	nearest2(&t->seg, xyz, m->vert_count, d2);
	for (int v = 0; v < m->vert_count; v++) {
		float r = NAN;
		if (t->rest_dist[v] > t->min_rest) {
			r = sqrtf(d2[v]) / t->rest_dist[v];
			if (r < row.radius.min) {
				row.radius.min = r;
				row.worst_vertex = v;
			}
			if (r > row.radius.max)
				row.radius.max = r;
			row.radius.counted++;
		}
		if (ratio)
			ratio[v] = r;
	}
	if (row.radius.counted == 0)
		row.radius.min = row.radius.max = 1.0f;
	return row;
}
