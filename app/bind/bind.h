/* Automatic skin weights: the paper's "linear gradient of bone projection
 * direction", on the skeleton posed in its bind pose.
 *
 * For a bone b with head H, tip T (from fk_pose), length L = |T - H| and
 * unit direction d = (T - H) / L, a vertex p has
 *   s = (p - H) . d                 projection on the bone (0 at H, L at T)
 *   r = |p - H - s d|               distance from the bone's line
 *   h = blend * L                   blend half-width
 *   R = min(clamp(radius * L, radius_min * S, radius_max * S), radius_cap * L)
 * where S (skeleton size) is the largest side of the bounding box of all
 * bind-pose joints: short spine bones still reach the flanks (radius_min),
 * long limb bones stay off the next limb (radius_max), and finger and
 * thumb bones do not swallow the hand (radius_cap). The influence box of
 * b is -h <= s <= L + h, r <= R (a box in (s, r): round across the bone,
 * so it does not depend on the bone's roll). Inside it
 *   w_b(p) = clamp(min(g_head, g_tip), 0, 1)
 *   g_head = 0.5 + (p - H) . m_H / (2h)   if another bone meets b at H, else 1
 *   g_tip  = 0.5 + (T - p) . m_T / (2h)   if another bone meets b at T, else 1
 * so w_b is 1 in the middle of the bone, 0.5 at a joint and 0 at h past
 * it: across a joint the two bones' weights cross-fade (they sum to 1 when
 * both have the same h). Outside the box w_b = 0. The bones meeting at a
 * joint are the bone ending there (its nearest ancestor of non-zero length)
 * and every bone starting there; a chain's free ends get no ramp.
 *
 * The ramp direction m is d (the paper's projection on the bone) except
 * where b is the only bone starting at its parent's tip: there m_H of b and
 * m_T of the parent are both the bisector (d_parent + d) / |d_parent + d|,
 * unless the bones fold back by more than about 150 degrees
 * (|d_parent + d| <= 0.5). On a straight joint (knee, elbow) that is d
 * again. On an angled one (the ankle, the CMU hip bone to the thigh) the
 * mid surface of the cross-fade, a plane through the joint, then cuts both
 * limbs alike, like a mitre. Cut square to the child instead, it leaves
 * more flesh on one side of the joint, and DQBS, which turns each
 * cross-section about the joint rigidly, changes the volume in proportion
 * to the bend angle there (measured on the CMU backflip with the generated
 * body: 1.0173 of the bound volume at worst with the mitre, 1.0250 square).
 *
 * Where b's head ramps, the bone ending at H (its nearest non-zero ancestor,
 * the root at the root joint) also gets 1 - g_head, or its own w if that is
 * larger: the cross-fade reaches a short parent (the CMU hip bone) whose
 * box misses the vertex. Only the bone whose segment H-T is nearest to the
 * vertex and the bones meeting it at a joint count: two limbs whose boxes
 * overlap (the thighs at the crotch, arm and chest at the armpit) do not
 * share a vertex.
 *
 * Bones starting where the nearest bone starts and pointing away from it
 * (more than 90 degrees apart: the lower back and a CMU hip bone, the two
 * clavicles) cross-fade across the plane bisecting them, with half-width
 * the mean of their h: the sibling takes min(its head ramp, the
 * cross-fade), the nearest bone at most 1 minus the cross-fade. The
 * nearest-bone test alone cut the skin where the nearest bone changes:
 * the hip bone, pointing sideways, is nearest to the flanks above the
 * waist, and a bent back showed a jagged crease there. Siblings closer
 * than 90 degrees (the hip bones at the crotch) keep the hard cut.
 *
 * Then per vertex: keep the 4 largest w_b, clamp at 0, normalise to sum 1.
 * A vertex with no weight (outside every box) is weighed again with the
 * boxes of the nearest bone n, of the bone ending at n's head and of the
 * bones starting at n's tip grown to 1.1 times the vertex's distance to n
 * (R' = max(R, 1.1 d)); siblings of n stay out (the lower back for a hip
 * vertex). The paper gives such a vertex to the nearest bone alone, which
 * cuts the skin where the nearest bone changes: the flanks of the
 * generated body's trunk lie outside the short spine bones' boxes, and a
 * bent back showed a jagged crease at every spine joint. Still no weight
 * (past a chain's free end): weight 1 to the nearest bone (ties: the lower
 * bone index).
 *
 * Zero-length bones (length <= 1e-6 S), the root among them, get no box and
 * never win the nearest-bone test (the root only takes head-ramp shares): a point has no direction to project on,
 * and the vertices around one are shared by the bones that meet there.
 * Their children's head ramps treat the nearest non-zero ancestor as the
 * parent. If every bone has zero length, every vertex goes to the root.
 *
 * Defaults (bind_default_params), tuned on the CMU skeleton with the
 * MakeHuman body and the generated mannequins: radius = 0.35,
 * radius_min = 0.05, radius_max = 0.10, radius_cap = 1.0, blend = 0.20.
 * Cost: one box test and one segment distance per vertex and bone, about 6 ms for 20000 vertices
 * on 31 bones on a desktop core. */
#ifndef BIND_H
#define BIND_H

#include <stdint.h>

#include "fk.h"
#include "skin_weights.h"
#include "skp_error.h"

typedef struct bind_params {
	float radius;      /* box radius R as a fraction of the bone length ... */
	float radius_min;  /* ... but at least this fraction of the skeleton size */
	float radius_max;  /* ... and at most this fraction of the skeleton size */
	float radius_cap;  /* ... and never more than this fraction of the length */
	float blend;       /* blend half-width h as a fraction of the bone length */
} bind_params;

extern const bind_params bind_default_params;

/* One bone's influence region, in bind-pose space. */
typedef struct bind_segment {
	vec3 head, dir;    /* H and unit d */
	float length;      /* L; 0 for a bone that gets no box */
	float radius;      /* R */
	float half;        /* h */
	vec3 head_n, tip_n; /* directions the head and tip ramps project on */
	uint8_t ramp_head; /* another bone meets this one at H */
	uint8_t ramp_tip;  /* ... at T */
	int16_t parent;    /* takes what the head ramp leaves: the bone ending
			    * at H, or the root (0) at the root joint */
} bind_segment;

typedef struct bind_rig {
	int bone_count;
	int boxed;         /* bones with a box (non-zero length) */
	float size;        /* S */
	bind_segment seg[SKP_MAX_BONES];
	/* bones sharing a joint with bone b (itself included), a bit per bone */
	uint32_t near[SKP_MAX_BONES][(SKP_MAX_BONES + 31) / 32];
	/* bones starting where bone b starts and pointing more than 90 degrees
	 * away from it (they cross-fade across their bisector) */
	uint32_t apart[SKP_MAX_BONES][(SKP_MAX_BONES + 31) / 32];
} bind_rig;

/* What binding saw, beyond the weights themselves. */
typedef struct bind_info {
	int fallback;      /* vertices outside every box (nearest bone) */
	int max_influences;
} bind_info;

/* Sets up the rig of skeleton s posed as pose (fk_pose). p NULL: defaults. */
void bind_prepare(bind_rig *rig, const skel *s, const skel_pose *pose,
		  const bind_params *p);

/* w_b(p) of the formula above; *inside (may be NULL) tells whether p is in
 * the box. */
float bind_segment_weight(const bind_segment *g, vec3 p, int *inside);

/* Distance from p to the segment H-T. */
float bind_segment_distance(const bind_segment *g, vec3 p);
/* Its square (bind_segment_distance is exactly sqrtf of it). */
float bind_segment_distance2(const bind_segment *g, vec3 p);
/* The nearest of the n segments seg[] with a length to p: its index, its
 * distance in *dist; -1 and INFINITY when none has a length (or every
 * distance is NaN). Of two at the same distance, the first. */
int bind_segment_nearest(const bind_segment *seg, int n, vec3 p, float *dist);

/* Weights of n vertices (n <= SKP_MAX_VERTS); info may be NULL. Fails on
 * too many vertices or a non-finite position. */
skp_status bind_weights(const bind_rig *rig, const vec3 *pos, int n,
			skin_weights *out, bind_info *info, skp_error *err);

#endif
