/* DQBS in fixed point with NEON integer instructions (AArch64, the
 * Raspberry Pi 4's Cortex-A72), four vertices per step, bit for bit the
 * results of skin_fixed.c. NEON has what the scalar kernel's int64 steps
 * need: 32x32->64 multiply-accumulates (vmlal), rounding shifts and the
 * saturating narrow to int32 in one instruction (vqrshrn is
 * fx_sat32(fx_shr_round(x, n))), and per-lane variable rounding shifts
 * (vrshl). So unlike the AVX2 kernel no envelope is needed: every lane
 * saturates where the scalar kernel does. The blend runs per vertex (its
 * four bones' rows times signed weights into int64 lanes), one transpose
 * turns four blends into lanes, and the reciprocal of each blend's norm
 * is the scalar fx_blend_scale (a chain of 64-bit steps NEON has no clz
 * for). No floating-point instruction: `make test` disassembles this
 * object to check (tests/check_simd_integer.sh). */
#include "skin_kernels.h"

#if defined(SKP_SIMD_NEON) && defined(__aarch64__)

#include "skin_neon.h"

/* A signed 64-bit value per lane of an int32x4_t, in two registers. */
typedef struct s64x4 {
	int64x2_t lo, hi;
} s64x4;

static inline s64x4 mul4(int32x4_t a, int32x4_t b)
{
	s64x4 r = { vmull_s32(vget_low_s32(a), vget_low_s32(b)), vmull_high_s32(a, b) };
	return r;
}

static inline s64x4 mla4(s64x4 acc, int32x4_t a, int32x4_t b)
{
	s64x4 r = { vmlal_s32(acc.lo, vget_low_s32(a), vget_low_s32(b)), vmlal_high_s32(acc.hi, a, b) };
	return r;
}

static inline s64x4 mls4(s64x4 acc, int32x4_t a, int32x4_t b)
{
	s64x4 r = { vmlsl_s32(acc.lo, vget_low_s32(a), vget_low_s32(b)), vmlsl_high_s32(acc.hi, a, b) };
	return r;
}

/* fx_sat32(fx_shr_round(x, 30)) and fx_sat32(x >> 30) per lane */
static inline int32x4_t narrow_round30(s64x4 x)
{
	return vcombine_s32(vqrshrn_n_s64(x.lo, 30), vqrshrn_n_s64(x.hi, 30));
}

static inline int32x4_t narrow_cut30(s64x4 x)
{
	return vcombine_s32(vqshrn_n_s64(x.lo, 30), vqshrn_n_s64(x.hi, 30));
}

/* fx_sat32(x + v) per lane */
static inline int32x4_t add_narrow(s64x4 x, int32x4_t v)
{
	return vcombine_s32(vqmovn_s64(vaddw_s32(x.lo, vget_low_s32(v))), vqmovn_s64(vaddw_high_s32(x.hi, v)));
}

/* fx_dq_blend of one vertex: each influence's weight negated when its
 * real part points away from the pivot's (the exact int64 dot product, as
 * fx_quat_dot), the sums in int64 and rounded once by 15 bits. */
static void blend_vertex(const skin_soa *in, const skin_bones *b, int v, int32x4_t *real, int32x4_t *dual)
{
	const int32x4_t pivot = vld1q_s32(&b->fdq[in->bone[0][v]].real.w);
	int64x2_t r0 = vdupq_n_s64(0), r1 = r0, u0 = r0, u1 = r0;
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		const fx_dq *d = &b->fdq[in->bone[k][v]];
		int32x4_t qr = vld1q_s32(&d->real.w), qd = vld1q_s32(&d->dual.w);
		int64x2_t dot = vmlal_high_s32(vmull_s32(vget_low_s32(qr), vget_low_s32(pivot)), qr, pivot);
		int32_t w = in->fweight[k][v];
		if (vaddvq_s64(dot) < 0)
			w = -w;
		r0 = vmlal_n_s32(r0, vget_low_s32(qr), w);
		r1 = vmlal_high_n_s32(r1, qr, w);
		u0 = vmlal_n_s32(u0, vget_low_s32(qd), w);
		u1 = vmlal_high_n_s32(u1, qd, w);
	}
	*real = vcombine_s32(vqrshrn_n_s64(r0, 15), vqrshrn_n_s64(r1, 15));
	*dual = vcombine_s32(vqrshrn_n_s64(u0, 15), vqrshrn_n_s64(u1, 15));
}

/* The blends of 4 vertices in lanes (d[0..3] real w x y z, d[4..7] dual)
 * and each one's 2 / |real|^2 as inv / 2^sh; 0 when a vertex's blend is
 * one fx_dq_transform_blend leaves alone (sh 0). */
static int blend4(const skin_soa *in, const skin_bones *b, int v, int32x4_t d[8], int32_t inv[NEON_LANES],
		  int64_t sh[NEON_LANES])
{
	int32x4_t real[NEON_LANES], dual[NEON_LANES];
	for (int j = 0; j < NEON_LANES; j++) {
		blend_vertex(in, b, v + j, &real[j], &dual[j]);
		fx_quat q;
		vst1q_s32(&q.w, real[j]);
		uint32_t y;
		int s = fx_blend_scale(q, &y);
		if (s == 0)
			return 0;
		inv[j] = (int32_t)y;
		sh[j] = -s; /* vrshl shifts right by minus its count */
	}
	skin_transpose4(real);
	skin_transpose4(dual);
	memcpy(d, real, sizeof real);
	memcpy(d + 4, dual, sizeof dual);
	return 1;
}

/* move_blended (fixed.c) on 4 lanes: v + (2 / s) (r x (r x v + w v + dv) +
 * w dv - dw r), dual = d + 4, or NULL for a normal, whose shifts cut. */
static void move4(const int32x4_t d[8], const int32x4_t *dual, const int32x4_t v[3], int32x4_t inv,
		  const int64x2_t nsh[2], int32x4_t out[3])
{
	const int32x4_t w = d[0], *r = d + 1;
	int32x4_t a[3];
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3, k = (i + 2) % 3;
		s64x4 sum = mla4(mls4(mul4(r[j], v[k]), r[k], v[j]), w, v[i]);
		if (dual) {
			s64x4 t = { vrshrq_n_s64(sum.lo, 30), vrshrq_n_s64(sum.hi, 30) };
			a[i] = add_narrow(t, dual[i + 1]);
		} else {
			a[i] = narrow_cut30(sum);
		}
	}
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3, k = (i + 2) % 3;
		s64x4 sum = mls4(mul4(r[j], a[k]), r[k], a[j]);
		if (dual)
			sum = mls4(mla4(sum, w, dual[i + 1]), dual[0], r[i]);
		int32x4_t bi = dual ? narrow_round30(sum) : narrow_cut30(sum);
		s64x4 delta = mul4(bi, inv);
		delta.lo = dual ? vrshlq_s64(delta.lo, nsh[0]) : vshlq_s64(delta.lo, nsh[0]);
		delta.hi = dual ? vrshlq_s64(delta.hi, nsh[1]) : vshlq_s64(delta.hi, nsh[1]);
		out[i] = add_narrow(delta, v[i]);
	}
}

static void load3(const int32_t *const src[3], int v, int32x4_t out[3])
{
	for (int i = 0; i < 3; i++)
		out[i] = vld1q_s32(src[i] + v);
}

void skin_dqbs_fixed_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	_Static_assert(FX_POS_FRAC == 16, "the NEON fixed kernel writes fx_pos as Q16.16 directly");
	const int32_t *const pos_in[3] = { in->fpx, in->fpy, in->fpz }, *const nrm_in[3] = { in->fnx, in->fny, in->fnz };
	for (int v = first; v < end; v += NEON_LANES) {
		int valid = end - v < NEON_LANES ? end - v : NEON_LANES;
		int32x4_t d[8];
		int32_t inv[NEON_LANES];
		int64_t sh[NEON_LANES];
		if (!blend4(in, b, v, d, inv, sh)) {
			/* a blend left as it is (all but cancelled): the scalar
			 * kernel says how */
			skin_dqbs_fixed(in, b, v, v + valid, out);
			continue;
		}
		const int64x2_t nsh[2] = { vld1q_s64(sh), vld1q_s64(sh + 2) };
		int32x4_t p[3], n[3], po[3], no[3];
		load3(pos_in, v, p);
		load3(nrm_in, v, n);
		move4(d, d + 4, p, vld1q_s32(inv), nsh, po);
		move4(d, NULL, n, vld1q_s32(inv), nsh, no);
		for (int i = 0; i < 3; i++)
			no[i] = vrshrq_n_s32(no[i], 14); /* Q30 to Q16 */
		skin_store_xyz4(out->fpos + 3 * v, po[0], po[1], po[2], valid);
		skin_store_xyz4(out->fnrm + 3 * v, no[0], no[1], no[2], valid);
	}
}

#else
typedef int skin_fixed_neon_not_built; /* the board chose other kernels */
#endif
