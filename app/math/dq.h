/* Unit dual quaternions for dual quaternion blend skinning (Kavan, Collins,
 * Zara, O'Sullivan 2008). A rigid transform "rotate by q, then translate by
 * t" is real = q, dual = 0.5 * t * q with t the pure quaternion (0, t).
 * Products follow quat.h: dq_mul(a, b) applies b first, then a. */
#ifndef DQ_H
#define DQ_H

#include <stdint.h>

#include "quat.h"
#include "rigid.h"
#include "vec3.h"

typedef struct dq {
	quat real, dual;
} dq;

dq dq_identity(void);
dq dq_from_quat_trans(quat q, vec3 t);
dq dq_from_rigid(const rigid *m);
/* Expects a unit dq (see dq_normalize). */
rigid dq_to_rigid(const dq *d);
/* Translation 2 * dual * conj(real) of a unit dq. */
vec3 dq_translation(const dq *d);
dq dq_mul(const dq *a, const dq *b);
/* Divides both parts by |real| and removes the component of dual along real,
 * so the result satisfies both unit constraints: |real| = 1, real . dual = 0. */
dq dq_normalize(dq d);
/* Both expect |real| = 1; real . dual need not be 0 (the formula ignores it). */
vec3 dq_transform_point(const dq *d, vec3 p);
vec3 dq_transform_normal(const dq *d, vec3 n);

/* Real part of the influence with the largest weight: the pivot that keeps
 * a vertex's blend on one hemisphere (first one wins a tie). */
quat dq_blend_pivot(const dq *bone_dqs, const uint16_t *bone_idx,
		    const float *weights, int count);
/* Sum of weights[i] * bone_dqs[bone_idx[i]], each influence negated when its
 * real part lies on the other hemisphere from pivot (shortest path). Not
 * normalised: this is the raw DLB sum. */
dq dq_blend(const dq *bone_dqs, const uint16_t *bone_idx, const float *weights,
	    int count, quat pivot);
/* dq_blend divided by the norm of its real part: one reciprocal square root
 * per vertex. Ready for dq_transform_point/normal. Identity if the real part
 * vanishes (only possible with a pivot that is not one of the influences). */
dq dq_blend_normalized(const dq *bone_dqs, const uint16_t *bone_idx,
		       const float *weights, int count, quat pivot);

#endif
