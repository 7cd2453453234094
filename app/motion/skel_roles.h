/* What each bone of a posed skeleton is for. Bone names differ between
 * exporters (endorphin's "RightHipJoint" is the thigh, CMU's "rhipjoint"
 * the pelvis, a BVH's "LHipJoint" has no length at all), so roles come
 * from the joint positions only: the bone with the highest tip is the head
 * and its ancestors the spine; every other branch off the spine is a leg
 * when it reaches the lowest quarter of the body, an arm otherwise. */
#ifndef SKEL_ROLES_H
#define SKEL_ROLES_H

#include <stdint.h>

#include "fk.h"
#include "skel.h"

typedef struct skel_roles {
	float ymin, ymax;
	float H;                        /* height; half the largest extent for a skeleton lying flat */
	int head_bone;
	vec3 up, side, depth;           /* the body faces along its thinnest horizontal axis */
	uint8_t spine[SKP_MAX_BONES];   /* the head bone and its ancestors */
	uint8_t leg[SKP_MAX_BONES];     /* non-spine bone in a leg branch */
	uint8_t arm[SKP_MAX_BONES];     /* non-spine bone in an arm branch */
	float reach[SKP_MAX_BONES];     /* longest path from the bone's tip to a leaf's tip (root: 0) */
} skel_roles;

/* Needs a skeleton of at least two bones with finite joints. */
void skel_find_roles(const skel *s, const skel_pose *p, skel_roles *out);

/* 1 when the skeleton has two leg branches and two arm branches or more:
 * a human's (a test arm, a robot arm has none). */
int skel_roles_biped(const skel *s, const skel_roles *r);

/* The first bone of b's branch: the one whose parent is on the spine. */
int skel_branch_start(const skel *s, const skel_roles *r, int b);

#endif
