#include "rig_seam.h"

#include <string.h>

#include "mesh_normals.h"

void rig_seam_normals(const rig_scene *r, mesh *m)
{
	if (!r->seams)
		return;
	/* A twin facing the other way is a sheet's back (a cape's two sides
	 * at one place), not a seam: it keeps its own. A lead precedes its
	 * twins, so its sum is whole before they read it. */
	for (int v = 0; v < m->vert_count; v++) {
		int lead = r->seam_lead[v];
		if (lead != v && vec3_dot(m->normal[lead], m->normal[v]) > 0.0f)
			m->normal[lead] = vec3_add(m->normal[lead], m->normal[v]);
	}
	for (int v = 0; v < m->vert_count; v++) {
		int lead = r->seam_lead[v];
		vec3 n = mesh_unit(m->normal[lead]);
		if (vec3_dot(n, m->normal[v]) > 0.0f)
			m->normal[v] = n;
	}
}

void rig_seam_weights(const rig_scene *r, skin_weights *wt)
{
	if (!r->seams)
		return;
	for (int v = 0; v < wt->vert_count; v++) {
		int lead = r->seam_lead[v];
		if (lead == v)
			continue;
		wt->count[v] = wt->count[lead];
		memcpy(wt->bone[v], wt->bone[lead], sizeof wt->bone[v]);
		memcpy(wt->weight[v], wt->weight[lead], sizeof wt->weight[v]);
	}
}
