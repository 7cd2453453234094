#include "rig_weights.h"

#include <string.h>

void rig_weights_to_skel(const rig_scene *r, const rig_map *m, skin_weights *out, rig_weights_info *info)
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
		if (skin_weights_set_largest(out, v, bone, weight, n) <= 0.0f) {
			info->unweighted++;
			out->count[v] = 1;
			out->bone[v][0] = 0;
			out->weight[v][0] = 1.0f;
		}
	}
}
