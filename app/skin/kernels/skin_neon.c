/* NEON kernels (AArch64, e.g. the Raspberry Pi 4's Cortex-A72): the AVX2
 * kernels' method on 4 lanes, two steps per SKIN_LANES block. NEON has no
 * gather, so each step loads the 4 vertices' bone rows and transposes them
 * (4x4 at a time) into lanes. Built when the board sets SIMD=neon; results
 * match skin_scalar.c to float rounding (FMA). The fixed-point kernel is
 * skin_fixed_neon.c. */
#include "skin_kernels.h"

#if defined(SKP_SIMD_NEON) && defined(__aarch64__)

#include <arm_neon.h>
#include <string.h>

#define NEON_LANES 4

typedef struct v3x4 {
	float32x4_t x, y, z;
} v3x4;

static v3x4 load3(const float *x, const float *y, const float *z, int v)
{
	v3x4 r = { vld1q_f32(x + v), vld1q_f32(y + v), vld1q_f32(z + v) };
	return r;
}

/* r[j] = 4 values of vertex j  ->  r[c] = value c of the 4 vertices */
static void transpose4(float32x4_t r[4])
{
	float32x4_t t0 = vtrn1q_f32(r[0], r[1]), t1 = vtrn2q_f32(r[0], r[1]);
	float32x4_t t2 = vtrn1q_f32(r[2], r[3]), t3 = vtrn2q_f32(r[2], r[3]);
	r[0] = vreinterpretq_f32_f64(vtrn1q_f64(vreinterpretq_f64_f32(t0), vreinterpretq_f64_f32(t2)));
	r[1] = vreinterpretq_f32_f64(vtrn1q_f64(vreinterpretq_f64_f32(t1), vreinterpretq_f64_f32(t3)));
	r[2] = vreinterpretq_f32_f64(vtrn2q_f64(vreinterpretq_f64_f32(t0), vreinterpretq_f64_f32(t2)));
	r[3] = vreinterpretq_f32_f64(vtrn2q_f64(vreinterpretq_f64_f32(t1), vreinterpretq_f64_f32(t3)));
}

/* Four consecutive floats at offset `at` of each vertex's bone row, in lanes. */
static void gather4x4(const float *base, int stride, const uint16_t *bone, int v, int at,
		      float32x4_t out[4])
{
	for (int j = 0; j < NEON_LANES; j++)
		out[j] = vld1q_f32(base + (size_t)bone[v + j] * (size_t)stride + at);
	transpose4(out);
}

/* The first `valid` of 4 xyz triples, interleaved, at dst. */
static void store_xyz4(float *dst, v3x4 a, int valid)
{
	float32x4x3_t t = { { a.x, a.y, a.z } };
	if (valid == NEON_LANES) {
		vst3q_f32(dst, t);
		return;
	}
	float tmp[3 * NEON_LANES];
	vst3q_f32(tmp, t);
	memcpy(dst, tmp, sizeof(float) * 3 * (size_t)valid);
}

static v3x4 normalize4(v3x4 a)
{
	float32x4_t len2 = vfmaq_f32(vfmaq_f32(vmulq_f32(a.z, a.z), a.y, a.y), a.x, a.x);
	float32x4_t inv = vdivq_f32(vdupq_n_f32(1.0f), vsqrtq_f32(len2));
	v3x4 r = { vmulq_f32(a.x, inv), vmulq_f32(a.y, inv), vmulq_f32(a.z, inv) };
	return r;
}

static v3x4 apply_rows(const float32x4_t m[12], v3x4 p, int with_translation)
{
	v3x4 r;
	float32x4_t *out[3] = { &r.x, &r.y, &r.z };
	for (int row = 0; row < 3; row++) {
		const float32x4_t *q = m + 4 * row;
		float32x4_t acc = with_translation ? q[3] : vdupq_n_f32(0.0f);
		acc = vfmaq_f32(acc, q[0], p.x);
		acc = vfmaq_f32(acc, q[1], p.y);
		*out[row] = vfmaq_f32(acc, q[2], p.z);
	}
	return r;
}

void skin_lbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_lbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	const float *base = &b->lbs12[0][0];
	for (int v = first; v < end; v += NEON_LANES) {
		float32x4_t m[12];
		for (int i = 0; i < 12; i++)
			m[i] = vdupq_n_f32(0.0f);
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			float32x4_t w = vld1q_f32(in->weight[k] + v);
			for (int row = 0; row < 3; row++) {
				float32x4_t c[4];
				gather4x4(base, 12, in->bone[k], v, 4 * row, c);
				for (int i = 0; i < 4; i++)
					m[4 * row + i] = vfmaq_f32(m[4 * row + i], w, c[i]);
			}
		}
		int valid = end - v < NEON_LANES ? end - v : NEON_LANES;
		v3x4 p = apply_rows(m, load3(in->px, in->py, in->pz, v), 1);
		v3x4 n = normalize4(apply_rows(m, load3(in->nx, in->ny, in->nz, v), 0));
		store_xyz4(out->pos + 3 * v, p, valid);
		store_xyz4(out->nrm + 3 * v, n, valid);
	}
}

typedef struct dq4 {
	float32x4_t rw, rx, ry, rz, dw, dx, dy, dz;
} dq4;

static dq4 gather_dq(const skin_bones *b, const uint16_t *bone, int v)
{
	float32x4_t r[4], d[4];
	gather4x4(&b->dq8[0][0], 8, bone, v, 0, r);
	gather4x4(&b->dq8[0][0], 8, bone, v, 4, d);
	dq4 q = { r[0], r[1], r[2], r[3], d[0], d[1], d[2], d[3] };
	return q;
}

static void dq_accumulate(dq4 *acc, const dq4 *d, float32x4_t w)
{
	acc->rw = vfmaq_f32(acc->rw, w, d->rw);
	acc->rx = vfmaq_f32(acc->rx, w, d->rx);
	acc->ry = vfmaq_f32(acc->ry, w, d->ry);
	acc->rz = vfmaq_f32(acc->rz, w, d->rz);
	acc->dw = vfmaq_f32(acc->dw, w, d->dw);
	acc->dx = vfmaq_f32(acc->dx, w, d->dx);
	acc->dy = vfmaq_f32(acc->dy, w, d->dy);
	acc->dz = vfmaq_f32(acc->dz, w, d->dz);
}

/* Weighted sum with each influence's sign flipped when its real part points
 * away from the pivot (influence 0, the largest weight). */
static dq4 dq_blend4(const skin_soa *in, const skin_bones *b, int v)
{
	const uint32x4_t sign = vdupq_n_u32(0x80000000u);
	dq4 pivot = gather_dq(b, in->bone[0], v);
	float32x4_t zero = vdupq_n_f32(0.0f);
	dq4 acc = { zero, zero, zero, zero, zero, zero, zero, zero };
	dq_accumulate(&acc, &pivot, vld1q_f32(in->weight[0] + v));
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		dq4 d = gather_dq(b, in->bone[k], v);
		float32x4_t dot = vmulq_f32(d.rw, pivot.rw);
		dot = vfmaq_f32(dot, d.rx, pivot.rx);
		dot = vfmaq_f32(dot, d.ry, pivot.ry);
		dot = vfmaq_f32(dot, d.rz, pivot.rz);
		uint32x4_t wbits = veorq_u32(vreinterpretq_u32_f32(vld1q_f32(in->weight[k] + v)),
					     vandq_u32(vreinterpretq_u32_f32(dot), sign));
		dq_accumulate(&acc, &d, vreinterpretq_f32_u32(wbits));
	}
	return acc;
}

static v3x4 cross4(v3x4 a, v3x4 b)
{
	v3x4 r = { vfmsq_f32(vmulq_f32(a.y, b.z), a.z, b.y),
		   vfmsq_f32(vmulq_f32(a.z, b.x), a.x, b.z),
		   vfmsq_f32(vmulq_f32(a.x, b.y), a.y, b.x) };
	return r;
}

/* a + b * s */
static v3x4 madd4(v3x4 a, v3x4 b, float32x4_t s)
{
	v3x4 r = { vfmaq_f32(a.x, b.x, s), vfmaq_f32(a.y, b.y, s), vfmaq_f32(a.z, b.z, s) };
	return r;
}

/* v + 2 r x (r x v + w v): rotation by the unit quaternion (w, r) */
static v3x4 rotate4(float32x4_t w, v3x4 r, v3x4 v)
{
	v3x4 t = madd4(cross4(r, v), v, w);
	return madd4(v, cross4(r, t), vdupq_n_f32(2.0f));
}

void skin_dqbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	const float32x4_t two = vdupq_n_f32(2.0f);
	for (int v = first; v < end; v += NEON_LANES) {
		dq4 d = dq_blend4(in, b, v);
		float32x4_t n2 = vfmaq_f32(vfmaq_f32(vfmaq_f32(vmulq_f32(d.rz, d.rz), d.ry, d.ry), d.rx, d.rx),
					   d.rw, d.rw);
		float32x4_t inv = vdivq_f32(vdupq_n_f32(1.0f), vsqrtq_f32(n2));
		float32x4_t rw = vmulq_f32(d.rw, inv), dw = vmulq_f32(d.dw, inv);
		v3x4 r = { vmulq_f32(d.rx, inv), vmulq_f32(d.ry, inv), vmulq_f32(d.rz, inv) };
		v3x4 dv = { vmulq_f32(d.dx, inv), vmulq_f32(d.dy, inv), vmulq_f32(d.dz, inv) };
		/* translation 2 (w_r d_v - w_d r_v + r_v x d_v) */
		v3x4 t = cross4(r, dv);
		t = madd4(t, dv, rw);
		t = madd4(t, r, vnegq_f32(dw));
		v3x4 p = madd4(rotate4(rw, r, load3(in->px, in->py, in->pz, v)), t, two);
		v3x4 n = rotate4(rw, r, load3(in->nx, in->ny, in->nz, v));
		int valid = end - v < NEON_LANES ? end - v : NEON_LANES;
		store_xyz4(out->pos + 3 * v, p, valid);
		store_xyz4(out->nrm + 3 * v, n, valid);
	}
}

#else
typedef int skin_neon_not_built; /* the board chose other kernels */
#endif
