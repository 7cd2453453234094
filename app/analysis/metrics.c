#include "metrics.h"

#include <math.h>

void metrics_segments_from_pose(metrics_segments *out, const skel_pose *p, int bone_count)
{
	float longest = 0.0f;
	for (int b = 0; b < bone_count; b++) {
		float len = vec3_length(vec3_sub(p->tip[b], p->head[b]));
		if (len > longest)
			longest = len;
	}
	out->count = 0;
	for (int b = 0; b < bone_count; b++) {
		if (!(vec3_length(vec3_sub(p->tip[b], p->head[b])) > 1e-6f * longest))
			continue;
		int i = out->count++;
		out->head[i] = p->head[b];
		out->tip[i] = p->tip[b];
		out->axis[i] = vec3_sub(p->tip[b], p->head[b]);
		out->inv_len2[i] = 1.0f / vec3_dot(out->axis[i], out->axis[i]);
	}
}

/* The metrics run this for every vertex, segment and frame: no division. */
static float segment_distance2(const metrics_segments *g, int i, vec3 q)
{
	vec3 aq = vec3_sub(q, g->head[i]);
	float s = vec3_dot(aq, g->axis[i]) * g->inv_len2[i];
	s = s < 0.0f ? 0.0f : s > 1.0f ? 1.0f : s;
	vec3 d = vec3_madd(aq, g->axis[i], -s);
	return vec3_dot(d, d);
}

float metrics_segment_distance(const metrics_segments *g, vec3 q)
{
	if (g->count == 0)
		return 0.0f;
	float best = INFINITY;
	for (int i = 0; i < g->count; i++) {
		float d2 = segment_distance2(g, i, q);
		if (d2 < best)
			best = d2;
	}
	return sqrtf(best);
}

static vec3 vertex(const float *xyz, uint32_t v)
{
	return vec3_make(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
}

void metrics_distances(const metrics_segments *g, const float *xyz, int n, float *out)
{
	for (int v = 0; v < n; v++)
		out[v] = metrics_segment_distance(g, vertex(xyz, (uint32_t)v));
}

/* Corner c relative to the origin o, in double. */
static void rel(const float *xyz, uint32_t c, const double o[3], double r[3])
{
	for (int k = 0; k < 3; k++)
		r[k] = (double)xyz[3 * c + k] - o[k];
}

double metrics_mesh_volume(const float *xyz, const uint32_t (*tri)[3], int tri_count)
{
	if (tri_count <= 0)
		return 0.0;
	/* The sum is origin independent only in exact arithmetic: an origin on
	 * the mesh keeps the terms as small as the mesh itself. */
	double o[3] = { xyz[3 * tri[0][0]], xyz[3 * tri[0][0] + 1], xyz[3 * tri[0][0] + 2] };
	double sum = 0.0;
	for (int t = 0; t < tri_count; t++) {
		double a[3], b[3], c[3];
		rel(xyz, tri[t][0], o, a);
		rel(xyz, tri[t][1], o, b);
		rel(xyz, tri[t][2], o, c);
		sum += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
		       a[2] * (b[0] * c[1] - b[1] * c[0]);
	}
	return sum / 6.0;
}

metrics_radius metrics_radius_ratio(const metrics_segments *posed, const float *xyz, const float *rest,
			      int n, float min_rest)
{
	metrics_radius r = { INFINITY, -INFINITY, 0 };
	for (int v = 0; v < n; v++) {
		if (!(rest[v] > min_rest))
			continue;
		float ratio = metrics_segment_distance(posed, vertex(xyz, (uint32_t)v)) / rest[v];
		if (ratio < r.min)
			r.min = ratio;
		if (ratio > r.max)
			r.max = ratio;
		r.counted++;
	}
	if (r.counted == 0)
		r.min = r.max = 1.0f;
	return r;
}
