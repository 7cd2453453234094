/* The skeleton given the mesh's proportions. A motion is joint rotations
 * (and a root path), so it plays as well on a skeleton with a longer spine
 * or shorter arms; a mesh whose shoulder sits 5% of the height away from
 * the skeleton's shears there whenever the arm moves. So, after the mesh is
 * on the skeleton (rig_align.h):
 *   1. the mesh is scaled about the skeleton's root so that root-to-ankle
 *      is as long on both (the motion's root height then still puts the
 *      feet on the floor), its hips moved onto the root;
 *   2. along each chain of mapped parts (hips-chest-head, clavicle-upper
 *      arm-forearm-hand, thigh-shin-foot-toe) the skeleton's bones between
 *      two parts are scaled so that the parts are as far apart as on the
 *      mesh;
 *   3. bones without rotation channels from the root to a thigh (CMU's
 *      hip bones) are pointed and sized so the thigh starts where the
 *      mesh's does.
 * Directions of bones with channels stay: rig_pose.h turns them. */
#ifndef RIG_PROPORTIONS_H
#define RIG_PROPORTIONS_H

#include "rig_map.h"

typedef struct rig_proportions {
	float mesh_scale;       /* step 1 */
	int scaled;             /* bone stretches in step 2 */
	float min_ratio, max_ratio;
	int hip_bones;          /* step 3 */
} rig_proportions;

/* pose is s's pose (the rest pose or a given one); it is recomputed with
 * values after the change. */
void rig_fit_proportions(skel *s, const float *values, skel_pose *pose, rig_scene *r, const rig_map *m,
			 rig_proportions *out);

#endif
