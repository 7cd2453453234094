#include "bind_smooth.h"

#include <math.h>
#include <string.h>

/* Neighbours by the triangles' edges, each edge from both ends (an edge
 * of two triangles listed twice: it weighs double, as it should for a
 * vertex inside a surface). */
static void build_neighbours(bind_smooth_work *k, const mesh *m)
{
	memset(k->fill, 0, sizeof k->fill[0] * (size_t)m->vert_count);
	for (int t = 0; t < m->tri_count; t++)
		for (int e = 0; e < 3; e++)
			k->fill[m->tri[t][e]] += 2;
	k->start[0] = 0;
	for (int v = 0; v < m->vert_count; v++) {
		k->start[v + 1] = k->start[v] + k->fill[v];
		k->fill[v] = k->start[v];
	}
	for (int t = 0; t < m->tri_count; t++)
		for (int e = 0; e < 3; e++) {
			uint32_t a = m->tri[t][e], b = m->tri[t][(e + 1) % 3], c = m->tri[t][(e + 2) % 3];
			k->next[k->fill[a]++] = b;
			k->next[k->fill[a]++] = c;
		}
}

static void add(bind_smooth_work *k, const uint8_t *bone, const float *weight, float f, uint8_t *list, int *n)
{
	for (int i = 0; i < BIND_SMOOTH_KEEP && weight[i] > 0.0f; i++) {
		if (!k->touched[bone[i]]) {
			k->touched[bone[i]] = 1;
			k->acc[bone[i]] = 0.0f;
			list[(*n)++] = bone[i];
		}
		k->acc[bone[i]] += f * weight[i];
	}
}

/* The keep largest of the bones in list, largest first, summing to 1. */
static void keep_largest(bind_smooth_work *k, const uint8_t *list, int n, int keep, uint8_t *bone, float *weight)
{
	float sum = 0.0f;
	for (int i = 0; i < keep; i++) {
		int best = -1;
		for (int j = 0; j < n; j++)
			if (k->touched[list[j]] && (best < 0 || k->acc[list[j]] > k->acc[list[best]]))
				best = j;
		if (best < 0 || !(k->acc[list[best]] > 0.0f)) {
			for (; i < keep; i++)
				weight[i] = 0.0f;
			break;
		}
		bone[i] = list[best];
		weight[i] = k->acc[list[best]];
		sum += weight[i];
		k->touched[list[best]] = 0;
	}
	for (int j = 0; j < n; j++)
		k->touched[list[j]] = 0;
	for (int i = 0; i < keep; i++)
		weight[i] = sum > 0.0f ? weight[i] / sum : 0.0f;
}

static void pass(bind_smooth_work *k, const mesh *m, int from)
{
	uint8_t list[SKP_MAX_BONES];
	for (int v = 0; v < m->vert_count; v++) {
		int n = 0;
		uint32_t deg = k->start[v + 1] - k->start[v];
		add(k, k->bone[from][v], k->weight[from][v], deg ? 0.5f : 1.0f, list, &n);
		for (uint32_t e = k->start[v]; e < k->start[v + 1]; e++)
			add(k, k->bone[from][k->next[e]], k->weight[from][k->next[e]], 0.5f / (float)deg, list, &n);
		keep_largest(k, list, n, BIND_SMOOTH_KEEP, k->bone[!from][v], k->weight[!from][v]);
	}
}

int bind_smooth_passes(const mesh *m)
{
	if (m->vert_count <= 0 || m->tri_count <= 0)
		return 0;
	vec3 lo = m->pos[0], hi = lo;
	for (int v = 1; v < m->vert_count; v++) {
		lo = vec3_min(lo, m->pos[v]);
		hi = vec3_max(hi, m->pos[v]);
	}
	double sum = 0.0;
	for (int t = 0; t < m->tri_count; t++)
		for (int e = 0; e < 3; e++)
			sum += vec3_length(vec3_sub(m->pos[m->tri[t][e]], m->pos[m->tri[t][(e + 1) % 3]]));
	float mean = (float)(sum / (3.0 * m->tri_count)), size = fmaxf(hi.x - lo.x, fmaxf(hi.y - lo.y, hi.z - lo.z));
	if (!(mean > 0.0f) || !(size > 0.0f))
		return 0;
	float edges = BIND_SMOOTH_REACH * size / mean;
	float passes = 2.0f * edges * edges;
	return passes < 1.0f ? 1 : passes > BIND_SMOOTH_MAX_PASSES ? BIND_SMOOTH_MAX_PASSES : (int)lrintf(passes);
}

int bind_smooth(bind_smooth_work *k, const mesh *m, skin_weights *w)
{
	int passes = bind_smooth_passes(m);
	if (passes <= 0)
		return 0;
	build_neighbours(k, m);
	memset(k->touched, 0, sizeof k->touched);
	for (int v = 0; v < m->vert_count; v++)
		for (int i = 0; i < BIND_SMOOTH_KEEP; i++) {
			k->bone[0][v][i] = i < w->count[v] ? (uint8_t)w->bone[v][i] : 0;
			k->weight[0][v][i] = i < w->count[v] ? w->weight[v][i] : 0.0f;
		}
	int cur = 0;
	for (int p = 0; p < passes; p++, cur = !cur)
		pass(k, m, cur);
	for (int v = 0; v < m->vert_count; v++) {
		uint8_t list[BIND_SMOOTH_KEEP];
		int n = 0;
		add(k, k->bone[cur][v], k->weight[cur][v], 1.0f, list, &n);
		uint8_t bone[SKP_MAX_INFLUENCES];
		float weight[SKP_MAX_INFLUENCES];
		keep_largest(k, list, n, SKP_MAX_INFLUENCES, bone, weight);
		int c = 0;
		while (c < SKP_MAX_INFLUENCES && weight[c] > 0.0f)
			c++;
		if (!c) {   /* nothing reached it: the root, as bind_weights does */
			bone[0] = 0;
			weight[0] = 1.0f;
			c = 1;
		}
		for (int i = 0; i < c; i++) {
			w->bone[v][i] = bone[i];
			w->weight[v][i] = weight[i];
		}
		w->count[v] = (uint8_t)c;
		for (int i = c; i < SKP_MAX_INFLUENCES; i++) {
			w->bone[v][i] = 0;
			w->weight[v][i] = 0.0f;
		}
	}
	return passes;
}
