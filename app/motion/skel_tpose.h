/* A bind pose with the arms out. A generated body wraps every bone in
 * flesh, so arms that hang at the sides in the rest pose (BVH exports
 * often rest that way, ASF skeletons rest in a T) would grow into the
 * torso and tear it when they move. */
#ifndef SKEL_TPOSE_H
#define SKEL_TPOSE_H

#include "fk.h"
#include "skel.h"

/* Fills values (dof_count of them, as amc_frame.value) with a pose in
 * which each arm's first bone that points more than 30 degrees below the
 * horizontal is turned, by its own rotation channels, to point straight
 * out sideways; the rest of the arm follows it. work is scratch. Returns
 * how many arms it raised: 0 leaves every value 0, the rest pose. */
int skel_tpose(const skel *s, float *values, skel_pose *work);

/* Turns bone by its own rotation channels (changing only those values)
 * until it points along target, as near as its channels allow; work
 * holds the resulting pose. Returns the cosine of the angle left. */
float skel_aim(const skel *s, int bone, vec3 target, float *values, skel_pose *work);

#endif
