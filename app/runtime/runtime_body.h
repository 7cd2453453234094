/* The bound body: the runtime's central struct, filled once at start-up
 * (app/setup from a mesh and weights, or show_source.c from a packed show)
 * and read by every frame after. */
#ifndef RUNTIME_BODY_H
#define RUNTIME_BODY_H

#include "bind.h"
#include "bind_balance.h"
#include "bind_fit.h"
#include "bind_gate.h"
#include "bind_pose_guess.h"
#include "mesh.h"
#include "tex_image.h"
#include "skel.h"

/* A skeleton, a mesh bound to it and the weights: what start-up binding
 * (app/setup: setup_bind_load) or a packed show (show_source.h) gives the
 * frame path. Tens of MB: keep it static. */
typedef struct bound_body {
	skel skel;
	skel_pose pose;             /* the bind pose */
	long pose_frame;            /* frame bound in, -1 for the rest pose or a derived one */
	float pose_value[SKP_MAX_DOF]; /* its channel values (all 0 for the rest pose) */
	int arms_raised;            /* > 0: derived from the rest pose by skel_tpose */
	bind_guess_result guess;    /* .turned > 0: the mesh's own pose (bind_pose_guess.h) */
	mesh mesh;                  /* fitted when --fit */
	tex_image texture;          /* mesh.textured: its base colour texture */
	int texture_skipped;        /* the image's texture was larger than the board keeps */
	int fitted;
	bind_fit_result fit;
	bind_rig rig;
	skin_weights weights;
	int automatic;              /* 1: computed (info, bind_ns valid), 0: --weights */
	int rigged;                 /* the mesh has weights of its own that map onto the
				     * skeleton (the importer): --weights mesh can use them */
	bind_info info;
	bind_balance_info balance;  /* valid when automatic and balanced */
	int balanced;
	int smooth_passes;          /* computed weights smoothed over the surface (bind_smooth.h) */
	unsigned long long bind_ns; /* time bind_prepare + bind_weights (+ bind_balance) took */
	uint8_t orphan[SKP_MAX_VERTS]; /* with has_orphans: vertices left to the root for want of a
					* mapped joint (the importer's, --weights mesh) */
	int has_orphans;
	uint8_t held[SKP_MAX_VERTS];   /* with has_held: vertices of a rigid part held by one joint (a
					* spear beside the armature, by the hand), not judged with the
					* body's region they lie in */
	int has_held;
	bind_rom rom;               /* the gate's range of motion */
	bind_gate_result gate;      /* and its figures (setup_gate.h) */
} bound_body;

/* The bind pose's values, or NULL when it is the rest pose. */
const float *bound_pose_values(const bound_body *body);

#endif
