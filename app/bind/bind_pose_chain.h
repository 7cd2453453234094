/* A limb's chain fitted to the mesh's limb, after bind_pose_guess.h has
 * aimed its bones one at a time: the skeleton's bones should run through
 * the middle of the flesh they move, so the rotation channels of the
 * chosen bones (the collar bone, the upper and lower bones) are turned, a
 * few degrees at a time, while that lowers the mean squared distance from
 * the limb's vertices to the nearest of its bones. The limb's vertices
 * are those nearest, in the starting pose, to one of its bones past the
 * first (a collar bone or a hip joint lies in the torso). Bones keep
 * their lengths, so where the skeleton's proportions differ from the
 * mesh's (a longer collar bone) the fit finds the compromise: a collar
 * bone turned down, an elbow bent further. */
#ifndef BIND_POSE_CHAIN_H
#define BIND_POSE_CHAIN_H

#include "fk.h"
#include "mesh.h"

/* start: the limb's first bone (a collar bone, a hip joint); turn[b]
 * non-zero: bone b's rotation channels may turn. values change in place;
 * pose (left in the result) and vert (m->vert_count entries) are scratch.
 * Returns the number of turns kept (0: the pose was left). */
int bind_guess_chain(const skel *s, const mesh *m, int start, const unsigned char *turn, int end, float *values,
		     skel_pose *pose, int *vert);

#endif
