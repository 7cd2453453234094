/* Putting a mesh on a skeleton before binding: uniform scale and a
 * translation (no rotation: both must already be Y up and face the same
 * way), so that the body's size and place match the bind-pose joints. */
#ifndef BIND_FIT_H
#define BIND_FIT_H

#include "fk.h"
#include "skp_error.h"

typedef struct bind_fit_result {
	float scale;          /* applied first, about the origin */
	vec3 offset;          /* then added */
	float skel_height;    /* Y extent of the bind-pose joints */
	float mesh_height;    /* Y extent of the mesh before fitting */
} bind_fit_result;

/* Y extent of every joint (head and tip) of the pose: head tip to lowest
 * toe on a standing body. *min_y (may be NULL) gets the lowest joint. */
float bind_fit_skel_height(const skel *s, const skel_pose *pose, float *min_y);

/* Scales pos[0..n) so its Y extent equals the skeleton's, puts its lowest
 * point on the lowest joint, and moves it in X and Z so that the torso's
 * centre at the root's height lies on the root: the XZ centre of the
 * bounding box of the vertices with |y - root y| <= BIND_FIT_SLICE * height
 * and |x - mesh centre x| <= BIND_FIT_TORSO * height (the pelvis, on a
 * standing body; the whole box would be pulled forward by hands and feet,
 * and a slice of full width catches hands hanging at that height). Falls
 * back to the full-width slice, then the whole box, when that is empty.
 * Normals stay valid (uniform positive scale). Fails on an empty or flat
 * mesh or a flat skeleton. */
skp_status bind_fit(vec3 *pos, int n, const skel *s, const skel_pose *pose,
		    bind_fit_result *out, skp_error *err);

/* bind_fit in two steps: what it would do (pos untouched; out required),
 * then doing it. */
skp_status bind_fit_measure(const vec3 *pos, int n, const skel *s, const skel_pose *pose,
			    bind_fit_result *out, skp_error *err);
void bind_fit_apply(vec3 *pos, int n, const bind_fit_result *fit);

/* Half-thickness and half-width of that slice, fractions of the height. */
#define BIND_FIT_SLICE 0.03f
#define BIND_FIT_TORSO 0.10f

#endif
