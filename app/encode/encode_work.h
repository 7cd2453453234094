/* The encoder's working state (private to app/encode): the source frames,
 * each track's step, and what quantising with those steps gives. */
#ifndef ENCODE_WORK_H
#define ENCODE_WORK_H

#include <stddef.h>

#include "codec_format.h"
#include "fk.h"

typedef struct enc_work {
	const skel *s;
	const float *src;       /* n x dofs source values */
	long n;
	int dofs;
	float step[SKP_MAX_DOF];
	uint8_t comp[SKP_MAX_BONES];  /* 1: the bone's three angles take up its parent's rounding */
	double *gsrc;           /* n x count x 9: source world rotations */
	double *gdec;           /* n x count x 9: decoded world rotations */
	double *psrc, *pdec;    /* n x count x 6: source and decoded heads and tips */
	skel_pose *ref;         /* n source poses (fk_pose) */
	float *dec;             /* n x dofs decoded values */
	int32_t *q;             /* n x dofs grid values */
	codec_track track[SKP_MAX_DOF];
	double *err;            /* n: each frame's shell error */
	double *tbuf;           /* SKEL_MAX_CHANNELS x n: one bone's targets */
	double shell;
} enc_work;

/* Quantises every track with its step, bone by bone (parents first), the
 * compensated bones' angles chosen against their decoded parents
 * (encode_comp.c): fills q, dec, gdec and track. 0, or -1 when a track
 * needs more than CODEC_MAX_BITS. */
int enc_quantise(enc_work *w);

/* World rotations of the source frames (gsrc), and which bones compensate. */
void enc_comp_prepare(enc_work *w);

/* Each frame's shell error of dec against ref into err; the worst. It
 * stops at the first frame past limit (HUGE_VAL: every frame). */
double enc_measure(enc_work *w, double limit);

#endif
