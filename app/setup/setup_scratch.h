/* Start-up scratch for the bound body. The OBJ parser, the choice of its
 * part, the generated body and the weight balancing each need megabytes of
 * work space (obj_work, mesh_pick_work, manq_work, bind_balance_work, all
 * sized by the board's vertex limit; the quality gate's work after them), one
 * after another and never two at once (setup_bind_load), so they share one
 * static area instead of holding five. Only the pointer a step was given
 * is valid, and only until the next step starts. */
#ifndef SETUP_SCRATCH_H
#define SETUP_SCRATCH_H

#include "bind_balance.h"
#include "bind_gate.h"
#include "bind_pose_guess.h"
#include "bind_smooth.h"
#include "runtime_skin.h"
#include "mannequin.h"
#include "obj.h"

/* setup_mesh_pick.c: a mesh's connected parts, and which are closed. */
typedef struct mesh_pick_work {
	int up[SKP_MAX_VERTS];              /* union-find over vertices */
	long tris[SKP_MAX_VERTS], verts[SKP_MAX_VERTS]; /* per root */
	char open[SKP_MAX_VERTS];           /* per root: an edge not shared by exactly two triangles */
	int to[SKP_MAX_VERTS];              /* old vertex -> kept one, -1 */
	uint32_t edge_start[SKP_MAX_VERTS + 1], fill[SKP_MAX_VERTS];
	uint32_t edge_other[3 * SKP_MAX_TRIS]; /* edges bucketed by their smaller vertex */
} mesh_pick_work;

typedef union setup_scratch {
	obj_work obj;
	mesh_pick_work pick;
	manq_work manq;
	bind_balance_work balance;
	bind_guess_work guess;
	bind_smooth_work smooth;
	struct {
		bind_gate_work work;
		runtime_skin skin;
		skel_pose pose;
	} gate;
} setup_scratch;

setup_scratch *setup_scratch_area(void);

#endif
