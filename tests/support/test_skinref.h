/* The kernel side of test_skin_reference and test_skin_reference_tool: the
 * generated body of CMU subject 02, bound as skintool binds it, and the
 * kernels skin_run picks run on a pose, the portable kernels and the
 * compact streams alongside. The buffers (tens of megabytes) and the body
 * are the caller's: every test program links this file. */
#ifndef TEST_SKINREF_H
#define TEST_SKINREF_H

#include <stdint.h>

#include "bind.h"
#include "mannequin.h"
#include "skin.h"
#include "skin_compact.h"

/* CMU subject 02 (02.asf), its rest pose, generated body and weights. */
typedef struct skinref_cmu02 {
	skel skel;
	skel_pose rest;
	mesh body;
	skin_weights w;
	int have;            /* all of them built */
	manq_work work;
	bind_rig rig;
} skinref_cmu02;

/* cmocka group setup of c: 0, with c->have 0 when the shared data is not
 * there; -1 when the body or its weights cannot be built. */
int skinref_cmu02_setup(skinref_cmu02 *c);
/* Only the skeleton and its rest pose (c->have stays 0): -1 when the
 * shared data is not there. */
int skinref_cmu02_skel(skinref_cmu02 *c);

typedef struct skinref_kernels {
	_Alignas(SKIN_ALIGN) unsigned char block[SKIN_SOA_BYTES(SKP_MAX_VERTS)];
	skin_soa soa;
	_Alignas(SKIN_ALIGN) unsigned char compact_block[SKIN_COMPACT_BYTES(SKP_MAX_VERTS)];
	skin_compact compact;
	_Alignas(SKIN_ALIGN) int16_t nrm16[3 * SKP_MAX_VERTS];
	skin_bones bones;
	_Alignas(SKIN_ALIGN) float pos[SKIN_ALGO_COUNT][3 * SKP_MAX_VERTS];
	_Alignas(SKIN_ALIGN) float nrm[SKIN_ALGO_COUNT][3 * SKP_MAX_VERTS];
	_Alignas(SKIN_ALIGN) int32_t fpos[3 * SKP_MAX_VERTS];
	_Alignas(SKIN_ALIGN) int32_t fnrm[3 * SKP_MAX_VERTS];
	/* the portable kernels' results, for the SIMD ones to match */
	_Alignas(SKIN_ALIGN) float spos[3 * SKP_MAX_VERTS];
	_Alignas(SKIN_ALIGN) float snrm[3 * SKP_MAX_VERTS];
	_Alignas(SKIN_ALIGN) int32_t sfpos[3 * SKP_MAX_VERTS];
	_Alignas(SKIN_ALIGN) int32_t sfnrm[3 * SKP_MAX_VERTS];
} skinref_kernels;

typedef struct skinref_body {
	const skel *skel;
	const skel_pose *bind;
	const mesh *mesh;
	const skin_weights *w;
	double height;
	double pos_err[SKIN_ALGO_COUNT], nrm_err[SKIN_ALGO_COUNT]; /* largest so far */
	double simd_err[SKIN_ALGO_COUNT]; /* against the portable kernel: float units, fixed LSB */
	double compact_err[2], compact_nrm_err[2]; /* compact LBS, DQBS against the float streams' */
	int lbs_collapses;   /* poses where LBS squeezes the skin to a line: its normals are noise there */
	long poses;
} skinref_body;

void skinref_d3(vec3 v, double o[3]);
/* The distance between k[0..2] and r. */
double skinref_err3(const float *k, const double r[3]);
/* The mesh's extent in y. */
double skinref_height_of(const mesh *m);

/* Every algorithm through skin_run on the first n vertices of k->soa into
 * k->pos, k->nrm (fixed point also in k->fpos, k->fnrm, and as floats in
 * pos and nrm); the portable kernels against them into b->simd_err, and,
 * when b has a mesh, the compact streams (k->compact) into
 * b->compact_err. */
void skinref_run_kernels(skinref_kernels *k, skinref_body *b, const skel_pose *pose, int n);

#endif
