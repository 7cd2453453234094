#include "skin_weights.h"

#include <math.h>
#include <string.h>

int skin_weights_dominant(const skin_weights *w, int v)
{
	int best = 0;
	for (int k = 1; k < w->count[v]; k++)
		if (w->weight[v][k] > w->weight[v][best])
			best = k;
	return w->count[v] ? w->bone[v][best] : -1;
}

float skin_weights_of(const skin_weights *w, int v, int b)
{
	for (int k = 0; k < w->count[v]; k++)
		if (w->bone[v][k] == b)
			return w->weight[v][k];
	return 0.0f;
}

float skin_weights_set_largest(skin_weights *w, int v, const uint16_t *bone, const float *weight,
			       int count)
{
	int top[SKP_MAX_INFLUENCES], kept = 0;
	for (int i = 0; i < count; i++) {
		if (!(weight[i] > 0.0f))
			continue;
		int k = kept < SKP_MAX_INFLUENCES ? kept++ : SKP_MAX_INFLUENCES;
		if (k == SKP_MAX_INFLUENCES && !(weight[i] > weight[top[k - 1]]))
			continue;
		if (k == SKP_MAX_INFLUENCES)
			k--;
		for (; k > 0 && weight[i] > weight[top[k - 1]]; k--)
			top[k] = top[k - 1];
		top[k] = i;
	}
	float sum = 0.0f;
	for (int k = 0; k < kept; k++)
		sum += weight[top[k]];
	if (!(sum > 0.0f))
		return 0.0f;
	w->count[v] = (uint8_t)kept;
	for (int k = 0; k < kept; k++) {
		w->bone[v][k] = bone[top[k]];
		w->weight[v][k] = weight[top[k]] / sum;
	}
	return sum;
}

/* Total variation between the weight vectors of two vertices: walk a's
 * influences against b's, then b's that a lacks. */
static double edge_diff(const skin_weights *w, int a, int b)
{
	double d = 0.0;
	for (int k = 0; k < w->count[a]; k++)
		d += fabs((double)w->weight[a][k] - skin_weights_of(w, b, w->bone[a][k]));
	for (int k = 0; k < w->count[b]; k++)
		if (skin_weights_of(w, a, w->bone[b][k]) == 0.0f)
			d += w->weight[b][k];
	return 0.5 * d;
}

void skin_weights_stats_compute(const skin_weights *w, int bone_count,
				const uint32_t (*tri)[3], int tri_count,
				skin_weights_stats *out)
{
	memset(out, 0, sizeof *out);
	for (int v = 0; v < w->vert_count; v++) {
		if (w->count[v] > out->max_influences)
			out->max_influences = w->count[v];
		for (int k = 0; k < w->count[v]; k++)
			if (w->bone[v][k] < bone_count && w->weight[v][k] > 0.0f)
				out->bone_verts[w->bone[v][k]]++;
	}
	double sum = 0.0;
	for (int t = 0; t < tri_count; t++) {
		for (int e = 0; e < 3; e++) {
			uint32_t a = tri[t][e], b = tri[t][(e + 1) % 3];
			if (a >= (uint32_t)w->vert_count || b >= (uint32_t)w->vert_count)
				continue;
			sum += edge_diff(w, (int)a, (int)b);
			out->edge_count++;
		}
	}
	if (out->edge_count)
		out->edge_diff_mean = sum / (double)out->edge_count;
}
