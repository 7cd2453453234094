#include "rig_weights.h"

#include <string.h>

/* The share of vertex v's weight on joints that move with the root for
 * want of a mapped joint of their own (the root or a joint mapped to it
 * above them). */
static float fallen_share(const rig_scene *r, const rig_map *m, int v)
{
	float fallen = 0.0f, all = 0.0f;
	for (int k = 0; k < r->infl_count[v]; k++) {
		int j = r->infl_joint[v][k];
		all += r->infl_weight[v][k];
		if (m->bone[j] < 0 && m->follow[j] == 0)
			fallen += r->infl_weight[v][k];
	}
	return all > 0.0f ? fallen / all : 1.0f;
}

void rig_weights_to_skel(const rig_scene *r, const rig_map *m, skin_weights *out, rig_weights_info *info,
			 uint8_t *orphan)
{
	memset(info, 0, sizeof *info);
	out->vert_count = r->mesh->vert_count;
	for (int v = 0; v < r->mesh->vert_count; v++) {
		uint16_t bone[RIG_MAX_INFLUENCES];
		float weight[RIG_MAX_INFLUENCES];
		int n = 0;
		for (int k = 0; k < r->infl_count[v]; k++) {
			int b = m->follow[r->infl_joint[v][k]], i = 0;
			while (i < n && bone[i] != b)
				i++;
			if (i == n) {
				bone[n] = (uint16_t)b;
				weight[n++] = 0.0f;
			}
			weight[i] += r->infl_weight[v][k];
		}
		info->trimmed += n > SKP_MAX_INFLUENCES;
		if (orphan)
			orphan[v] = fallen_share(r, m, v) > 0.999f;
		if (skin_weights_set_largest(out, v, bone, weight, n) <= 0.0f) {
			info->unweighted++;
			out->count[v] = 1;
			out->bone[v][0] = 0;
			out->weight[v][0] = 1.0f;
		}
	}
}
