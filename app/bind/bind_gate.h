/* The check every bind passes before anything is written: the mesh skinned
 * in test poses (the range of motion of bind_rom.h, and frames of a motion
 * where there is one) against the mesh as bound. Four measures, each per
 * region (a vertex's region is the bone nearest to it in the bind pose):
 *   tears   a triangle edge stretched to more than stretch_ratio times its
 *           bind length and by more than stretch_extent of the skeleton's
 *           extent (the skin between two parts bound to bones that part);
 *   drift   a vertex that moved (in the body's frame) and whose distance to
 *           the posed skeleton (its nearest bone segment) grows past its
 *           distance in the bind pose, and past its distance to its own
 *           bones there (a part far from its bone that keeps to it, as a
 *           robot's head does, leaves nothing), by more than drift of the
 *           extent: a part that leaves its bones; a distance that shrinks
 *           (another limb passing by, a hand on the chest) is contact, not
 *           a failure, and is only reported (closer);
 *   root    vertices bound to the root alone where their region moves (the
 *           share of the region: joints that mapped to nothing; for a
 *           rigged mesh, the vertices whose joints fell back to the root);
 *           this and rigid count a region's vertices past the first
 *           quarter of its bone (the rest is joint skin), unless their
 *           heaviest bone is on another branch and holds them near (a big
 *           head beside an upper arm is not the arm's skin);
 *   rigid   a limb region (arm or leg: a rig with fewer spine joints than
 *           the skeleton, or a robot's one-piece torso, bends the spine
 *           its own way) whose vertices do not follow its bone: when a move
 *           turns the bone, the vertices' displacement along the one the
 *           bone's own transform gives them, summed over the region, over
 *           the same for rigid attachment (1: it follows, 0: it stays).
 * The extent is the largest side of the bind-pose joints' bounding box.
 * Measured on the skinned positions the caller's kernel writes (DQBS: the
 * method shown), so what it checks is what plays. No allocation: the work
 * area is the caller's (megabytes: static). */
#ifndef BIND_GATE_H
#define BIND_GATE_H

#include "bind.h"
#include "bind_rom.h"
#include "mesh.h"

typedef struct bind_gate_limits {
	float stretch_ratio, stretch_extent;
	float drift;
	float root_share;
	float follow_min;
	int region_min;         /* regions of fewer vertices are not judged for root and rigid */
} bind_gate_limits;

extern const bind_gate_limits bind_gate_default_limits;

enum { BIND_GATE_TEARS = 1, BIND_GATE_DRIFT = 2, BIND_GATE_ROOT = 4, BIND_GATE_RIGID = 8 };

/* Where a figure was worst. */
typedef struct bind_gate_worst {
	float value;
	int region;             /* bone; -1: none measured */
	int move;               /* the range-of-motion move, -1: a motion frame */
	long frame;             /* that frame's number (move -1) */
	int vertex;
} bind_gate_worst;

typedef struct bind_gate_result {
	float extent;
	int moves;              /* range-of-motion poses measured */
	long frames;            /* motion frames measured */
	bind_gate_worst stretch;        /* largest edge length over its bind length */
	bind_gate_worst grow;           /* largest edge lengthening / extent */
	int torn_edges;                 /* past both stretch limits */
	int doubled_edges;              /* ever past twice their bind length */
	bind_gate_worst drift;          /* largest growth of the distance to the skeleton / extent */
	bind_gate_worst closer;         /* largest shrinking of it / extent */
	int drifting;                   /* vertices past the drift limit */
	bind_gate_worst root;           /* region with the largest share of root-only moving vertices */
	int root_moving;                /* such vertices in all */
	bind_gate_worst rigid;          /* region following its bone least */
	unsigned failed;                /* BIND_GATE_* */
} bind_gate_result;

typedef struct bind_gate_work {
	const skel *skel;
	bind_gate_limits lim;
	const skel_pose *bind;
	const mesh *mesh;
	float extent;
	bind_segment seg[SKP_MAX_BONES];        /* the current pose's bones with a length */
	int seg_bone[SKP_MAX_BONES], seg_count;
	int16_t region[SKP_MAX_VERTS];
	float bind_dist[SKP_MAX_VERTS];
	float own_dist[SKP_MAX_VERTS];          /* the larger of that and the distance to its own bones */
	uint8_t root_only[SKP_MAX_VERTS];       /* 1: bound to the root alone; 2: ... and seen moving */
	float bind_edge[SKP_MAX_TRIS][3];
	int region_verts[SKP_MAX_BONES];
	uint8_t limb[SKP_MAX_BONES];            /* an arm or leg bone (skel_roles.h) */
	double follow_num[SKP_MAX_BONES], follow_den[SKP_MAX_BONES];
	bind_gate_result res;
	uint8_t drifted[SKP_MAX_VERTS];
	uint8_t inner[SKP_MAX_VERTS];           /* judged with its region (root, rigid) */
	uint8_t torn[SKP_MAX_TRIS];             /* a bit per edge of the triangle: torn, then doubled */
	float xyz[3 * SKP_MAX_VERTS], nrm[3 * SKP_MAX_VERTS];   /* for the caller's kernel */
} bind_gate_work;

/* Sets up the measures for mesh m bound with weights wt to s posed as
 * bind, judged by lim (NULL: the defaults). orphan (NULL: vertices
 * weighted to the root alone) marks the vertices left to the root for
 * want of a mapped joint; held (may be NULL) those of a rigid part held by
 * one joint (a spear by the hand), which the region they lie in (a thigh
 * beside the spear) need not move. */
void bind_gate_start(bind_gate_work *w, const skel *s, const skel_pose *bind, const mesh *m,
		     const skin_weights *wt, const uint8_t *orphan, const uint8_t *held,
		     const bind_gate_limits *lim);

/* One test pose and the mesh skinned in it (xyz per vertex): move is the
 * range-of-motion move it came from (index move_index), or NULL for a
 * motion frame numbered frame. */
void bind_gate_add(bind_gate_work *w, const skel_pose *pose, const float *xyz, const bind_rom_move *move,
		   int move_index, long frame);

/* The figures, and what failed. */
void bind_gate_finish(bind_gate_work *w, bind_gate_result *out);

#endif
