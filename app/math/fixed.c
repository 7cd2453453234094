/* Integer-only: tests/check_fixed_integer.sh builds this file with the FPU
 * registers disabled. Overflow bounds are argued in fixed.h. */
#include "fixed.h"

#include <stddef.h>

static const fx_quat fx_quat_identity = { FX_Q30_ONE, 0, 0, 0 };

/* Hamilton product with every component summed exactly and rounded once by
 * 2^s; int64 results so callers can add two products before saturating. */
static void qmul_shr(fx_quat a, fx_quat b, int s, int64_t r[4])
{
	r[0] = fx_shr_round(fx_mul_wide(a.w, b.w) - fx_mul_wide(a.x, b.x) - fx_mul_wide(a.y, b.y) -
			    fx_mul_wide(a.z, b.z), s);
	r[1] = fx_shr_round(fx_mul_wide(a.w, b.x) + fx_mul_wide(a.x, b.w) + fx_mul_wide(a.y, b.z) -
			    fx_mul_wide(a.z, b.y), s);
	r[2] = fx_shr_round(fx_mul_wide(a.w, b.y) - fx_mul_wide(a.x, b.z) + fx_mul_wide(a.y, b.w) +
			    fx_mul_wide(a.z, b.x), s);
	r[3] = fx_shr_round(fx_mul_wide(a.w, b.z) + fx_mul_wide(a.x, b.y) - fx_mul_wide(a.y, b.x) +
			    fx_mul_wide(a.z, b.w), s);
}

static fx_quat quat_sat(const int64_t r[4])
{
	fx_quat q = { fx_sat32(r[0]), fx_sat32(r[1]), fx_sat32(r[2]), fx_sat32(r[3]) };
	return q;
}

fx_quat fx_quat_mul(fx_quat a, fx_quat b)
{
	int64_t r[4];

	qmul_shr(a, b, 30, r);
	return quat_sat(r);
}

fx_vec3 fx_quat_rotate(fx_quat q, fx_vec3 v)
{
	/* a = u x v + w v: each sum uses three components of the unit q once,
	 * whose magnitudes add up to at most sqrt(3): below sqrt(3) 2^61, and
	 * |a_i| < sqrt(3) 2^31 after the shift. */
	int64_t ax = fx_shr_round((int64_t)q.y * v.z - (int64_t)q.z * v.y +
				  (int64_t)q.w * v.x, 30);
	int64_t ay = fx_shr_round((int64_t)q.z * v.x - (int64_t)q.x * v.z +
				  (int64_t)q.w * v.y, 30);
	int64_t az = fx_shr_round((int64_t)q.x * v.y - (int64_t)q.y * v.x +
				  (int64_t)q.w * v.z, 30);
	/* 2 u x a: two components of q (|sum| <= sqrt(2) 2^30) times |a_i|:
	 * below sqrt(6) 2^61 < 2^62.3. The factor 2 goes into the shift (29)
	 * so it costs no precision. */
	fx_vec3 r = {
		fx_sat32(v.x + fx_shr_round(q.y * az - q.z * ay, 29)),
		fx_sat32(v.y + fx_shr_round(q.z * ax - q.x * az, 29)),
		fx_sat32(v.z + fx_shr_round(q.x * ay - q.y * ax, 29)),
	};
	return r;
}

/* Shift-and-subtract square root; leaves x - floor(sqrt(x))^2 in *rem. */
static uint64_t isqrt_rem(uint64_t x, uint64_t *rem)
{
	uint64_t r = 0, bit = (uint64_t)1 << 62;

	while (bit > x)
		bit >>= 2;
	while (bit) {
		if (x >= r + bit) {
			x -= r + bit;
			r = (r >> 1) + bit;
		} else {
			r >>= 1;
		}
		bit >>= 2;
	}
	*rem = x;
	return r;
}

uint32_t fx_isqrt64(uint64_t x)
{
	uint64_t rem;

	return (uint32_t)isqrt_rem(x, &rem);
}

static uint64_t rsqrt_step(uint64_t xq, uint64_t y)
{
	uint64_t y2 = (y * y + (1u << 30)) >> 31;          /* Q31, < 2^32 */
	uint64_t half_xy2 = (xq * y2 + (1u << 30)) >> 31;  /* X y^2 / 2 in Q31, < 2^32 */
	uint64_t three_halves = (uint64_t)3 << 30;         /* 1.5 in Q31 */
	uint64_t f = three_halves > half_xy2 ? three_halves - half_xy2 : 0;
	return (y * f + (1u << 30)) >> 31;                 /* y, f < 2^32 */
}

/* Per segment [p, q] of X: the line through 1/sqrt at p and q, moved half
 * way to the tangent of the same slope (equal error at the ends and in the
 * middle). */
static const uint32_t rsqrt_seed_a[8] = {
	3049607619u, 2754682106u, 2531942015u, 2355946473u,
	2156398227u, 1947854397u, 1790353369u, 1665905727u,
};
static const uint32_t rsqrt_seed_b[8] = {
	906863524u, 669418843u, 520272022u, 419379203u,
	320624674u, 236675302u, 183943938u, 148272939u,
};

/* xq = X in Q30, X in [1, 4): [1, 2) in quarters, then [2, 4) in halves */
static uint64_t rsqrt_seed(uint64_t xq)
{
	int s = xq >> 31 ? (int)(xq >> 29) : (int)(xq >> 28) - 4;
	return rsqrt_seed_a[s] - (((uint64_t)rsqrt_seed_b[s] * xq + (1u << 29)) >> 30);
}

uint32_t fx_rsqrt_q60(uint64_t x, int *shift)
{
	*shift = 0;
	if (x == 0 || x >= (uint64_t)1 << 62)
		return 0;
	/* Scale by 4^e into [2^60, 2^62): X = x / 2^60 in [1, 4). */
	int e = (__builtin_clzll(x) - 2) / 2;
	x <<= 2 * e;
	uint64_t xq = x >> 30; /* floor: below 2^32, as the SIMD multiplies need */
	uint64_t y = rsqrt_seed(xq);
	for (int i = 0; i < 2; i++)
		y = rsqrt_step(xq, y);
	/* 1/sqrt(x / 2^60) before scaling is 2^e / sqrt(X) = y / 2^(31 - e) */
	*shift = 31 - e;
	return y > INT32_MAX ? INT32_MAX : (uint32_t)y;
}

/* Per segment [p, q] of X, as for the rsqrt seed: the chord of 1/X moved
 * half way to the tangent of the same slope. */
const uint32_t fx_recip_seed_a[FX_RECIP_SEGMENTS] = {
	4052846001u, 3624347854u, 3277932859u, 2992046706u,
	2752082450u, 2547787585u, 2371752666u, 2218489005u,
};
const uint32_t fx_recip_seed_b[FX_RECIP_SEGMENTS] = {
	1908874354u, 1527099483u, 1249445032u, 1041204193u,
	881018933u, 755159085u, 654471207u, 572662306u,
};

/* (x << e) >> 30 for 0 < x < 2^61, e = clz(x) - 3 (into *e), from 32-bit
 * shifts: a 32-bit core shifts 64 bits by a variable through a call. */
static uint32_t top31(uint64_t x, int *e)
{
	uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
	*e = hi ? __builtin_clz(hi) - 3 : 29 + __builtin_clz(lo);
	if (*e > 30)
		return lo << (*e - 30); /* x below 2^30: hi is 0 */
	int k = 30 - *e;
	return k ? (lo >> k) | (hi << (32 - k)) : lo; /* k = 0: x below 2^31 */
}

uint32_t fx_recip_q60(uint64_t x, int *e)
{
	*e = 0;
	if (x == 0 || x >= (uint64_t)1 << 61)
		return 0;
	uint32_t xq = top31(x, e); /* X in Q30, below 2^31; x 2^e in [2^60, 2^61) */
	int s = (int)(xq >> 27) - 8;
	/* y stays below 2^32: the seed is at most a[0] < 2^32, and each step
	 * keeps it within 0.2% of 1 / X <= 1 (Q31); so X y is within 0.2% of
	 * 2^31 and 2^32 - X y below 2^32 */
	uint32_t y = fx_recip_seed_a[s] - (uint32_t)((fx_mulu_wide(fx_recip_seed_b[s], xq) + (1u << 29)) >> 30);
	for (int i = 0; i < FX_RECIP_STEPS; i++) {
		uint32_t xy = (uint32_t)((fx_mulu_wide(xq, y) + (1u << 29)) >> 30); /* X y in Q31 */
		y = (uint32_t)((fx_mulu_wide(y, 0u - xy) + (1u << 30)) >> 31);
	}
	return y;
}

fx_dq fx_dq_from_quat_trans(fx_quat q, fx_vec3 t)
{
	fx_quat tq = { 0, t.x, t.y, t.z };
	int64_t d[4];

	/* Shift 31 instead of 30: the 0.5 of dual = 0.5 t q. */
	qmul_shr(tq, q, 31, d);
	fx_dq r = { q, quat_sat(d) };
	return r;
}

fx_vec3 fx_dq_translation(const fx_dq *d)
{
	const fx_quat *r = &d->real, *u = &d->dual;
	/* vector part of 2 dual conj(real) = 2 (rw dv - dw rv + rv x dv); each
	 * sum uses every real component once: below 2 * 2^30 * 2^31. */
	int64_t tx = (int64_t)r->w * u->x - (int64_t)u->w * r->x +
		     (int64_t)r->y * u->z - (int64_t)r->z * u->y;
	int64_t ty = (int64_t)r->w * u->y - (int64_t)u->w * r->y +
		     (int64_t)r->z * u->x - (int64_t)r->x * u->z;
	int64_t tz = (int64_t)r->w * u->z - (int64_t)u->w * r->z +
		     (int64_t)r->x * u->y - (int64_t)r->y * u->x;
	fx_vec3 t = { fx_sat32(fx_shr_round(tx, 29)), fx_sat32(fx_shr_round(ty, 29)),
		      fx_sat32(fx_shr_round(tz, 29)) };
	return t;
}

fx_dq fx_dq_mul(const fx_dq *a, const fx_dq *b)
{
	int64_t rd[4], dr[4], sum[4];

	qmul_shr(a->real, b->dual, 30, rd);
	qmul_shr(a->dual, b->real, 30, dr);
	for (int i = 0; i < 4; i++)
		sum[i] = rd[i] + dr[i];
	fx_dq r = { fx_quat_mul(a->real, b->real), quat_sat(sum) };
	return r;
}

static int32_t scale_rs(int32_t c, uint32_t m, int shift)
{
	/* |c| <= 2^31 and m <= 2^31: the product is below 2^62. */
	return fx_sat32(fx_shr_round((int64_t)c * m, shift));
}

static fx_quat quat_scale_rs(fx_quat q, uint32_t m, int shift)
{
	fx_quat r = { scale_rs(q.w, m, shift), scale_rs(q.x, m, shift),
		      scale_rs(q.y, m, shift), scale_rs(q.z, m, shift) };
	return r;
}

/* |q|^2 in Q60, saturated: a blend whose weights sum past 1 (not what
 * skin_soa_load writes, but a caller may) can reach |q| = 2^32, whose
 * square does not fit; saturated, it is out of fx_rsqrt_q60's range like
 * any other norm too long. */
/* c[0]^2 + ... + c[3]^2 for components of at most 2^30.5. On ARMv6-M from
 * the halves c = h 2^16 + l, l in [0, 2^16): the squares of the high
 * halves (each below 2^29.1) sum in uint32, the h l products and the
 * squares of the low halves in 64 bits; elsewhere as it reads. */
static uint64_t sum_squares(const int32_t c[4])
{
#if FX_NARROW_MUL
	const int32_t h0 = c[0] >> 16, h1 = c[1] >> 16, h2 = c[2] >> 16, h3 = c[3] >> 16;
	const uint32_t l0 = (uint16_t)c[0], l1 = (uint16_t)c[1], l2 = (uint16_t)c[2], l3 = (uint16_t)c[3];
	uint32_t hh = (uint32_t)(h0 * h0) + (uint32_t)(h1 * h1) + (uint32_t)(h2 * h2) + (uint32_t)(h3 * h3);
	int64_t hl = (int64_t)(h0 * (int32_t)l0) + (int64_t)(h1 * (int32_t)l1) + (int64_t)(h2 * (int32_t)l2) +
		     (int64_t)(h3 * (int32_t)l3);
	uint64_t ll = (uint64_t)(l0 * l0) + (uint64_t)(l1 * l1) + (uint64_t)(l2 * l2) + (uint64_t)(l3 * l3);
	return ((uint64_t)hh << 32) + ((uint64_t)hl << 17) + ll;
#else
	return (uint64_t)(fx_mul_wide(c[0], c[0]) + fx_mul_wide(c[1], c[1]) + fx_mul_wide(c[2], c[2]) +
			  fx_mul_wide(c[3], c[3]));
#endif
}

static uint64_t quat_norm2_sat(fx_quat q)
{
	const int32_t c[4] = { q.w, q.x, q.y, q.z };
	const int32_t lim = 1518500249; /* floor(2^30.5): its square is below 2^61 */
	if (c[0] >= -lim && c[0] <= lim && c[1] >= -lim && c[1] <= lim && c[2] >= -lim && c[2] <= lim &&
	    c[3] >= -lim && c[3] <= lim) {
		/* the usual case, a blend of unit quaternions: the sum of four
		 * squares below 2^61 is below 2^63 */
		return sum_squares(c);
	}
	uint64_t sum = 0;
	for (int i = 0; i < 4; i++) {
		uint64_t sq = (uint64_t)fx_mul_wide(c[i], c[i]);
		sum = sum > UINT64_MAX - sq ? UINT64_MAX : sum + sq;
	}
	return sum;
}

fx_dq fx_dq_normalize(fx_dq d)
{
	int shift;
	uint32_t m = fx_rsqrt_q60(quat_norm2_sat(d.real), &shift);

	if (m == 0) {
		fx_dq id = { fx_quat_identity, { 0, 0, 0, 0 } };
		return id;
	}
	d.real = quat_scale_rs(d.real, m, shift);
	d.dual = quat_scale_rs(d.dual, m, shift);
	return d;
}

fx_vec3 fx_dq_transform_point(const fx_dq *d, fx_vec3 p)
{
	fx_vec3 r = fx_quat_rotate(d->real, p);
	fx_vec3 t = fx_dq_translation(d);
	fx_vec3 o = { fx_sat32((int64_t)r.x + t.x), fx_sat32((int64_t)r.y + t.y),
		      fx_sat32((int64_t)r.z + t.z) };
	return o;
}

fx_vec3 fx_dq_transform_normal(const fx_dq *d, fx_vec3 n)
{
	return fx_quat_rotate(d->real, n);
}

fx_quat fx_dq_blend_pivot(const fx_dq *bone_dqs, const uint16_t *bone_idx,
			  const fx_w15 *weights, int count)
{
	int best = 0;

	for (int i = 1; i < count; i++)
		if (weights[i] > weights[best])
			best = i;
	return count > 0 ? bone_dqs[bone_idx[best]].real : fx_quat_identity;
}

fx_dq fx_dq_blend(const fx_dq *bone_dqs, const uint16_t *bone_idx,
		  const fx_w15 *weights, int count, fx_quat pivot)
{
	/* Q45 for the real part, F+15 for the dual: each term is below
	 * 2^16 * 2^31 = 2^47, so even 65535 influences cannot overflow. */
	int64_t r[4] = { 0, 0, 0, 0 }, u[4] = { 0, 0, 0, 0 };

	for (int i = 0; i < count; i++) {
		const fx_dq *d = &bone_dqs[bone_idx[i]];
		/* q and -q are the same rotation: keep every influence on the
		 * pivot's hemisphere so the sum takes the short way round. */
		int32_t w = fx_quat_dot(d->real, pivot) < 0 ? -(int32_t)weights[i] : (int32_t)weights[i];

		r[0] += fx_mul_wide(w, d->real.w); r[1] += fx_mul_wide(w, d->real.x);
		r[2] += fx_mul_wide(w, d->real.y); r[3] += fx_mul_wide(w, d->real.z);
		u[0] += fx_mul_wide(w, d->dual.w); u[1] += fx_mul_wide(w, d->dual.x);
		u[2] += fx_mul_wide(w, d->dual.y); u[3] += fx_mul_wide(w, d->dual.z);
	}
	for (int k = 0; k < 4; k++) {
		r[k] = fx_shr_round(r[k], 15);
		u[k] = fx_shr_round(u[k], 15);
	}
	fx_dq b = { quat_sat(r), quat_sat(u) };
	return b;
}

int fx_blend_scale(fx_quat real, uint32_t *inv)
{
	int e;
	uint32_t y = fx_recip_q60(quat_norm2_sat(real), &e);
	/* 2 / s = y 2^(e + 1) / 2^31; sh >= 1 (a defined rounding shift)
	 * for s >= 2^-28 */
	int sh = 29 - e;

	*inv = 0;
	if (y == 0 || sh < 1)
		return 0;
	*inv = (y + 1) >> 1;
	return sh;
}
