/* A texture's seams: vertices the weld kept apart only because their UVs
 * differ (rig_weld.h) are one place of the surface, so they must move and
 * shade as one. Each takes its seam lead's (the first twin's) weights, and
 * all of them the mean of their normals: else the seam would crack when
 * computed weights differ on its two sides, or show as a crease in the
 * light. */
#ifndef RIG_SEAM_H
#define RIG_SEAM_H

#include "rig_scene.h"
#include "skin_weights.h"

/* Every twin's normal (m: r's mesh, as r->seam_lead numbers it) the
 * normalised sum of its group's: after each mesh_compute_normals. */
void rig_seam_normals(const rig_scene *r, mesh *m);

/* Every twin's weights its lead's: after the weights are made or
 * smoothed. */
void rig_seam_weights(const rig_scene *r, skin_weights *wt);

#endif
