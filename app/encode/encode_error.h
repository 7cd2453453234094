/* The error measure of the encoder and of `skintool bench-image`: for
 * every joint (a bone's head, the root's position), the points a shell
 * distance along its three axes, moved by the joint's world rotation and
 * position from forward kinematics (fk_pose, as the players pose), and
 * the largest distance between where decoded values and the source put
 * them; per frame, the largest over the joints. ACL's measure (its
 * "qvvf transform error", default shell 3 cm). */
#ifndef ENCODE_ERROR_H
#define ENCODE_ERROR_H

#include "fk.h"

/* Joint b's error between two poses. */
double encode_joint_error(const skel_pose *ref, const skel_pose *got, int b, double shell);

/* The frame's error between two poses of skeleton s. */
double encode_shell_error(const skel *s, const skel_pose *ref, const skel_pose *got, double shell);

#endif
