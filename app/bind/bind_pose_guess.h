/* The pose a user's mesh was modelled in, found against the skeleton, so
 * that a mesh in an A-pose binds to a T-posed skeleton (and the other way
 * round) without a hand-made bind-pose file. For each arm, the mesh's
 * vertices well out to that side of the shoulder (past 35% of the arm's
 * length: the arm, not the torso) give the arm's elevation as the median of
 * their elevations seen from the shoulder; the skeleton's upper arm (the
 * first bone about as long as the arm's longest) is then turned to it by
 * its own rotation channels, within the vertical plane through it, when
 * they differ by 8 degrees or more. The mesh must already be the
 * skeleton's size and in its place (bind_fit.h), Y up, facing the same way. */
#ifndef BIND_POSE_GUESS_H
#define BIND_POSE_GUESS_H

#include "fk.h"
#include "mesh.h"

#define BIND_GUESS_MAX_ARMS 8   /* limbs: arms and legs */

typedef struct bind_guess_arm {
	int bone;               /* the limb's upper bone (upper arm, thigh) */
	float from_deg, to_deg; /* its elevation before and after (+ above the horizontal) */
	int lower;              /* the bone after it (forearm, shin), or -1 */
	float lower_turn_deg;   /* how far that was turned, 0: not */
	int ends;               /* bones below it turned (bind_pose_ends.h: hand, thumb, foot, toes) */
} bind_guess_arm;

typedef struct bind_guess_result {
	int arm_count;          /* arms looked at */
	int turned;             /* arms whose pose changed */
	bind_guess_arm arm[BIND_GUESS_MAX_ARMS];
} bind_guess_result;

#define GUESS_MAX_SAMPLES SKP_MAX_VERTS

/* Scratch for bind_guess_pose. */
typedef struct bind_guess_work {
	skel_pose pose;
	union {                 /* one at a time */
		float elevation[GUESS_MAX_SAMPLES];
		int chain_vert[GUESS_MAX_SAMPLES];
	};
} bind_guess_work;

/* values: the starting pose (all 0: the rest pose), changed in place to
 * the guess. */
void bind_guess_pose(const skel *s, const mesh *m, float *values, bind_guess_work *w,
		     bind_guess_result *out);

#endif
