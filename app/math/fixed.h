/* Fixed-point dual quaternion skinning for boards without an FPU (or where
 * bit-exact results across boards matter). Integer arithmetic only: int32
 * storage, int64 intermediates; fixed_convert.h is the only bridge to float.
 *
 * Formats:
 *
 *   fx_q30  int32 Q2.30 (sign, 1 integer bit, 30 fraction bits): unit
 *           quaternion components, rotation and normal components. Range
 *           [-2, 2), resolution 2^-30 = 9.3e-10.
 *   fx_pos  int32 with FX_POS_FRAC fraction bits; the default 16 gives signed
 *           Q15.16 (sign, 15 integer bits, 16 fraction bits): positions,
 *           translations and the dual part of an fx_dq. Resolution 2^-16 =
 *           1.5e-5 model units, range [-32768, 32768) units.
 *   fx_w15  uint16 Q1.15 skinning weight, 32768 = 1.0: four weights can sum
 *           to exactly 1.0 and a single full weight is representable.
 *
 * The scaling rule that makes the code independent of FX_POS_FRAC: a
 * product of an fx_q30 with a value in any format F, shifted right by 30,
 * is in F; a product with an fx_w15, shifted right by 15, is in F. So
 * quaternion products and rotations work unchanged on Q30 normals and on
 * fx_pos points; only the valid range (documented per function) depends on
 * the format.
 *
 * Why nothing overflows: products are int32 x int32 into int64 (<= 2^62),
 * except the second stage of fx_quat_rotate (int32 x 33-bit, see there).
 * A quaternion product component, a rotated-vector component or a dot product
 * is a signed sum in which every component of the unit operand appears once,
 * so its partial sums are bounded by |unit|_1 * max|other| <= 2 * 2^30 *
 * 2^31 = 2^62 (the L1 norm of a unit 4-vector is at most 2), whatever int32
 * the other operand holds (the second cross product of a rotation stays
 * below 2^62.3, see fx_quat_rotate). Only the final int32 results need a range
 * argument: a rotation preserves length, so rotated values fit whenever the
 * input did; the dual part of a bone with |t| < 32768 units is 0.5 |t| <
 * 16384 units = 2^30 raw; a blend with weights summing to 32768 is a convex
 * combination, so it stays within the largest input. Results that could
 * still leave int32 (translation of a dq whose |t| >= 32768, the dual part
 * after dividing a degenerate blend by a small norm) saturate instead of
 * wrapping.
 *
 * Rounding: every right shift rounds to nearest (ties towards +infinity),
 * except that fx_dq_transform_blend cuts a normal's (14 spare bits); signed
 * right shift must be arithmetic (checked at compile time below).
 */
#ifndef FIXED_H
#define FIXED_H

#include <stdint.h>

#ifndef FX_POS_FRAC
#define FX_POS_FRAC 16
#endif

#define FX_Q30_ONE ((int32_t)1 << 30)
#define FX_POS_ONE ((int32_t)1 << FX_POS_FRAC)
#define FX_W15_ONE 32768u

_Static_assert(FX_POS_FRAC >= 0 && FX_POS_FRAC <= 30, "FX_POS_FRAC out of range");
_Static_assert((-3 >> 1) == -2, "fixed.c needs an arithmetic signed right shift");

typedef int32_t fx_q30;
typedef int32_t fx_pos;
typedef uint16_t fx_w15;

/* fx_pos components for points and translations, fx_q30 for normals. */
typedef struct fx_vec3 {
	int32_t x, y, z;
} fx_vec3;

/* fx_q30 components for rotations; fx_pos for the dual part of an fx_dq. */
typedef struct fx_quat {
	int32_t w, x, y, z;
} fx_quat;

/* real: fx_q30 unit quaternion; dual: fx_pos, 0.5 * t * real as in dq.h. */
typedef struct fx_dq {
	fx_quat real, dual;
} fx_dq;

/* a * b exactly, for int32 a and b: every product in this module goes
 * through it with 32-bit operands, so a core with a 32 x 32 -> 64 multiply
 * (SMULL on a Cortex-M3/M4, IMUL on x86-64) gets one instruction. The
 * Cortex-M0 (ARMv6-M) has none: its MULS keeps the low 32 bits, and GCC
 * would call libgcc's 64 x 64 multiply; there the product is built from
 * four 16 x 16 products of the operands' halves, each of which fits 32
 * bits (a signed high half times an unsigned low half is below 2^31).
 * FX_NARROW_MUL says which: code that can use 32-bit sums of halves
 * instead (the fixed kernel's blend) does so where it is 1. */
#ifndef FX_NARROW_MUL /* a test may set it, to run that path on the host */
#if defined(__ARM_ARCH_6M__)
#define FX_NARROW_MUL 1
#else
#define FX_NARROW_MUL 0
#endif
#endif

static inline int64_t fx_mul_wide(int32_t a, int32_t b)
{
#if FX_NARROW_MUL
	int32_t ah = a >> 16, bh = b >> 16;
	uint32_t al = (uint16_t)a, bl = (uint16_t)b;
	int64_t mid = (int64_t)(ah * (int32_t)bl) + (int64_t)((int32_t)al * bh);
	/* unsigned arithmetic: shifting a negative int64 left is undefined */
	uint64_t r = ((uint64_t)(int64_t)(ah * bh) << 32) + ((uint64_t)mid << 16) + al * bl;
	return (int64_t)r;
#else
	return (int64_t)a * b;
#endif
}

/* The same for unsigned a and b. */
static inline uint64_t fx_mulu_wide(uint32_t a, uint32_t b)
{
#if FX_NARROW_MUL
	uint32_t ah = a >> 16, bh = b >> 16, al = a & 0xffffu, bl = b & 0xffffu;
	uint64_t mid = (uint64_t)(ah * bl) + al * bh;
	return ((uint64_t)(ah * bh) << 32) + (mid << 16) + al * bl;
#else
	return (uint64_t)a * b;
#endif
}

/* A sum of products, exact (as int64, whose range the caller answers
 * for): fx_sum_start(c), fx_sum_add(&s, a, b) for each product,
 * fx_sum_value(&s). Where a 32 x 32 -> 64 multiply-add is an instruction
 * it is that; on ARMv6-M, where each fx_mul_wide puts its four products
 * of halves together in 64 bits, the sum keeps those parts apart instead
 * (the products of high halves, the mixed ones, the low ones: adding an
 * int32 to an int64 is 2 or 3 instructions) and puts them together once. */
#if FX_NARROW_MUL
typedef struct fx_sum {
	int64_t hi, mid;
	uint64_t lo;
} fx_sum;

static inline fx_sum fx_sum_start(int64_t c)
{
	fx_sum s = { 0, 0, (uint64_t)c };
	return s;
}

static inline void fx_sum_add(fx_sum *s, int32_t a, int32_t b)
{
	int32_t ah = a >> 16, bh = b >> 16;
	uint32_t al = (uint16_t)a, bl = (uint16_t)b;
	s->hi += ah * bh;
	s->mid += ah * (int32_t)bl;
	s->mid += (int32_t)al * bh;
	s->lo += al * bl;
}

static inline int64_t fx_sum_value(const fx_sum *s)
{
	return (int64_t)(((uint64_t)s->hi << 32) + ((uint64_t)s->mid << 16) + s->lo);
}
#else
typedef struct fx_sum {
	int64_t v;
} fx_sum;

static inline fx_sum fx_sum_start(int64_t c)
{
	fx_sum s = { c };
	return s;
}

static inline void fx_sum_add(fx_sum *s, int32_t a, int32_t b)
{
	s->v += fx_mul_wide(a, b);
}

static inline int64_t fx_sum_value(const fx_sum *s)
{
	return s->v;
}
#endif

/* v / 2^s rounded to nearest, 1 <= s <= 62, |v| < 2^63 - 2^(s-1). */
static inline int64_t fx_shr_round(int64_t v, int s)
{
	return (v + ((int64_t)1 << (s - 1))) >> s;
}

static inline int32_t fx_sat32(int64_t v)
{
	return v > INT32_MAX ? INT32_MAX : v < INT32_MIN ? INT32_MIN : (int32_t)v;
}

/* a * b with a in Q30 and b in any format F; the result is in F. |a*b| <
 * 2^62 always; the result saturates if it leaves int32 (only if |a| > 1). */
static inline int32_t fx_mul_q30(fx_q30 a, int32_t b)
{
	return fx_sat32(fx_shr_round(fx_mul_wide(a, b), 30));
}

/* Dot product in Q60 (Q30+F if b is in F), exact. One operand a unit Q30
 * quaternion (or both shorter than 2): partial sums <= |a| |b| < 2^63. */
static inline int64_t fx_quat_dot(fx_quat a, fx_quat b)
{
	return fx_mul_wide(a.w, b.w) + fx_mul_wide(a.x, b.x) + fx_mul_wide(a.y, b.y) + fx_mul_wide(a.z, b.z);
}
/* Hamilton product, rotate by b then a. One operand must be a unit Q30
 * quaternion, the other may be Q30 or any format F (the result is then F).
 * Each component is summed exactly in int64 and rounded once. */
fx_quat fx_quat_mul(fx_quat a, fx_quat b);
/* Rotates v (any format, any int32 components) by the unit Q30 quaternion q:
 * v + 2 u x (u x v + w v). Error about 2 LSB of v's format. */
fx_vec3 fx_quat_rotate(fx_quat q, fx_vec3 v);

/* floor(sqrt(x)), exact for every uint64. Shift-and-subtract, no multiply. */
uint32_t fx_isqrt64(uint64_t x);
/* 1 / sqrt(x / 2^60) as m / 2^*shift, m in [2^30, 2^31), for 0 < x < 2^62
 * (the squared norm of a Q30 quaternion shorter than 2). A mantissa and a
 * shift rather than a Q30 value so that scaling any int32 by it is one
 * 32x32 -> 64 multiply that cannot overflow, even for norms far below 1.
 * Relative error below 2^-29. Returns 0 (and *shift = 0) for x = 0 or
 * x >= 2^62.
 *
 * Method: x is scaled by 4^e into [2^60, 2^62), X = x / 2^60 in [1, 4) is
 * cut to Q30, the seed is a minimax line on one of 8 segments of [1, 4)
 * (width 1/4 below 2, 1/2 above: within 0.25%), then 2 Newton steps
 * y' = y (1.5 - X y^2 / 2) in Q31 (0.25% -> 9e-6 -> 1.1e-9), all products
 * of two values below 2^32. */
uint32_t fx_rsqrt_q60(uint64_t x, int *shift);

/* 1 / (x / 2^60) for 0 < x < 2^61 as y / 2^(31 - *e), y in [2^30, 2^31]:
 * 1 / X in Q31 for X = x 2^e / 2^60 in [1, 2). Returns 0 (and *e = 0) for
 * x = 0 or x >= 2^61. Relative error below 2^-29 (X is cut to Q30).
 *
 * Method (shared with the SIMD kernel, which must match bit for bit): xq =
 * X cut to Q30, the seed a[s] - b[s] X a minimax line on one of 8 segments
 * of width 1/8 (within 0.19%), then FX_RECIP_STEPS Newton steps
 * y' = y (2 - X y) in Q31 (0.19% -> 3.4e-6 -> 1.2e-11), every product of
 * two values below 2^32. */
#define FX_RECIP_SEGMENTS 8
#define FX_RECIP_STEPS 2
extern const uint32_t fx_recip_seed_a[FX_RECIP_SEGMENTS]; /* Q31 */
extern const uint32_t fx_recip_seed_b[FX_RECIP_SEGMENTS]; /* Q31 */
uint32_t fx_recip_q60(uint64_t x, int *e);

/* Rotate by the unit Q30 quaternion q, then translate by t (fx_pos).
 * |t| < 32768 units so that the dual part fits. */
fx_dq fx_dq_from_quat_trans(fx_quat q, fx_vec3 t);
/* 2 * dual * conj(real) (vector part), fx_pos; real must be unit. Saturates
 * if |t| >= 32768 units. */
fx_vec3 fx_dq_translation(const fx_dq *d);
/* a * b (apply b, then a); real parts unit, result |t| < 32768 units. */
fx_dq fx_dq_mul(const fx_dq *a, const fx_dq *b);
/* Divides both parts by |real| (|real| < 2). Identity if real is zero. The
 * dual part's component along real is left in place: the transforms below
 * ignore it. */
fx_dq fx_dq_normalize(fx_dq d);
/* Both expect a unit real part (e.g. from fx_dq_normalize). p in
 * fx_pos, n in fx_q30; the result saturates rather than wrapping. */
fx_vec3 fx_dq_transform_point(const fx_dq *d, fx_vec3 p);
fx_vec3 fx_dq_transform_normal(const fx_dq *d, fx_vec3 n);

/* Real part of the largest-weight influence (first wins a tie). */
fx_quat fx_dq_blend_pivot(const fx_dq *bone_dqs, const uint16_t *bone_idx,
			  const fx_w15 *weights, int count);
/* DQBS sum of weights[i] * bone_dqs[bone_idx[i]] with each influence negated
 * when its real part has a negative dot product with pivot. Accumulated
 * exactly in int64 (Q45 and F+15; any count < 65536 fits), rounded once.
 * With weights summing to 32768 the result is a convex combination, so
 * |real| <= 1 and |dual| <= the largest bone's |dual|. Not normalised. */
fx_dq fx_dq_blend(const fx_dq *bone_dqs, const uint16_t *bone_idx,
		  const fx_w15 *weights, int count, fx_quat pivot);
/* Moves the point p (fx_pos) and the normal n (fx_q30) as fx_dq_transform_point
 * and _normal of fx_dq_normalize(d) would, without normalising d: with
 * (w, r) its real and (dw, dv) its dual part and s = |(w, r)|^2, a unit
 * quaternion's rotation v + 2 r x (r x v + w v) becomes, for any length,
 * v + (2 / s) r x (r x v + w v), and the translation joins it inside:
 *   p' = p + (2 / s) (r x (r x p + w p + dv) + w dv - dw r)
 *   n' = n + (2 / s) r x (r x n + w n)
 * 42 products instead of the 50 of normalising, rotating and translating,
 * and no normalised copy of d, nor a square root: 2 / s = inv / 2^sh with
 * inv = round(y / 2) in [2^29, 2^30] and sh = 29 - e, (y, e) from
 * fx_recip_q60(s in Q60). The two inner sums are rounded to p's format
 * (n's for the normal) and saturated, so no product leaves int64; within
 * int32 range (|p| + |t| < 32768 units) the results match the normalised
 * path to a few LSB, more only as 2 / s grows. Identity (p, n returned as
 * they are) when s is 0, below 2^-28 (an all but cancelled blend) or 2 or
 * more (weights summing well past 1). */
void fx_dq_transform_blend(const fx_dq *d, fx_vec3 p, fx_vec3 n, fx_vec3 *po, fx_vec3 *no);
/* fx_dq_transform_blend's 2 / s for the blend's real part as *inv / 2^sh,
 * returning sh, or 0 where it leaves p and n as they are; for SIMD kernels
 * that must match it bit for bit. */
int fx_blend_scale(fx_quat real, uint32_t *inv);

#endif
