/* DQBS in fixed point: integer arithmetic only (checked by
 * tests/check_fixed_integer.sh). Output is Q16.16, which is GL_FIXED.
 *
 * This is the reference every fixed kernel matches bit for bit, and the
 * kernel of the boards without SIMD: the Cortex-M0 and M4 run it. Two
 * forms of the same numbers (fx_dq_blend, then fx_dq_transform_blend):
 * on a Cortex-M0 (FX_NARROW_MUL), which has no 32 x 32 -> 64 multiply,
 * the blend's exact sums from 32-bit ones; elsewhere (the M4, the host)
 * one vertex as chains of 64-bit multiply-adds with one cheap range check
 * a sum, by hand (inline SMLAL, SSAT) on ARMv7E-M, where GCC 12's own
 * code spills. The test programs compare them with each other and with
 * the SIMD kernels (tests/embedded: the checksums). */
#include "skin_kernels.h"

_Static_assert(FX_POS_FRAC <= 16, "positions are written as Q16.16");

/* fx_shr_round(v, 14) in 32 bits: v = q 2^14 + r rounds to q + (r >= 2^13). */
static int32_t q30_to_q16(fx_q30 v)
{
	return (v >> 14) + ((v >> 13) & 1);
}

#if FX_NARROW_MUL
/* fx_dq_blend's sums, split at bit 16: every component c of a bone's dq
 * is hi 2^16 + lo (hi = c >> 16 signed, lo in [0, 2^16): the rows of
 * skin_bones.fdq_split), so sum w c = 2^16 H + L with H = sum w hi and
 * L = sum w lo. With weights (negated or not) whose magnitudes add up to
 * at most 2^15, |H| <= 2^30 and |L| < 2^31: both fit int32, as each
 * product does. And fx_shr_round(2^16 H + L, 15) = 2 H + (L + 2^14) >>
 * 15, 2^16 H being a multiple of 2^15. One component of four influences,
 * split rows q[k] weighted w[k]: */
static int32_t blend_component(const int32_t *const q[4], const int32_t w[4], int c)
{
	int32_t h = w[0] * q[0][c] + w[1] * q[1][c] + w[2] * q[2][c] + w[3] * q[3][c];
	int32_t l = w[0] * q[0][8 + c] + w[1] * q[1][8 + c] + w[2] * q[2][8 + c] + w[3] * q[3][8 + c];
	int32_t t = (l + (1 << 14)) >> 15; /* |t| <= 2^16 */
	if (h > -(1 << 30) + (1 << 16) && h < (1 << 30) - (1 << 16))
		return 2 * h + t; /* cannot leave int32 */
	return fx_sat32(2 * (int64_t)h + t);
}

static const int32_t *row(const skin_bones *b, int bone)
{
	return &b->fdq_split[bone][0][0];
}
#else
static const int32_t *row(const skin_bones *b, int bone)
{
	return (const int32_t *)&b->fdq[bone]; /* 8 int32, real then dual */
}
#endif

#if FX_NARROW_MUL
/* fx_quat_dot(a, p) < 0 (1 or 0), decided from the products of the high
 * halves where they are clear, else -1. The low halves move the dot by
 * less than 2^32 (sum |a hi| + sum |p hi| + 4) <= 2^32 (2^18 + 4), so
 * beyond that the high halves' sum A (the dot in units of 2^32) has its
 * sign. A is taken as 4 B + e, B the sum of the products shifted right by
 * 2 (each below 2^28 in magnitude: B fits int32) and e in [0, 12]. For
 * unit quaternions only bones within a thousandth of opposite rotations
 * are left undecided. */
static int opposite(const int32_t *a, const int32_t *p) /* the rows' high halves */
{
	const int32_t bound = (1 << 18) + 4; /* a multiple of 4 */
	int32_t b = (a[0] * p[0] >> 2) + (a[1] * p[1] >> 2) + (a[2] * p[2] >> 2) + (a[3] * p[3] >> 2);
	return b >= bound / 4 ? 0 : b <= (-bound - 12) / 4 ? 1 : -1;
}
#else
static int opposite(const int32_t *a, const int32_t *p)
{
	(void)a;
	(void)p;
	return -1; /* the exact dot costs as little */
}
#endif

/* fx_dq_blend's weights with its sign fix: negated where the bone's real
 * part has a negative dot product with the pivot's. An unused slot
 * (weight 0) needs no test. */
static void signed_weights(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES],
			   const int32_t *const rows[SKP_MAX_INFLUENCES], const fx_w15 w[SKP_MAX_INFLUENCES],
			   int32_t sw[SKP_MAX_INFLUENCES])
{
	sw[0] = w[0];
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		int flip = w[k] ? opposite(rows[k], rows[0]) : 0;
		if (flip < 0)
			flip = fx_quat_dot(b->fdq[idx[k]].real, b->fdq[idx[0]].real) < 0;
		sw[k] = flip ? -(int32_t)w[k] : (int32_t)w[k];
	}
}

#if !FX_NARROW_MUL
/* The kernel of a core with a 32 x 32 -> 64 multiply-add (a Cortex-M4's
 * SMLAL, x86-64's IMUL): every sum a chain of multiply-adds, and each
 * result's range checked where the definition would saturate (a vertex
 * for which any check fails is done again by the definition). The
 * numbers are the definition's: fx_dq_blend, then fx_dq_transform_blend. */

/* The high word of a sum: its value x >> k fits int32 exactly when
 * (high word + 2^(k-33)) is below 2^(k-32) as uint32. */
static inline uint32_t high(int64_t x)
{
	return (uint32_t)((uint64_t)x >> 32);
}

/* x >> k for 32 < k < 64 from the two words, x below 2^(31+k) */
#define SHR64(x, k) ((int32_t)(((uint32_t)(uint64_t)(x) >> (k)) | (high(x) << (32 - (k)))))

#if defined(__ARM_FEATURE_DSP) && defined(__thumb2__)
/* ARMv7E-M (Cortex-M4): wide_blend as the C version below (there the
 * comment), by hand: GCC 12 spills the rows or the weights of that C and
 * moves each sum between register pairs. Here every product is one load
 * and one SMLAL, and the range check one SSAT of the high word, whose Q
 * flag collects them: set when a high word leaves [-2^14, 2^14), so the
 * function returns 0 when every sum fits. */
#define WIDE_SUM(c)                                                                                \
	"ldr %[t0], [%[q0], #4*" #c "]\n\t"                                                      \
	"ldr %[t1], [%[q1], #4*" #c "]\n\t"                                                      \
	"mov %[lo], #16384\n\t"                                                                  \
	"mov %[hi], #0\n\t"                                                                      \
	"smlal %[lo], %[hi], %[t0], %[w0]\n\t"                                                   \
	"ldr %[t0], [%[q2], #4*" #c "]\n\t"                                                      \
	"smlal %[lo], %[hi], %[t1], %[w1]\n\t"                                                   \
	"ldr %[t1], [%[q3], #4*" #c "]\n\t"                                                      \
	"smlal %[lo], %[hi], %[t0], %[w2]\n\t"                                                   \
	"smlal %[lo], %[hi], %[t1], %[w3]\n\t"                                                   \
	"lsrs %[lo], %[lo], #15\n\t"                                                             \
	"orr %[lo], %[lo], %[hi], lsl #17\n\t"                                                   \
	"ssat %[t0], #15, %[hi]\n\t"                                                             \
	"str %[lo], [%[d], #4*" #c "]\n\t"

__attribute__((noinline)) static uint32_t wide_blend(const int32_t *q0, const int32_t *q1, const int32_t *q2,
						     const int32_t *q3, int32_t w0, int32_t w1, int32_t w2, int32_t w3,
						     int32_t d[8])
{
	uint32_t lo, hi, t0, t1;
	__asm__("mov %[t0], #0\n\t"
		"msr APSR_nzcvq, %[t0]\n\t" /* Q cleared */
		WIDE_SUM(0) WIDE_SUM(1) WIDE_SUM(2) WIDE_SUM(3) WIDE_SUM(4) WIDE_SUM(5) WIDE_SUM(6) WIDE_SUM(7)
		"mrs %[t0], APSR\n\t"
		"and %[t0], %[t0], #1 << 27\n\t" /* Q */
		: [lo] "=&r"(lo), [hi] "=&r"(hi), [t0] "=&r"(t0), [t1] "=&r"(t1)
		: [q0] "r"(q0), [q1] "r"(q1), [q2] "r"(q2), [q3] "r"(q3), [w0] "r"(w0), [w1] "r"(w1), [w2] "r"(w2),
		  [w3] "r"(w3), [d] "r"(d)
		: "cc", "memory");
	(void)lo;
	(void)hi;
	(void)t1;
	return t0; /* 0 when every sum fits */
}

/* The same for two influences (the others' weights 0) */
#define WIDE_SUM2(c)                                                                               \
	"ldr %[t0], [%[q0], #4*" #c "]\n\t"                                                      \
	"ldr %[t1], [%[q1], #4*" #c "]\n\t"                                                      \
	"mov %[lo], #16384\n\t"                                                                  \
	"mov %[hi], #0\n\t"                                                                      \
	"smlal %[lo], %[hi], %[t0], %[w0]\n\t"                                                   \
	"smlal %[lo], %[hi], %[t1], %[w1]\n\t"                                                   \
	"lsrs %[lo], %[lo], #15\n\t"                                                             \
	"orr %[lo], %[lo], %[hi], lsl #17\n\t"                                                   \
	"ssat %[t0], #15, %[hi]\n\t"                                                             \
	"str %[lo], [%[d], #4*" #c "]\n\t"

__attribute__((noinline)) static uint32_t wide_blend2(const int32_t *q0, const int32_t *q1, int32_t w0, int32_t w1,
						      int32_t d[8])
{
	uint32_t lo, hi, t0, t1;
	__asm__("mov %[t0], #0\n\t"
		"msr APSR_nzcvq, %[t0]\n\t"
		WIDE_SUM2(0) WIDE_SUM2(1) WIDE_SUM2(2) WIDE_SUM2(3) WIDE_SUM2(4) WIDE_SUM2(5) WIDE_SUM2(6) WIDE_SUM2(7)
		"mrs %[t0], APSR\n\t"
		"and %[t0], %[t0], #1 << 27\n\t"
		: [lo] "=&r"(lo), [hi] "=&r"(hi), [t0] "=&r"(t0), [t1] "=&r"(t1)
		: [q0] "r"(q0), [q1] "r"(q1), [w0] "r"(w0), [w1] "r"(w1), [d] "r"(d)
		: "cc", "memory");
	(void)lo;
	(void)hi;
	(void)t1;
	return t0;
}
#else
/* fx_dq_blend's rounded sums of the rows q0..q3 weighted w0..w3 into d;
 * 0 when every one fits int32 (else fx_dq_blend saturates: the vertex
 * goes to it). Out of line, with nothing else live, so that the rows, the
 * weights and a sum stay in registers. */
__attribute__((noinline)) static uint32_t wide_blend(const int32_t *q0, const int32_t *q1, const int32_t *q2,
						     const int32_t *q3, int32_t w0, int32_t w1, int32_t w2, int32_t w3,
						     int32_t d[8])
{
	uint32_t chk = 0;
	for (int c = 0; c < 8; c++) {
		int64_t t = ((int64_t)1 << 14) + (int64_t)w0 * q0[c] + (int64_t)w1 * q1[c] + (int64_t)w2 * q2[c] +
			    (int64_t)w3 * q3[c];
		chk |= high(t) + (1u << 14);
		d[c] = SHR64(t, 15);
	}
	return chk >> 15;
}

static uint32_t wide_blend2(const int32_t *q0, const int32_t *q1, int32_t w0, int32_t w1, int32_t d[8])
{
	return wide_blend(q0, q1, q0, q1, w0, w1, 0, 0, d);
}
#endif

/* (x + 2^29) >> 30 and friends of fx_recip_q60, for 1 <= hi < 2^29 where
 * x = hi 2^32 + lo is the blend's squared norm s in Q60: returns sh =
 * 32 - clz(hi) and 2 / s = *inv / 2^sh, step for step fx_blend_scale
 * (e = clz64(s) - 3 = 29 - sh, the top 31 bits cut, the seed line, the
 * Newton steps). */
static inline int wide_scale(uint32_t hi, uint32_t lo, uint32_t *inv)
{
	int z = __builtin_clz(hi); /* 3..31 */
	uint32_t xq = (lo >> (33 - z)) | (hi << (z - 1));
	int s = (int)(xq >> 27) - 8;
	uint32_t y = fx_recip_seed_a[s] - (uint32_t)(((uint64_t)fx_recip_seed_b[s] * xq + (1u << 29)) >> 30);
	for (int i = 0; i < FX_RECIP_STEPS; i++) {
		uint32_t xy = (uint32_t)(((uint64_t)xq * y + (1u << 29)) >> 30);
		y = (uint32_t)(((uint64_t)y * (0u - xy) + (1u << 30)) >> 31);
	}
	*inv = (y + 1) >> 1;
	return 32 - z;
}

/* v + (x 2^sh + b m) >> sh with the rounding r (2^(sh-1) or 0), 1 <= sh
 * <= 29; *chk collects the high word + 2^(sh-1), below 2^sh when it fits */
static inline int32_t wide_move(int32_t v, int32_t b, int32_t m, int32_t pw, int sh, uint32_t r, uint32_t half,
				uint32_t *chk)
{
	int64_t t = (int64_t)r + (int64_t)b * m + (int64_t)v * pw;
	*chk |= high(t) + half;
	return (int32_t)(((uint32_t)t >> sh) | (high(t) << (32 - sh)));
}

#if defined(__ARM_FEATURE_DSP) && defined(__thumb2__)
/* The sums of products by hand too (GCC 12 moves each 64-bit sum between
 * register pairs and spills the factors): start + sum of a_i b_i, then
 * >> 30, and the range check an SSAT of the high word into the Q flag
 * (set when the result leaves int32), which wide_ok reads once. end30 is
 * volatile: it stays between the flag's clearing and its reading. */
typedef struct wide_acc {
	uint32_t lo;
	int32_t hi;
} wide_acc;

static inline wide_acc acc_start(int64_t start)
{
	wide_acc a = { (uint32_t)start, (int32_t)(start >> 32) };
	return a;
}

/* a += a0 b0 (+ a1 b1): few operands an asm, so that GCC 12 finds them
 * registers however many values are live around it */
static inline void mac1(wide_acc *a, int32_t a0, int32_t b0)
{
	__asm__("smlal %[lo], %[hi], %[a0], %[b0]" : [lo] "+r"(a->lo), [hi] "+r"(a->hi) : [a0] "r"(a0), [b0] "r"(b0));
}

static inline void mac2(wide_acc *a, int32_t a0, int32_t b0, int32_t a1, int32_t b1)
{
	__asm__("smlal %[lo], %[hi], %[a0], %[b0]\n\tsmlal %[lo], %[hi], %[a1], %[b1]"
		: [lo] "+r"(a->lo), [hi] "+r"(a->hi)
		: [a0] "r"(a0), [b0] "r"(b0), [a1] "r"(a1), [b1] "r"(b1));
}

/* a >> 30, the high word saturated to 30 bits into the Q flag (set when
 * the result leaves int32) */
static inline int32_t end30(wide_acc a)
{
	__asm__ volatile("lsrs %[lo], %[lo], #30\n\torr %[lo], %[lo], %[hi], lsl #2\n\tssat %[hi], #30, %[hi]"
			 : [lo] "+r"(a.lo), [hi] "+r"(a.hi)
			 :
			 : "cc");
	return (int32_t)a.lo;
}

static inline int32_t sum4(uint32_t *c30, int64_t start, int32_t a0, int32_t b0, int32_t a1, int32_t b1, int32_t a2,
			   int32_t b2, int32_t a3, int32_t b3)
{
	wide_acc a = acc_start(start);
	(void)c30; /* the Q flag instead */
	mac2(&a, a0, b0, a1, b1);
	mac2(&a, a2, b2, a3, b3);
	return end30(a);
}

static inline int32_t sum3(uint32_t *c30, int64_t start, int32_t a0, int32_t b0, int32_t a1, int32_t b1, int32_t a2,
			   int32_t b2)
{
	wide_acc a = acc_start(start);
	(void)c30;
	mac2(&a, a0, b0, a1, b1);
	mac1(&a, a2, b2);
	return end30(a);
}

static inline int32_t sum2(uint32_t *c30, int32_t a0, int32_t b0, int32_t a1, int32_t b1)
{
	wide_acc a;
	(void)c30;
	__asm__("smull %[lo], %[hi], %[a0], %[b0]" : [lo] "=&r"(a.lo), [hi] "=&r"(a.hi) : [a0] "r"(a0), [b0] "r"(b0));
	mac1(&a, a1, b1);
	return end30(a);
}

#define WIDE_CHECK_START(c30) __asm__ volatile("msr APSR_nzcvq, %0" : : "r"(0) : "cc")

static inline int wide_ok(uint32_t c30)
{
	uint32_t apsr;
	(void)c30;
	__asm__ volatile("mrs %0, APSR" : "=r"(apsr));
	return !(apsr & 1u << 27);
}
#else
/* start + sum of a_i b_i, then >> 30, exact (the definition's int64 sum);
 * *c30 collects the high words + 2^29, below 2^30 while each result fits
 * int32 (wide_ok). */
static inline int32_t sum4(uint32_t *c30, int64_t start, int32_t a0, int32_t b0, int32_t a1, int32_t b1, int32_t a2, int32_t b2,
			   int32_t a3, int32_t b3)
{
	int64_t t = start + (int64_t)a0 * b0 + (int64_t)a1 * b1 + (int64_t)a2 * b2 + (int64_t)a3 * b3;
	*c30 |= high(t) + (1u << 29);
	return SHR64(t, 30);
}

static inline int32_t sum3(uint32_t *c30, int64_t start, int32_t a0, int32_t b0, int32_t a1, int32_t b1, int32_t a2, int32_t b2)
{
	return sum4(c30, start, a0, b0, a1, b1, a2, b2, 0, 0);
}

static inline int32_t sum2(uint32_t *c30, int32_t a0, int32_t b0, int32_t a1, int32_t b1)
{
	return sum4(c30, 0, a0, b0, a1, b1, 0, 0, 0, 0);
}

#define WIDE_CHECK_START(c30) ((void)(c30))

static inline int wide_ok(uint32_t c30)
{
	return c30 >> 30 == 0;
}
#endif

/* The moves of wide_move_blend by 2 / s = inv / 2^sh: inlined with sh a
 * constant for the usual blends (s in [2^59, 2^61): sh 28 or 29), where
 * the shifts take immediates and free three registers. */
__attribute__((always_inline)) static inline int wide_apply(const int32_t d[8], const fx_vec3 *p, const fx_vec3 *n,
							   int32_t *po, int32_t *no, uint32_t inv, int sh)
{
	int32_t m = (int32_t)inv, pw = (int32_t)1 << sh;
	/* hidden from GCC, which knowing them positive would build b m from
	 * an unsigned multiply and a correction instead of one SMLAL */
	__asm__("" : "+r"(m), "+r"(pw));
	const uint32_t half = 1u << (sh - 1);
	const int32_t w = d[0], rx = d[1], ry = d[2], rz = d[3];
	const int32_t nrx = -rx, nry = -ry, nrz = -rz, dw = d[4], dx = d[5], dy = d[6], dz = d[7];
	const int64_t rnd = (int64_t)1 << 29;
	uint32_t cm = 0, c30 = 0; /* high words + half, below 2^sh when they fit; c30: sum4 */
	WIDE_CHECK_START(c30);
	/* a = r x p + w p + dv, b = r x a + w dv - dw r */
	const int32_t ax = sum3(&c30, (int64_t)dx * (1 << 30) + rnd, ry, p->z, nrz, p->y, w, p->x);
	const int32_t ay = sum3(&c30, (int64_t)dy * (1 << 30) + rnd, rz, p->x, nrx, p->z, w, p->y);
	const int32_t az = sum3(&c30, (int64_t)dz * (1 << 30) + rnd, rx, p->y, nry, p->x, w, p->z);
	const int32_t bx = sum4(&c30, rnd, ry, az, nrz, ay, w, dx, nrx, dw);
	const int32_t by = sum4(&c30, rnd, rz, ax, nrx, az, w, dy, nry, dw);
	const int32_t bz = sum4(&c30, rnd, rx, ay, nry, ax, w, dz, nrz, dw);
	po[0] = wide_move(p->x, bx, m, pw, sh, half, half, &cm);
	po[1] = wide_move(p->y, by, m, pw, sh, half, half, &cm);
	po[2] = wide_move(p->z, bz, m, pw, sh, half, half, &cm);
	/* the normal: a = r x n + w n, b = r x a, cut instead of rounded */
	const int32_t nax = sum3(&c30, 0, ry, n->z, nrz, n->y, w, n->x);
	const int32_t nay = sum3(&c30, 0, rz, n->x, nrx, n->z, w, n->y);
	const int32_t naz = sum3(&c30, 0, rx, n->y, nry, n->x, w, n->z);
	no[0] = q30_to_q16(wide_move(n->x, sum2(&c30, ry, naz, nrz, nay), m, pw, sh, 0, half, &cm));
	no[1] = q30_to_q16(wide_move(n->y, sum2(&c30, rz, nax, nrx, naz), m, pw, sh, 0, half, &cm));
	no[2] = q30_to_q16(wide_move(n->z, sum2(&c30, rx, nay, nry, nax), m, pw, sh, 0, half, &cm));
	return wide_ok(c30) && cm >> sh == 0;
}

/* fx_dq_transform_blend of the blend d, when none of its steps saturates
 * (1; else 0 and the caller runs the definition). With s = |real|^2
 * below 2^61 (else the definition leaves p and n as they are) every real
 * component is below 2^30.5 in magnitude, so its negation is exact and
 * every sum below is the definition's int64 sum, exactly (fixed_move.c). */
__attribute__((noinline)) static int wide_move_blend(const int32_t d[8], const fx_vec3 *p, const fx_vec3 *n,
						     int32_t *po, int32_t *no)
{
	const int32_t w = d[0], rx = d[1], ry = d[2], rz = d[3];
	/* s modulo 2^64: the definition saturates it only past 2^64, and
	 * reads 2^61 and more (and 2^64, here 0) as "leave them" */
	uint64_t s = (uint64_t)((int64_t)w * w) + (uint64_t)((int64_t)rx * rx) + (uint64_t)((int64_t)ry * ry) +
		     (uint64_t)((int64_t)rz * rz);
	uint32_t hi = (uint32_t)(s >> 32);
	if (hi - 1 >= (1u << 29) - 1) { /* hi = 0 (sh < 1) or s >= 2^61 */
		po[0] = p->x; po[1] = p->y; po[2] = p->z;
		no[0] = q30_to_q16(n->x); no[1] = q30_to_q16(n->y); no[2] = q30_to_q16(n->z);
		return 1;
	}
	uint32_t inv;
	const int sh = wide_scale(hi, (uint32_t)s, &inv);
	if (sh == 28)
		return wide_apply(d, p, n, po, no, inv, 28);
	if (sh == 29)
		return wide_apply(d, p, n, po, no, inv, 29);
	return wide_apply(d, p, n, po, no, inv, sh);
}

/* One vertex: positions out as they are (Q16.16), normals in Q16 */
static void wide_vertex(const skin_bones *b, const uint16_t idx[4], const fx_w15 wt[4], const fx_vec3 *p,
			const fx_vec3 *n, int32_t *po, int32_t *no)
{
	const int32_t *r0 = row(b, idx[0]);
	if (wt[0] == FX_W15_ONE && (wt[1] | wt[2] | wt[3]) == 0) {
		/* one bone: (c 2^15 + 2^14) >> 15 = c, the blend is its row */
		if (wide_move_blend(r0, p, n, po, no))
			return;
	} else if ((uint32_t)wt[0] + wt[1] + wt[2] + wt[3] <= FX_W15_ONE) {
		const int32_t *const rows[4] = { r0, row(b, idx[1]), row(b, idx[2]), row(b, idx[3]) };
		int32_t sw[4], d[8];
		signed_weights(b, idx, rows, wt, sw);
		/* the unused slots (weight 0) left out of the sums: they add 0 */
		uint32_t over = (wt[2] | wt[3]) == 0 ? wide_blend2(rows[0], rows[1], sw[0], sw[1], d)
						      : wide_blend(rows[0], rows[1], rows[2], rows[3], sw[0], sw[1],
								   sw[2], sw[3], d);
		if (over == 0 && wide_move_blend(d, p, n, po, no))
			return;
	}
	fx_dq q = fx_dq_blend(b->fdq, idx, wt, SKP_MAX_INFLUENCES, b->fdq[idx[0]].real);
	fx_vec3 pp, nn;
	fx_dq_transform_blend(&q, *p, *n, &pp, &nn);
	po[0] = pp.x; po[1] = pp.y; po[2] = pp.z;
	no[0] = q30_to_q16(nn.x); no[1] = q30_to_q16(nn.y); no[2] = q30_to_q16(nn.z);
}

_Static_assert(FX_POS_FRAC == 16, "the wide kernel writes positions as they are");
#define FIXED_VERTEX wide_vertex
#else
static int32_t pos_to_q16(fx_pos v)
{
	return (int32_t)((int64_t)v * (1 << (16 - FX_POS_FRAC)));
}

/* fx_dq_blend(b->fdq, idx, w, 4, pivot) for weights summing to at most 1;
 * 0 (and d untouched) when they do not. */
static int blend(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES], const fx_w15 w[SKP_MAX_INFLUENCES],
		 fx_dq *d)
{
	_Static_assert(SKP_MAX_INFLUENCES == 4 && sizeof(fx_dq) == 8 * sizeof(int32_t), "a row of 8 int32");
	if ((uint32_t)w[0] + w[1] + w[2] + w[3] > FX_W15_ONE)
		return 0;
	const int32_t *const rows[4] = { row(b, idx[0]), row(b, idx[1]), row(b, idx[2]), row(b, idx[3]) };
	int32_t sw[4], r[8];
	signed_weights(b, idx, rows, w, sw);
	for (int c = 0; c < 8; c++) /* one call site: inlined */
		r[c] = blend_component(rows, sw, c);
	fx_dq out = { { r[0], r[1], r[2], r[3] }, { r[4], r[5], r[6], r[7] } };
	*d = out;
	return 1;
}

/* One vertex, as wide_vertex (the Cortex-M0's form) */
static void narrow_vertex(const skin_bones *b, const uint16_t idx[4], const fx_w15 w[4], const fx_vec3 *p,
			  const fx_vec3 *n, int32_t *po, int32_t *no)
{
	fx_dq d;
	if (!blend(b, idx, w, &d))
		d = fx_dq_blend(b->fdq, idx, w, SKP_MAX_INFLUENCES, b->fdq[idx[0]].real);
	fx_vec3 pp, nn;
	fx_dq_transform_blend(&d, *p, *n, &pp, &nn);
	po[0] = pos_to_q16(pp.x); po[1] = pos_to_q16(pp.y); po[2] = pos_to_q16(pp.z);
	no[0] = q30_to_q16(nn.x); no[1] = q30_to_q16(nn.y); no[2] = q30_to_q16(nn.z);
}
#define FIXED_VERTEX narrow_vertex
#endif

void skin_dqbs_fixed(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v++) {
		uint16_t idx[SKP_MAX_INFLUENCES];
		fx_w15 w[SKP_MAX_INFLUENCES];
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			idx[k] = in->bone[k][v];
			w[k] = in->fweight[k][v];
		}
		const fx_vec3 p = { in->fpx[v], in->fpy[v], in->fpz[v] }, n = { in->fnx[v], in->fny[v], in->fnz[v] };
		FIXED_VERTEX(b, idx, w, &p, &n, out->fpos + 3 * v, out->fnrm + 3 * v);
	}
}

