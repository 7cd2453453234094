/* Volume-balanced weights: a pass after bind_weights that moves weight
 * across each joint's cross-fade so that bending the joint does not, to
 * first order, change the volume that dual quaternion skinning encloses.
 *
 * Why. DQBS turns a vertex with weight t on the bones past joint j (j's
 * subtree) about the joint centre c by t times the joint's rotation. For a
 * small rotation theta about a unit axis u the enclosed volume changes by
 *   dV = theta u . M,   M = sum_v t_v (p_v - c) x dV/dp_v
 * where dV/dp_v is the volume's gradient at vertex v (the mesh's area
 * weighted normal, over 3). M is zero where the flesh the cross-fade cuts
 * is centred on the joint; the generated body's hips (the CMU hip joint
 * lies in front of the pelvis), ankles, waist and shoulders are not, and
 * there DQBS gained or lost volume in proportion to the bend angle (a thigh
 * bent 90 degrees: +0.5% of the body).
 *
 * What. For each joint with rotation channels whose |M| would move the
 * volume by at least BIND_BALANCE_MIN_MOMENT of it per 30 degrees, find the
 * smoothest change dt of the subtree shares that makes M zero:
 *   minimise  sum over mesh edges (dt_a - dt_b)^2 + eps sum dt^2
 *   subject to M + sum_v dt_v (p_v - c) x dV/dp_v = 0,  0 <= t_v + dt_v <= 1
 * over the vertices of the cross-fade (0 < t < 1) and a few rings of mesh
 * neighbours around it, dt = 0 beyond; of those, only vertices whose
 * largest weight is on the joint's own bone or outside its subtree (the
 * upper arm, beyond a clavicle's joint, would otherwise take weight of the
 * chest and lag when the arm moves). The minimiser is a sum of three
 * harmonic-like fields, (L + eps I)^-1 applied to each component of
 * (p - c) x dV/dp (conjugate gradients), weighted to meet the constraint;
 * vertices pushed past 0 or 1 are clamped there and the rest solved again.
 * While the largest change exceeds BIND_BALANCE_AIM the region grows by
 * two rings (up to BIND_BALANCE_MAX_RINGS): a wider region needs a smaller
 * change. If it still exceeds BIND_BALANCE_MAX_CHANGE the change is scaled
 * down to it and the joint balanced in part: more would move skin visibly,
 * and a joint left as bound while its mirror image is balanced (the two
 * sides of a body are never quite alike) would make a lopsided body. The
 * side that loses share keeps its bones' proportions; what the other side
 * gains goes to the joint's own bone or its parent; then the 4 largest are
 * kept and normalised.
 *
 * The pass depends only on the bind pose and the mesh, never on a clip.
 * Measured with the generated body: DQBS's worst volume deviation per clip
 * 0.33-1.76% -> 0.23-0.96% on the eight CMU clips (backflip 1.76 -> 0.96),
 * 3.64 -> 0.58% on the endorphin walk; about 0.6 s for 11700 vertices. On
 * the MakeHuman A-pose the hip moments are fifteen times larger, and the
 * regions they need reach the knee and across the back (max radius
 * ratio 10.1 -> 12.1 on 02_01), so the tools balance the generated body by
 * default and a mesh of your own only when asked. */
#ifndef BIND_BALANCE_H
#define BIND_BALANCE_H

#include <stdint.h>

#include "fk.h"
#include "skel.h"
#include "skin_weights.h"
#include "skp_error.h"

#define BIND_BALANCE_MIN_MOMENT 0.0005  /* of the volume, per 30 degrees */
#define BIND_BALANCE_AIM        0.25    /* grow the region until the change is this small */
#define BIND_BALANCE_MAX_CHANGE 0.4     /* largest change of a share ever applied */
#define BIND_BALANCE_MAX_RINGS  16

typedef enum bind_balance_outcome {
	BIND_BALANCE_NONE = 0,   /* no rotation channel, or no cross-fade */
	BIND_BALANCE_NEEDLESS,   /* moment below BIND_BALANCE_MIN_MOMENT */
	BIND_BALANCE_DONE,
	BIND_BALANCE_PARTLY      /* change capped at BIND_BALANCE_MAX_CHANGE */
} bind_balance_outcome;

/* Per bone (the joint at its head). */
typedef struct bind_balance_info {
	uint8_t outcome[SKP_MAX_BONES];   /* bind_balance_outcome */
	float moment[SKP_MAX_BONES];      /* |M| before, as a fraction of the volume per 30 degrees */
	float moment_after[SKP_MAX_BONES];
	float change[SKP_MAX_BONES];      /* largest |dt| applied */
	uint8_t rings[SKP_MAX_BONES];     /* rings of neighbours around the cross-fade */
	double volume;                    /* signed volume of the bind-pose mesh */
} bind_balance_info;

/* Scratch space, caller-provided (about 11 MB at the host's limits). */
typedef struct bind_balance_work {
	uint32_t adj_start[SKP_MAX_VERTS + 1];
	uint32_t adj[SKP_MAX_TRIS * 6];   /* neighbours, an edge once per triangle */
	double grad[SKP_MAX_VERTS][3];    /* dV/dp */
	double arm[SKP_MAX_VERTS][3];     /* (p - c) x dV/dp for the current joint */
	float share[SKP_MAX_VERTS];       /* t: weight on the joint's subtree */
	uint8_t reachable[SKP_MAX_VERTS]; /* mostly on the joint's bone or outside its subtree */
	int32_t slot[SKP_MAX_VERTS];      /* index in band, or -1 */
	uint32_t band[SKP_MAX_VERTS];     /* cross-fade and rings */
	double change[SKP_MAX_VERTS];     /* dt, by slot */
	uint8_t clamped[SKP_MAX_VERTS];   /* by slot */
	double psi[3][SKP_MAX_VERTS];     /* by slot */
	double cg_r[SKP_MAX_VERTS], cg_p[SKP_MAX_VERTS], cg_kp[SKP_MAX_VERTS];
	uint8_t subtree[SKP_MAX_BONES];
} bind_balance_work;

/* Balances w (bound to the n vertices pos and the triangles tri in the
 * bind pose `pose` of s) in place. info may be NULL. Fails on a triangle
 * index out of range or a weight on a bone s does not have. */
skp_status bind_balance(const skel *s, const skel_pose *pose, const vec3 *pos, int n,
			const uint32_t (*tri)[3], int tri_count, skin_weights *w,
			bind_balance_work *work, bind_balance_info *info, skp_error *err);

/* Told after each joint: done of total (a front end draws progress; a
 * large mesh takes seconds). */
typedef struct bind_progress {
	void (*step)(void *ctx, int done, int total);
	void *ctx;
} bind_progress;

/* bind_balance, calling progress (may be NULL) after each joint. */
skp_status bind_balance_watched(const skel *s, const skel_pose *pose, const vec3 *pos, int n,
				const uint32_t (*tri)[3], int tri_count, skin_weights *w,
				bind_balance_work *work, bind_balance_info *info,
				const bind_progress *progress, skp_error *err);

#endif
