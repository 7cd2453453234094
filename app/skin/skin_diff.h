/* Where two skinned bodies part, and where one has left its shape: per
 * vertex how far LBS lies from DQBS, or how far the skin has moved
 * towards or away from its bone since the bind pose (flesh lost or
 * gained), and per joint the largest of those: the close-up's choice on
 * the kiosk (app/render) and in the report (skintool compare) alike.
 *
 * A vertex belongs to the joint nearest to it as bound (a joint being a
 * bone's head, named by skel_joints.h); its bone is the one carrying most
 * of its weight. No allocation: the caller owns the struct (static). */
#ifndef SKIN_DIFF_H
#define SKIN_DIFF_H

#include <stdint.h>

#include "skel_joints.h"
#include "skin.h"

typedef struct skin_diff {
	int count, bone_count;
	const skel_joints *joints;       /* as given to skin_diff_init (kept; NULL: none) */
	uint8_t joint[SKP_MAX_VERTS];    /* the joint nearest each vertex as bound */
	uint8_t bone[SKP_MAX_VERTS];     /* its heaviest bone (SKP_MAX_BONES: none) */
	float radius[SKP_MAX_VERTS];     /* its distance to that bone as bound */
	float score[SKP_MAX_BONES];      /* the last measure's largest per joint (units) */
} skin_diff;

/* Sorts the vertices of soa (bound in pose bind) to their joints and
 * bones. joints (s's, found in bind; NULL when unknown) must outlive d:
 * the focus asks which joints are elbows and knees. */
void skin_diff_init(skin_diff *d, const skel *s, const skel_pose *bind, const skel_joints *joints,
		    const skin_soa *soa);

/* How far each vertex of a (xyz triples) lies from b's: into dist when
 * not NULL, the largest per joint into d->score. Returns the largest. */
float skin_diff_between(skin_diff *d, const float *a, const float *b, float *dist);

/* How far each vertex of pos (skinned in pose) has moved from its bone
 * since the bind pose, signed (negative: nearer, the flesh thinner): into
 * dist when not NULL, the largest magnitude per joint into d->score.
 * Returns the largest magnitude. */
float skin_diff_from_bind(skin_diff *d, const skel_pose *pose, const float *pos, float *dist);

/* An elbow or knee is folded when its two bones are bent past a right
 * angle: the inside of the fold, where LBS's crease collapses, then lies
 * hidden between the two bones' flesh, and the fold's point outside it
 * is what the close-up can show. */
#define SKIN_FOLD_COS 0.0f
/* The outside counts alone when it holds at least this share of the
 * joint's squared parting: else it barely parts, and showing it would
 * show nothing. */
#define SKIN_FOLD_SHARE_MIN 0.01

/* From the head of a joint whose bone points along axis, its parent's
 * along parent, towards the outside of the fold they make (unit); zero
 * when they are not bent past SKIN_FOLD_COS. */
vec3 skin_fold_outside(vec3 axis, vec3 parent);

/* Where on a joint the close-up looks, and which of its vertices that
 * choice counts. */
typedef struct skin_focus {
	int found;      /* 0: the joint's vertices do not part at all */
	vec3 at;        /* where they part (not found: the joint's head) */
	float reach;    /* how far round it */
	vec3 head;      /* a folded elbow's or knee's head */
	vec3 outward;   /* and the way out of its fold: the vertices beyond
			 * the plane through head square to it count; zero:
			 * every vertex of the joint */
} skin_focus;

/* Where joint's vertices of a (xyz triples, skinned in pose) lie furthest
 * from b's: their midpoints' centroid weighted by the squared distance,
 * so the close-up centres on the change, not on the joint's head (a
 * shoulder's differ at the armpit), and how far round it they part, their
 * root-mean-squared distance from it with the same weights, which the
 * close-up frames. Of a folded elbow or knee of a human's skeleton only
 * the vertices on the outside of the fold count (SKIN_FOLD_SHARE_MIN):
 * the inside is hidden, and the centroid of both would lie within the
 * limb, between a curled elbow's crease and its point. One pass; not found
 * for a joint out of range. */
skin_focus skin_diff_focus(const skin_diff *d, const skel_pose *pose, const float *a, const float *b, int joint);

/* Whether vertex v of a and b lies where f counts (on f's side of a
 * fold; which joint it belongs to is the caller's to check). */
int skin_focus_counts(const skin_focus *f, const float *a, const float *b, int v);

/* The joint of the largest score (-1 when every score is 0). */
int skin_diff_worst(const skin_diff *d);

#endif
