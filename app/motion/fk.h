/* Forward kinematics of an Acclaim skeleton (column vectors):
 *   C = rotation of the bone's axis line, M = the frame's rotations in dof
 *   order (first applied first), G = G_parent * C * M * C^-1,
 *   head = tip_parent + G_parent * offset, tip = head + length * G * direction.
 * Root: position + (TX TY TZ), rotation C_root * R * C_root^-1 with R from
 * the RX RY RZ channels in the `order` sequence. */
#ifndef FK_H
#define FK_H

#include "skel.h"

typedef struct skel_pose {
	quat rot[SKP_MAX_BONES];     /* G of each bone */
	vec3 head[SKP_MAX_BONES];    /* start of the bone (parent's tip; root: position) */
	vec3 tip[SKP_MAX_BONES];     /* end of the bone (root: position) */
} skel_pose;

/* values: one frame as amc_frame.value (radians, length units), or NULL
 * for the rest pose. */
void fk_pose(const skel *s, const float *values, skel_pose *out);

/* The middle of the bounding box of the first count bones' tips: what the
 * renderer's camera follows, and what image acceptance wants on the body. */
vec3 fk_tip_centre(const skel_pose *pose, int count);

#endif
