/* DQBS in fixed point with NEON integer instructions (AArch64, the
 * Raspberry Pi 4's Cortex-A72), four vertices per step, bit for bit the
 * results of skin_fixed.c. NEON has what the scalar kernel's int64 steps
 * need: 32x32->64 multiply-accumulates (vmlal), rounding shifts and the
 * saturating narrow to int32 in one instruction (vqrshrn is
 * fx_sat32(fx_shr_round(x, n))), and per-lane variable rounding shifts
 * (vrshl). So unlike the AVX2 kernel it needs no envelope for positions
 * and normals: every lane saturates where the scalar kernel does. The
 * blend runs per vertex (its four bones' rows, negated by the sign fix,
 * times one lane of the weights into int64 lanes), one transpose turns
 * four blends into lanes, and the reciprocal of each blend's norm runs in
 * lanes too, as fx_blend_scale would (the rare norm outside its range
 * sends the step to the scalar kernel; a frame whose bone rows cannot be
 * negated, the whole call: see skin_bones.fdq_signed). No floating-point
 * instruction: `make test` disassembles this object to check
 * (tests/check_simd_integer.sh). */
#include "skin_kernels.h"

#if defined(SKP_SIMD_NEON) && defined(__aarch64__)

#include "skin_neon.h"

/* A signed 64-bit value per lane of an int32x4_t, in two registers. */
typedef struct s64x4 {
	int64x2_t lo, hi;
} s64x4;

NEON_INLINE s64x4 mul4(int32x4_t a, int32x4_t b)
{
	s64x4 r = { vmull_s32(vget_low_s32(a), vget_low_s32(b)), vmull_high_s32(a, b) };
	return r;
}

NEON_INLINE s64x4 mla4(s64x4 acc, int32x4_t a, int32x4_t b)
{
	s64x4 r = { vmlal_s32(acc.lo, vget_low_s32(a), vget_low_s32(b)), vmlal_high_s32(acc.hi, a, b) };
	return r;
}

NEON_INLINE s64x4 mls4(s64x4 acc, int32x4_t a, int32x4_t b)
{
	s64x4 r = { vmlsl_s32(acc.lo, vget_low_s32(a), vget_low_s32(b)), vmlsl_high_s32(acc.hi, a, b) };
	return r;
}

/* fx_sat32(fx_shr_round(x, 30)) and fx_sat32(x >> 30) per lane */
NEON_INLINE int32x4_t narrow_round30(s64x4 x)
{
	return vqrshrn_high_n_s64(vqrshrn_n_s64(x.lo, 30), x.hi, 30);
}

NEON_INLINE int32x4_t narrow_cut30(s64x4 x)
{
	return vqshrn_high_n_s64(vqshrn_n_s64(x.lo, 30), x.hi, 30);
}

/* fx_sat32(x + v) per lane */
NEON_INLINE int32x4_t add_narrow(s64x4 x, int32x4_t v)
{
	return vqmovn_high_s64(vqmovn_s64(vaddw_s32(x.lo, vget_low_s32(v))), vaddw_high_s32(x.hi, v));
}

/* What the blends read, in locals for the whole run (through skin_soa
 * and skin_bones, every step reloaded the pointers: the stores might have
 * changed them). */
typedef struct blend_src {
	const uint16_t *bone[SKP_MAX_INFLUENCES];
	const fx_w15 *weight[SKP_MAX_INFLUENCES];
	const char *rows;                        /* skin_bones.fdq_signed */
	const uint16_t (*at)[SKP_MAX_BONES + 1]; /* skin_bones.fdq_at */
} blend_src;

/* The weights of influence k of vertices v..v+3, one per lane. */
NEON_INLINE void load_weights(const blend_src *in, int v, int32x4_t w[SKP_MAX_INFLUENCES])
{
#pragma GCC unroll 12
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		w[k] = vreinterpretq_s32_u32(vmovl_u16(vld1_u16(in->weight[k] + v)));
}

/* fx_dq_blend of vertex v + j (its weights in lane j of w): each
 * influence's row taken negated where the sign fix (the exact int64 dot
 * product with the pivot's real part, as fx_dq_blend tests it, once per
 * bone pair and frame) says, as fdq_at points, the sums in int64 and
 * rounded once by 15 bits. */
NEON_INLINE void blend_vertex(const blend_src *in, int v, int j, const int32x4_t w[SKP_MAX_INFLUENCES],
			      int32x4_t *real, int32x4_t *dual)
{
	const uint16_t *at = in->at[in->bone[0][v + j]];
	int64x2_t r0 = vdupq_n_s64(0), r1 = r0, u0 = r0, u1 = r0;
#pragma GCC unroll 12
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		const int32_t *row = (const int32_t *)(in->rows + at[in->bone[k][v + j]]);
		int32x4_t qr = vld1q_s32(row), qd = vld1q_s32(row + 4);
		r0 = vmlal_laneq_s32(r0, vget_low_s32(qr), w[k], j);
		r1 = vmlal_high_laneq_s32(r1, qr, w[k], j);
		u0 = vmlal_laneq_s32(u0, vget_low_s32(qd), w[k], j);
		u1 = vmlal_high_laneq_s32(u1, qd, w[k], j);
	}
	*real = vqrshrn_high_n_s64(vqrshrn_n_s64(r0, 15), r1, 15);
	*dual = vqrshrn_high_n_s64(vqrshrn_n_s64(u0, 15), u1, 15);
}

/* (a * b + 2^(s-1)) >> s per lane, for products whose result fits 32 bits */
#define MUL_ROUND(a, b, s) vrshrn_high_n_u64(vrshrn_n_u64(vmull_u32(vget_low_u32(a), vget_low_u32(b)), s), \
					      vmull_high_u32(a, b), s)

/* A 32-bit table entry per lane: lane value s picks bytes 4s..4s+3. Two
 * one-register lookups (entries 0-3, then 4-7, whose out-of-range bytes
 * keep the first's) rather than one over a register pair, which GCC 12
 * builds in memory every step. */
NEON_INLINE uint32x4_t lookup8(const uint32_t table[8], uint32x4_t s)
{
	uint8x16_t bytes = vreinterpretq_u8_u32(vmlaq_n_u32(vdupq_n_u32(0x03020100u), s, 0x04040404u));
	uint8x16_t r = vqtbl1q_u8(vld1q_u8((const uint8_t *)table), bytes);
	return vreinterpretq_u32_u8(vqtbx1q_u8(r, vld1q_u8((const uint8_t *)table + 16), vsubq_u8(bytes, vdupq_n_u8(16))));
}

/* The squared norms of the blends' real parts (d[0..3]) in Q60, two
 * lanes each in n[0], n[1], their high halves in *top, and whether every
 * lane is in [2^32, 2^61) (its high half in [1, 2^29)), the range where
 * recip4x2 gives fx_blend_scale's results: outside it (a blend that all but
 * cancelled, or weights summing past 1) the caller takes the scalar
 * kernel. */
NEON_INLINE int norms4(const int32x4_t d[4], uint64x2_t n[2], uint32x4_t *top)
{
	int64x2_t lo = vmull_s32(vget_low_s32(d[0]), vget_low_s32(d[0])), hi = vmull_high_s32(d[0], d[0]);
#pragma GCC unroll 4
	for (int c = 1; c < 4; c++) {
		lo = vmlal_s32(lo, vget_low_s32(d[c]), vget_low_s32(d[c]));
		hi = vmlal_high_s32(hi, d[c], d[c]);
	}
	/* unsigned: four squares of int32 wrap only when all are 2^62, to 0 */
	n[0] = vreinterpretq_u64_s64(lo);
	n[1] = vreinterpretq_u64_s64(hi);
	*top = vuzp2q_u32(vreinterpretq_u32_s64(lo), vreinterpretq_u32_s64(hi));
	uint32x4_t ok = vcltq_u32(vsubq_u32(*top, vdupq_n_u32(1)), vdupq_n_u32((1u << 29) - 1));
	return vminvq_u32(ok) != 0;
}

/* fx_blend_scale on two sets of 4 lanes, step for step the same integers,
 * for squared norms x (from norms4) in [2^32, 2^61): there clz(x) is clz of
 * x's high half (NEON counts leading zeros of 32-bit lanes only) and every
 * value below fits 32 bits. inv / 2^-nsh is each lane's 2 / |real|^2. Two
 * sets stage by stage: the reciprocal is a chain of dependent multiplies
 * (a step's 4 vertices alone left the core waiting on it for a quarter of
 * the loop's cycles, by the Cortex-A72 model), so two chains side by side. */
NEON_INLINE void recip4x2(const uint64x2_t n[2][2], const uint32x4_t top[2], int32x4_t inv[2], int64x2_t nsh[2][2])
{
	uint32x4_t xq[2], y[2];
	int32x4_t e[2];
#pragma GCC unroll 2
	for (int g = 0; g < 2; g++) {
		/* fx_recip_q60: e = clz(x) - 3 puts x 2^e in [2^60, 2^61); X in Q30 */
		e[g] = vsubq_s32(vreinterpretq_s32_u32(vclzq_u32(top[g])), vdupq_n_s32(3));
		uint64x2_t xl = vshlq_u64(n[g][0], vmovl_s32(vget_low_s32(e[g])));
		uint64x2_t xh = vshlq_u64(n[g][1], vmovl_high_s32(e[g]));
		xq[g] = vshrn_high_n_u64(vshrn_n_u64(xl, 30), xh, 30);
		uint32x4_t seg = vsubq_u32(vshrq_n_u32(xq[g], 27), vdupq_n_u32(8));
		y[g] = vsubq_u32(lookup8(fx_recip_seed_a, seg), MUL_ROUND(lookup8(fx_recip_seed_b, seg), xq[g], 30));
	}
#pragma GCC unroll 4
	for (int i = 0; i < FX_RECIP_STEPS; i++) {
#pragma GCC unroll 2
		for (int g = 0; g < 2; g++) {
			uint32x4_t xy = MUL_ROUND(xq[g], y[g], 30);
			y[g] = MUL_ROUND(y[g], vsubq_u32(vdupq_n_u32(0), xy), 31); /* 2^32 - xy */
		}
	}
#pragma GCC unroll 2
	for (int g = 0; g < 2; g++) {
		/* fx_blend_scale: inv = (y + 1) / 2, sh = 29 - e (vrshl shifts
		 * right by minus its count) */
		inv[g] = vreinterpretq_s32_u32(vrshrq_n_u32(y[g], 1));
		int32x4_t neg = vsubq_s32(e[g], vdupq_n_s32(29));
		nsh[g][0] = vmovl_s32(vget_low_s32(neg));
		nsh[g][1] = vmovl_high_s32(neg);
	}
}

/* The blends of 4 vertices in lanes (d[0..3] real w x y z, d[4..7] dual). */
NEON_INLINE void blend4(const blend_src *in, int v, int32x4_t d[8])
{
	int32x4_t real[NEON_LANES], dual[NEON_LANES], w[SKP_MAX_INFLUENCES];
	load_weights(in, v, w);
#pragma GCC unroll 12
	for (int j = 0; j < NEON_LANES; j++)
		blend_vertex(in, v, j, w, &real[j], &dual[j]);
	skin_transpose4(real);
	skin_transpose4(dual);
#pragma GCC unroll 4
	for (int c = 0; c < 4; c++) {
		d[c] = real[c];
		d[4 + c] = dual[c];
	}
}

/* move_blended (fixed.c) on 4 lanes: v + (2 / s) (r x (r x v + w v + dv) +
 * w dv - dw r), dual = d + 4, or NULL for a normal, whose shifts cut. */
NEON_INLINE void move4(const int32x4_t d[8], const int32x4_t *dual, const int32x4_t v[3], int32x4_t inv,
		  const int64x2_t nsh[2], int32x4_t out[3])
{
	const int32x4_t w = d[0], *r = d + 1;
	int32x4_t a[3];
#pragma GCC unroll 12
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3, k = (i + 2) % 3;
		/* a point's sum starts at dv 2^30: rounded by 30 bits, that is
		 * round(sum / 2^30) + dv exactly, saturated as fx_sat32 would
		 * (|sum| < 2^62.3 for norms below 2^61 and |dv 2^30| <= 2^61:
		 * no int64 overflow) */
		s64x4 sum;
		if (dual) {
			s64x4 start = { vshll_n_s32(vget_low_s32(dual[i + 1]), 30), vshll_high_n_s32(dual[i + 1], 30) };
			sum = mla4(start, r[j], v[k]);
		} else {
			sum = mul4(r[j], v[k]);
		}
		sum = mla4(mls4(sum, r[k], v[j]), w, v[i]);
		a[i] = dual ? narrow_round30(sum) : narrow_cut30(sum);
	}
#pragma GCC unroll 12
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

NEON_INLINE void load3(const int32_t *const src[3], int v, int32x4_t out[3])
{
#pragma GCC unroll 12
	for (int i = 0; i < 3; i++)
		out[i] = vld1q_s32(src[i] + v);
}

/* Vertices a step of the kernel's loop: two sets of 4 (see recip4x2). */
#define FIXED_STEP (2 * NEON_LANES)

/* The kernel's loop over whole steps, from v until a step has a norm out
 * of norms4's range or fewer than FIXED_STEP vertices are left; returns
 * where it stopped. Apart, without calls, so that nothing it keeps in
 * registers has to be saved around the scalar kernel's call (AArch64
 * calls keep only the low halves of v8-v15): with the call inside, the
 * loop made 70 stack loads and stores per 4 vertices (GCC 12). noclone
 * keeps the name that tests/model_cycles.sh looks for. */
__attribute__((noinline, noclone))
static int fixed_neon_run(const skin_soa *in, const skin_bones *b, int v, int end, const skin_out *out)
{
	_Static_assert(FX_POS_FRAC == 16, "the NEON fixed kernel writes fx_pos as Q16.16 directly");
	const int32_t *const pos_in[3] = { in->fpx, in->fpy, in->fpz }, *const nrm_in[3] = { in->fnx, in->fny, in->fnz };
	blend_src src = { .rows = (const char *)b->fdq_signed, .at = b->fdq_at };
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		src.bone[k] = in->bone[k];
		src.weight[k] = in->fweight[k];
	}
	int32_t *fpos = out->fpos, *fnrm = out->fnrm;
	for (; end - v >= FIXED_STEP; v += FIXED_STEP) {
		int32x4_t d[2][8], inv[2];
		int64x2_t nsh[2][2];
		uint64x2_t norm[2][2];
		uint32x4_t top[2];
		blend4(&src, v, d[0]);
		blend4(&src, v + NEON_LANES, d[1]);
		if (!(norms4(d[0], norm[0], &top[0]) & norms4(d[1], norm[1], &top[1])))
			break;
		recip4x2(norm, top, inv, nsh);
#pragma GCC unroll 2
		for (int g = 0; g < 2; g++) {
			int at = v + g * NEON_LANES;
			int32x4_t p[3], n[3], po[3], no[3];
			load3(pos_in, at, p);
			load3(nrm_in, at, n);
			move4(d[g], d[g] + 4, p, inv[g], nsh[g], po);
			move4(d[g], NULL, n, inv[g], nsh[g], no);
#pragma GCC unroll 12
			for (int i = 0; i < 3; i++)
				no[i] = vrshrq_n_s32(no[i], 14); /* Q30 to Q16 */
			skin_store_xyz4(fpos + 3 * at, po[0], po[1], po[2], NEON_LANES);
			skin_store_xyz4(fnrm + 3 * at, no[0], no[1], no[2], NEON_LANES);
		}
	}
	return v;
}

/* The steps fixed_neon_run leaves (a norm out of norms4's range, the last
 * 1-7 vertices) go to the scalar kernel, which gives the same bits. */
void skin_dqbs_fixed_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	if (!b->simd_ok) {
		skin_dqbs_fixed(in, b, first, end, out);
		return;
	}
	int v = first;
	while ((v = fixed_neon_run(in, b, v, end, out)) < end) {
		int stop = end - v < FIXED_STEP ? end : v + FIXED_STEP;
		skin_dqbs_fixed(in, b, v, stop, out);
		v = stop;
	}
}

#else
typedef int skin_fixed_neon_not_built; /* the board chose other kernels */
#endif
