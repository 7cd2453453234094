/* Putting a rigged mesh on the skeleton by its joints: the rotation, the
 * uniform scale and the translation that best carry the mesh's joints onto
 * the skeleton's matching ones (least squares: Horn's closed form, a unit
 * quaternion from the largest eigenvector of a 4x4 matrix). Files differ
 * in which way is up and which way the body faces (glTF is Y up facing
 * +Z, an FBX from Blender Z up, a Blender glTF may turn its armature), so
 * the rotation is found, not assumed; when it is within 20 degrees of a
 * quarter-turn combination it is snapped to it, since posture differences
 * (a slight stoop, legs apart) should not tilt the body. */
#ifndef RIG_ALIGN_H
#define RIG_ALIGN_H

#include "quat.h"
#include "skp_error.h"

typedef struct rig_align {
	quat rot;
	float scale;            /* x' = scale * rot(x) + offset */
	vec3 offset;
	int snapped;            /* rot is an axis-aligned turn */
	float snap_deg;         /* how far the least-squares rotation was from it */
	float turn_deg;         /* angle of rot */
	float rms;              /* residual distance over the pairs, after */
} rig_align;

/* Fits to[i] ~ scale * rot(from[i]) + offset over n >= 3 pairs. Fails
 * when the points are all on a line or of no extent. */
skp_status rig_align_fit(const vec3 *from, const vec3 *to, int n, rig_align *out, skp_error *err);

vec3 rig_align_point(const rig_align *a, vec3 p);

#endif
