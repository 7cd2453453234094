/* What every rig reader (rig_import.c, rig_makehuman.c) fills a scene with. */
#include "rig_scene.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>

void rig_scene_release(rig_scene *r)
{
	free(r->texture_rgba);
	r->texture_rgba = NULL;
	r->texture_w = r->texture_h = 0;
}

void rig_scene_reset(rig_scene *r)
{
	mesh *m = r->mesh;
	rig_scene_release(r);
	memset(r, 0, offsetof(rig_scene, infl_count));
	r->mesh = m;
	r->seams = 0;
	r->texture_path[0] = r->texture_material[0] = '\0';
}

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
