/* Forward kinematics of an Acclaim skeleton (column vectors):
 *   C = rotation of the bone's axis line, M = the frame's rotations in dof
 *   order (first applied first), G = G_parent * C * M * C^-1,
 *   head = tip_parent + G_parent * offset, tip = head + length * G * direction.
 * Root: position + (TX TY TZ), rotation C_root * R * C_root^-1 with R from
 * the RX RY RZ channels in the `order` sequence.
 *
 * In two steps, so that poses can be blended in between: a frame's values
 * give each bone's local motion (skel_local: C M C^-1, the translation and
 * `l` channels), and the local motion gives the posed skeleton. */
#ifndef FK_H
#define FK_H

#include "skel.h"

typedef struct skel_pose {
	quat rot[SKP_MAX_BONES];     /* G of each bone */
	vec3 head[SKP_MAX_BONES];    /* start of the bone (parent's tip; root: position) */
	vec3 tip[SKP_MAX_BONES];     /* end of the bone (root: position) */
} skel_pose;

/* One frame as each bone's motion relative to its parent: what the
 * playback engine interpolates between captured frames (app/play). */
typedef struct skel_local {
	quat rot[SKP_MAX_BONES];     /* C M C^-1 (root: C R C^-1) */
	vec3 trans[SKP_MAX_BONES];   /* translation channels: the root's in world axes,
	                              * a joint's in its own axis frame */
	float stretch[SKP_MAX_BONES]; /* the `l` channel */
} skel_local;

/* values: one frame as amc_frame.value (radians, length units), or NULL
 * for the rest pose. fk_pose(s, v, p) is fk_local(s, v, l) then
 * fk_from_local(s, l, p), bit for bit. */
void fk_pose(const skel *s, const float *values, skel_pose *out);
void fk_local(const skel *s, const float *values, skel_local *out);
void fk_from_local(const skel *s, const skel_local *l, skel_pose *out);

/* fk_pose's step for bone i alone (out holds its parent's pose already):
 * what the encoder takes again for the bones below a track it changed. */
void fk_pose_bone(const skel *s, int i, const float *values, skel_pose *out);

/* The middle of the bounding box of the first count bones' tips: what the
 * renderer's camera follows, and what image acceptance wants on the body. */
vec3 fk_tip_centre(const skel_pose *pose, int count);

#endif
