/* What every rig reader (rig_import.c, rig_makehuman.c) fills a scene with. */
#include "rig_scene.h"

#include <string.h>

int rig_find_joint(const rig_scene *r, const char *name)
{
	for (int j = 0; j < r->joint_count; j++)
		if (strcmp(r->joint[j].name, name) == 0)
			return j;
	return -1;
}

void rig_add_influence(rig_scene *r, int v, int joint, float weight)
{
	int n = r->infl_count[v];
	for (int k = 0; k < n; k++)
		if (r->infl_joint[v][k] == joint) {
			r->infl_weight[v][k] += weight;
			return;
		}
	if (n == RIG_MAX_INFLUENCES) {
		r->dropped_influences++;
		return;
	}
	r->infl_joint[v][n] = (uint16_t)joint;
	r->infl_weight[v][n] = weight;
	r->infl_count[v] = (uint8_t)(n + 1);
}
