/* Where a limb is narrowest past its lower bone's middle: a wrist, an
 * ankle. The limb's flesh thins from the elbow (knee) to the wrist
 * (ankle) and widens again into the hand (foot), so the centre of the
 * thinnest cross-section marks the joint where the lower bone ends,
 * whatever the skeleton's proportions; bind_pose_chain.h pulls the lower
 * bone's end to it. */
#ifndef BIND_POSE_NARROW_H
#define BIND_POSE_NARROW_H

#include "fk.h"
#include "mesh.h"

/* Bone l's cross-sections from 50% to 130% of its length, across its
 * axis in pose p: *at gets the centroid of the one whose vertices spread
 * least around their centroid. Returns 0 when there is none (too few
 * vertices, the thinnest at either end of the range). */
int bind_guess_narrowest(const mesh *m, const skel_pose *p, int l, vec3 *at);

#endif
