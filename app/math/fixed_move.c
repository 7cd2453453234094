/* Moving a point and a normal by a blend of dual quaternions that is not
 * normalised (fx_dq_transform_blend, fixed.h): integer arithmetic only,
 * like fixed.c. Every intermediate the definition saturates almost never
 * needs it, so each vertex first takes a path that only checks that none
 * does (no saturation, every sum a chain of multiply-adds); the rare one
 * that does is done again by the definition itself. */
#include "fixed.h"

/* The sums below are each a dot product of (part of) the blend's real
 * part, shorter than 2^30.5 for s < 2, with at most 4 int32 values (at
 * most 2^32 long): below 2^62.5, and b inv below 2^61. They are written out
 * with 32-bit operands (fx_mul_wide), so that a 32-bit core multiplies
 * each pair once; the arithmetic is the one the SIMD kernels match. */

/* p + (2 / s) (r x (r x p + w p + dv) + w dv - dw r), rounded at each
 * shift. */
__attribute__((noinline)) static fx_vec3 point_saturated(const fx_dq *d, fx_vec3 p, uint32_t inv, int sh)
{
	const int32_t w = d->real.w, rx = d->real.x, ry = d->real.y, rz = d->real.z;
	const int32_t dw = d->dual.w, dx = d->dual.x, dy = d->dual.y, dz = d->dual.z;
	const int32_t m = (int32_t)inv; /* at most 2^30 */
	int32_t ax = fx_sat32(fx_shr_round(fx_mul_wide(ry, p.z) - fx_mul_wide(rz, p.y) + fx_mul_wide(w, p.x), 30) + dx);
	int32_t ay = fx_sat32(fx_shr_round(fx_mul_wide(rz, p.x) - fx_mul_wide(rx, p.z) + fx_mul_wide(w, p.y), 30) + dy);
	int32_t az = fx_sat32(fx_shr_round(fx_mul_wide(rx, p.y) - fx_mul_wide(ry, p.x) + fx_mul_wide(w, p.z), 30) + dz);
	int32_t bx = fx_sat32(fx_shr_round(fx_mul_wide(ry, az) - fx_mul_wide(rz, ay) + fx_mul_wide(w, dx) -
					   fx_mul_wide(dw, rx), 30));
	int32_t by = fx_sat32(fx_shr_round(fx_mul_wide(rz, ax) - fx_mul_wide(rx, az) + fx_mul_wide(w, dy) -
					   fx_mul_wide(dw, ry), 30));
	int32_t bz = fx_sat32(fx_shr_round(fx_mul_wide(rx, ay) - fx_mul_wide(ry, ax) + fx_mul_wide(w, dz) -
					   fx_mul_wide(dw, rz), 30));
	fx_vec3 o = { fx_sat32(p.x + fx_shr_round(fx_mul_wide(bx, m), sh)),
		      fx_sat32(p.y + fx_shr_round(fx_mul_wide(by, m), sh)),
		      fx_sat32(p.z + fx_shr_round(fx_mul_wide(bz, m), sh)) };
	return o;
}

/* n + (2 / s) r x (r x n + w n). The shifts cut instead of rounding (3
 * adds fewer per lane in the SIMD kernels): the normal leaves in Q16, 14
 * bits coarser than the Q30 it is moved in, which the cut's bias (under 2
 * LSB of Q30) does not reach. */
__attribute__((noinline)) static fx_vec3 normal_saturated(const fx_quat *q, fx_vec3 n, uint32_t inv, int sh)
{
	const int32_t w = q->w, rx = q->x, ry = q->y, rz = q->z, m = (int32_t)inv;
	int32_t ax = fx_sat32((fx_mul_wide(ry, n.z) - fx_mul_wide(rz, n.y) + fx_mul_wide(w, n.x)) >> 30);
	int32_t ay = fx_sat32((fx_mul_wide(rz, n.x) - fx_mul_wide(rx, n.z) + fx_mul_wide(w, n.y)) >> 30);
	int32_t az = fx_sat32((fx_mul_wide(rx, n.y) - fx_mul_wide(ry, n.x) + fx_mul_wide(w, n.z)) >> 30);
	int32_t bx = fx_sat32((fx_mul_wide(ry, az) - fx_mul_wide(rz, ay)) >> 30);
	int32_t by = fx_sat32((fx_mul_wide(rz, ax) - fx_mul_wide(rx, az)) >> 30);
	int32_t bz = fx_sat32((fx_mul_wide(rx, ay) - fx_mul_wide(ry, ax)) >> 30);
	fx_vec3 o = { fx_sat32(n.x + (fx_mul_wide(bx, m) >> sh)), fx_sat32(n.y + (fx_mul_wide(by, m) >> sh)),
		      fx_sat32(n.z + (fx_mul_wide(bz, m) >> sh)) };
	return o;
}

/* v as int32, *bad set when it does not fit (where the definition would
 * saturate). */
static inline int32_t fit(int64_t v, int *bad)
{
	*bad |= v != (int32_t)v;
	return (int32_t)v;
}

/* The fast path's sums of products. Each sum pairs factors of the blend's
 * real part (the first, r) with factors of what it moves (the second, v),
 * and is exact in int64 (below 2^62.5, see above). */
#if FX_NARROW_MUL
/* A Cortex-M0 multiplies 32 x 32 bits into 32 only. Each factor is split
 * once into halves, v = h 2^16 + l with l in [-2^15, 2^15), and a sum is
 * kept in parts, the products of high halves, the two kinds of mixed ones
 * and the low ones, put together once at the end. The first three fit
 * int32 within the bounds point_fast and normal_fast check (by Cauchy-
 * Schwarz: the r factors of a sum are at most 4 components of the real
 * part, whose length is below 2^30.5 since s < 2, so their high halves
 * are at most 2^14.5 + 1 long together, their low halves at most 2^16;
 * the v factors' high halves at most 2^15 + 2 long, their low halves
 * 2^16; so each part stays below 2^30.6); the low products, each up to
 * 2^30, are summed in 64 bits. */
typedef struct operand {
	int32_t h, l;
} operand;

static inline operand op(int32_t v)
{
	int32_t l = (int16_t)v;
	operand o = { (v - l) >> 16, l };
	return o;
}

static inline operand neg(operand a)
{
	operand o = { -a.h, -a.l };
	return o;
}

typedef struct parts {
	int32_t hh, hl, lh;
	int64_t ll;
} parts;

static inline void add(parts *s, operand r, operand v)
{
	s->hh += r.h * v.h;
	s->hl += r.h * v.l;
	s->lh += r.l * v.h;
	s->ll += r.l * v.l;
}

static inline int64_t total(int64_t start, const parts *s)
{
	uint64_t mid = (uint64_t)((int64_t)s->hl + s->lh);
	return (int64_t)((uint64_t)start + ((uint64_t)(int64_t)s->hh << 32) + (mid << 16) + (uint64_t)s->ll);
}

static inline int32_t sum4(int64_t start, operand r0, operand v0, operand r1, operand v1, operand r2, operand v2,
			   operand r3, operand v3, int *bad)
{
	parts s = { 0, 0, 0, 0 };
	add(&s, r0, v0);
	add(&s, r1, v1);
	add(&s, r2, v2);
	add(&s, r3, v3);
	return fit(total(start, &s) >> 30, bad);
}
#else
typedef int32_t operand;

static inline operand op(int32_t v)
{
	return v;
}

static inline operand neg(operand a)
{
	return -a;
}

static inline int32_t sum4(int64_t start, operand r0, operand v0, operand r1, operand v1, operand r2, operand v2,
			   operand r3, operand v3, int *bad)
{
	return fit((start + fx_mul_wide(r0, v0) + fx_mul_wide(r1, v1) + fx_mul_wide(r2, v2) + fx_mul_wide(r3, v3)) >> 30,
		   bad);
}
#endif

static inline int32_t sum3(int64_t start, operand r0, operand v0, operand r1, operand v1, operand r2, operand v2,
			   int *bad)
{
	const operand zero = op(0);
	return sum4(start, r0, v0, r1, v1, r2, v2, zero, zero, bad);
}

/* |v| <= limit for each component, where a Cortex-M0's parts need it. */
static inline int within(const int32_t *v, int n, int32_t limit)
{
	int ok = 1;
	for (int i = 0; i < n; i++)
		ok &= v[i] >= -limit && v[i] <= limit;
	return !FX_NARROW_MUL || ok;
}

/* v + (x >> sh) for 1 <= sh <= 29 from 32-bit shifts (a 64-bit shift by
 * a variable is a call or a dozen instructions on a 32-bit core); *bad
 * set when x >> sh or the sum leaves int32, where the definition's int64
 * sum might still fit: that rare vertex just takes the definition. */
static inline int32_t add_shifted(int32_t v, int64_t x, int sh, int *bad)
{
	uint32_t lo = (uint32_t)x;
	int32_t hi = (int32_t)(x >> 32);
	int32_t r = (int32_t)((lo >> sh) | ((uint32_t)hi << (32 - sh)));
	int32_t sum;
	*bad |= (hi >> sh) != (r < 0 ? -1 : 0);
	*bad |= __builtin_add_overflow(v, r, &sum);
	return sum;
}

/* point_saturated's result when no step of it saturates (else 0). The
 * subtracted products are added with a negated factor (INT32_MIN, which
 * has none, goes to the definition), and a sum's rounding and the dual
 * part it is followed by join it as its start: (S + 2^29) >> 30 + dv =
 * (dv 2^30 + 2^29 + S) >> 30, with S below 2^62.5 and dv 2^30 below 2^61.
 * The blend's parts are read where they are used, which keeps fewer of
 * them in registers at once. */
__attribute__((noinline)) static int point_fast(const fx_dq *d, fx_vec3 p, int32_t m, int sh, fx_vec3 *o)
{
	const fx_quat *r = &d->real, *u = &d->dual;
	if (r->x == INT32_MIN || r->y == INT32_MIN || r->z == INT32_MIN || u->w == INT32_MIN)
		return 0;
	if (!within(&p.x, 3, (1 << 28) - 1) || !within(&u->w, 4, (1 << 28) - 1))
		return 0;
	const int64_t half = (int64_t)1 << 29, one = (int64_t)1 << 30, round = (int64_t)1 << (sh - 1);
	const operand w = op(r->w), rx = op(r->x), ry = op(r->y), rz = op(r->z), nrx = neg(rx), nry = neg(ry),
		      nrz = neg(rz);
	const operand px = op(p.x), py = op(p.y), pz = op(p.z);
	int bad = 0;
	fx_vec3 a, b;
	a.x = sum3(u->x * one + half, ry, pz, nrz, py, w, px, &bad);
	a.y = sum3(u->y * one + half, rz, px, nrx, pz, w, py, &bad);
	a.z = sum3(u->z * one + half, rx, py, nry, px, w, pz, &bad);
	if (bad || !within(&a.x, 3, 1 << 30))
		return 0;
	const operand ax = op(a.x), ay = op(a.y), az = op(a.z), dw = op(u->w);
	b.x = sum4(half, ry, az, nrz, ay, w, op(u->x), nrx, dw, &bad);
	b.y = sum4(half, rz, ax, nrx, az, w, op(u->y), nry, dw, &bad);
	b.z = sum4(half, rx, ay, nry, ax, w, op(u->z), nrz, dw, &bad);
	o->x = add_shifted(p.x, fx_mul_wide(b.x, m) + round, sh, &bad);
	o->y = add_shifted(p.y, fx_mul_wide(b.y, m) + round, sh, &bad);
	o->z = add_shifted(p.z, fx_mul_wide(b.z, m) + round, sh, &bad);
	return !bad;
}

/* normal_saturated's result when no step of it saturates (else 0); the
 * real part's components are not INT32_MIN (point_fast checked). */
__attribute__((noinline)) static int normal_fast(const fx_quat *r, fx_vec3 n, int32_t m, int sh, fx_vec3 *o)
{
	if (!within(&n.x, 3, 1 << 30))
		return 0;
	const operand w = op(r->w), rx = op(r->x), ry = op(r->y), rz = op(r->z), nrx = neg(rx), nry = neg(ry),
		      nrz = neg(rz), zero = op(0);
	const operand nx = op(n.x), ny = op(n.y), nz = op(n.z);
	int bad = 0;
	fx_vec3 a, b;
	a.x = sum3(0, ry, nz, nrz, ny, w, nx, &bad);
	a.y = sum3(0, rz, nx, nrx, nz, w, ny, &bad);
	a.z = sum3(0, rx, ny, nry, nx, w, nz, &bad);
	if (bad || !within(&a.x, 3, 1400000000))
		return 0;
	const operand ax = op(a.x), ay = op(a.y), az = op(a.z);
	b.x = sum3(0, ry, az, nrz, ay, zero, zero, &bad);
	b.y = sum3(0, rz, ax, nrx, az, zero, zero, &bad);
	b.z = sum3(0, rx, ay, nry, ax, zero, zero, &bad);
	o->x = add_shifted(n.x, fx_mul_wide(b.x, m), sh, &bad);
	o->y = add_shifted(n.y, fx_mul_wide(b.y, m), sh, &bad);
	o->z = add_shifted(n.z, fx_mul_wide(b.z, m), sh, &bad);
	return !bad;
}

void fx_dq_transform_blend(const fx_dq *d, fx_vec3 p, fx_vec3 n, fx_vec3 *po, fx_vec3 *no)
{
	uint32_t inv;
	int sh = fx_blend_scale(d->real, &inv);

	if (sh == 0) {
		*po = p;
		*no = n;
		return;
	}
	if (point_fast(d, p, (int32_t)inv, sh, po) && normal_fast(&d->real, n, (int32_t)inv, sh, no))
		return;
	*po = point_saturated(d, p, inv, sh);
	*no = normal_saturated(&d->real, n, inv, sh);
}
