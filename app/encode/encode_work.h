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
	skel_pose *got;         /* n decoded poses, as the last measure left them */
	float *dec;             /* n x dofs decoded values */
	int32_t *q;             /* n x dofs grid values */
	codec_track track[SKP_MAX_DOF];
	double *err;            /* n: each frame's shell error */
	double *tbuf;           /* SKEL_MAX_CHANNELS x n: one bone's targets */
	double shell;
	uint8_t bone_of[SKP_MAX_DOF]; /* the bone a track moves */
	struct enc_snap {       /* a subtree's state before a trial (enc_snap_save) */
		int top;
		double *gdec, *pdec;    /* n x count x 9, x 6 */
		struct enc_snap_joint { quat rot; vec3 head, tip; } *got; /* n x count */
	} snap;
} enc_work;

/* Is bone a bone d or one of its ancestors? A track of bone a changes
 * the quantised values and the poses of those bones d only. */
static inline int enc_above(const skel *s, int a, int d)
{
	for (; d >= 0; d = s->bone[d].parent)
		if (d == a)
			return 1;
	return 0;
}

/* The snapshot's buffers, sized as the work's; 0 or -1 (out of memory). */
int enc_snap_alloc(enc_work *w);
void enc_snap_free(enc_work *w);

/* Keeps what a trial of bone top's tracks changes and a later trial
 * reads (the decoded rotations, places and poses of top and the bones
 * below it: the parents of a later trial's bones), so that a refused step
 * is taken back by enc_snap_restore instead of a second trial. Their
 * values, grid values and tracks (q, dec, track) and the frames' errors
 * are left as the refused trial made them: a trial quantises its own
 * bones before it reads them, and the encoder's last trial every bone. */
void enc_snap_save(enc_work *w, int top);
void enc_snap_restore(enc_work *w);

/* Quantises the tracks of bone top and the bones below it with their
 * steps, bone by bone (parents first), the compensated bones' angles
 * chosen against their decoded parents (encode_compensate.c): fills q, dec,
 * gdec, pdec and track (top 0: every bone). 0, or -1 when a track needs
 * more than CODEC_MAX_BITS. */
int enc_quantise(enc_work *w, int top);

/* World rotations of the source frames (gsrc), and which bones compensate. */
void enc_comp_prepare(enc_work *w);

/* The decoded poses (got) of bone top and the bones below it, and their
 * worst shell error against ref; with top 0 each frame's error goes to
 * err. It stops at the first frame past limit (HUGE_VAL: every frame). */
double enc_measure(enc_work *w, int top, double limit);

#endif
