/* DQBS in fixed point with AVX2 integer instructions, eight vertices per
 * step, bit for bit the results of skin_fixed.c: the blend with 16-bit
 * multiply-adds on components split into 16-bit halves (blend_vertex), the
 * transform with the division by |real|^2 folded in (as
 * fx_dq_transform_blend) with 32x32->64 products (vpmuldq) on the even and
 * odd vertices in 64-bit lanes, each sum of products kept in 64 bits until
 * its one shift. No floating-point instruction: `make test` disassembles
 * this object to check (tests/check_simd_integer.sh). */
#include "skin_kernels.h"

#ifdef SKP_SIMD_AVX2

#include "skin_avx2_layout.h"

static __m256i load_weights(const fx_w15 *w, int v)
{
	return _mm256_cvtepu16_epi32(_mm_load_si128((const __m128i *)(w + v)));
}

/* Weights as 16-bit multiply-add operands: w01 holds the pair (w0, w1),
 * w23 (w2, w3); the sign fix flips the bones' rows instead (see blend).
 * Slot 0 (the pivot) may hold 32768, which int16 cannot: it enters as
 * w0 - 32768, and blend_vertex adds 32768 c / 2^15 = c after the rounding
 * (exact: c is an integer). Returns nonzero when a lane breaks what the
 * 16-bit products need and skin_soa_load guarantees (weights summing to
 * at most 1.0, a full weight only in slot 0): the caller then takes the
 * scalar path. */
static inline __attribute__((always_inline)) int blend_weights(const skin_soa *in, int v,
								int32_t w01[SKIN_LANES],
								int32_t w23[SKIN_LANES])
{
	const __m256i low16 = _mm256_set1_epi32(0xffff), full = _mm256_set1_epi32(FX_W15_ONE);
	__m256i bad = _mm256_setzero_si256(), sum = _mm256_setzero_si256(), w[SKP_MAX_INFLUENCES];
#pragma GCC unroll 8
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		__m256i x = load_weights(in->fweight[k], v);
		sum = _mm256_add_epi32(sum, x);
		if (k == 0)
			x = _mm256_sub_epi32(x, full);
		else
			bad = _mm256_or_si256(bad, _mm256_cmpeq_epi32(x, full));
		w[k] = x;
	}
	_mm256_store_si256((__m256i *)w01, _mm256_or_si256(_mm256_and_si256(w[0], low16), _mm256_slli_epi32(w[1], 16)));
	_mm256_store_si256((__m256i *)w23, _mm256_or_si256(_mm256_and_si256(w[2], low16), _mm256_slli_epi32(w[3], 16)));
	bad = _mm256_or_si256(bad, _mm256_cmpgt_epi32(sum, full));
	return !_mm256_testz_si256(bad, bad);
}

/* One vertex's blend, all eight components at once: a 16-bit unpack of two
 * bones' rows (see fdq_halves) pairs their low halves (and their high
 * halves) component by component, and one multiply-add with the pair of
 * weights sums both; the rows need no transpose (only the eight results
 * do, once). With c = hi 2^16 + lo, sum(w c) = 2^16 sum(w hi) + sum(w lo);
 * with the pivot's weight entering as w0 - 2^15, sum |w| <= 2^15 - w0 +
 * min(3 w0, 2^15 - w0) <= 1.5 2^15, so both sums and the rounding below
 * fit in 32 bits (nor can a multiply-add overflow: only w0 - 2^15 may be
 * -2^15). The rounded shift by 15 is then 2 sum(w hi) + round(sum(w lo) /
 * 2^15) + c0, exactly the scalar kernel's 64-bit result; 2 sum(w hi) may
 * wrap, but the total is that in-range result, and wrapping adds are exact
 * modulo 2^32. */
static inline __attribute__((always_inline)) __m256i blend_vertex(const int16_t *const row[SKP_MAX_INFLUENCES],
								  const fx_dq *pivot, int32_t w01,
								  int32_t w23)
{
	_Static_assert(SKP_MAX_INFLUENCES == 4, "blend_vertex pairs four influences");
	__m256i r[SKP_MAX_INFLUENCES];
#pragma GCC unroll 8
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		r[k] = _mm256_loadu_si256((const __m256i *)row[k]);
	__m256i wa = _mm256_set1_epi32(w01), wb = _mm256_set1_epi32(w23);
	__m256i lo = _mm256_add_epi32(_mm256_madd_epi16(_mm256_unpacklo_epi16(r[0], r[1]), wa),
				      _mm256_madd_epi16(_mm256_unpacklo_epi16(r[2], r[3]), wb));
	__m256i hi = _mm256_add_epi32(_mm256_madd_epi16(_mm256_unpackhi_epi16(r[0], r[1]), wa),
				      _mm256_madd_epi16(_mm256_unpackhi_epi16(r[2], r[3]), wb));
	__m256i sum = _mm256_add_epi32(_mm256_add_epi32(hi, hi),
				       _mm256_srai_epi32(_mm256_add_epi32(lo, _mm256_set1_epi32(1 << 14)), 15));
	return _mm256_add_epi32(sum, _mm256_loadu_si256((const __m256i *)pivot));
}

/* The blend of one batch from its weights (see blend_weights), each
 * bone's row negated where the sign fix says (fdq_at, per bone pair): the
 * same integers as the scalar kernel's negated weight, as w (-c) = (-w) c,
 * looked up per vertex where gathering the flips into lanes cost more. */
static inline __attribute__((always_inline)) void blend(const skin_soa *in, const skin_bones *b, int v,
							  const int32_t w01[SKIN_LANES],
							  const int32_t w23[SKIN_LANES], __m256i out[8])
{
	__m256 r[SKIN_LANES];
#pragma GCC unroll 8
	for (int j = 0; j < SKIN_LANES; j++) {
		const int16_t *row[SKP_MAX_INFLUENCES];
		int pivot = in->bone[0][v + j];
		const uint16_t *at = b->fdq_at[pivot];
		row[0] = b->fdq_halves[pivot][0];
#pragma GCC unroll 8
		for (int k = 1; k < SKP_MAX_INFLUENCES; k++)
			row[k] = (const int16_t *)((const char *)b->fdq_halves + at[in->bone[k][v + j]]);
		r[j] = _mm256_castsi256_ps(blend_vertex(row, &b->fdq[pivot], w01[j], w23[j]));
	}
	skin_transpose8(r);
#pragma GCC unroll 8
	for (int c = 0; c < 8; c++)
		out[c] = _mm256_castps_si256(r[c]);
}

static inline __m256i epi64(long long v)
{
	return _mm256_set1_epi64x(v);
}

/* (a * b + 2^(s-1)) >> s on 4 unsigned 64-bit lanes holding 32-bit values */
static inline __m256i mul_round(__m256i a, __m256i b, int s)
{
	return _mm256_srl_epi64(_mm256_add_epi64(_mm256_mul_epu32(a, b), epi64(1ll << (s - 1))),
				_mm_cvtsi32_si128(s));
}

/* fx_blend_scale on 4 lanes (fx_recip_q60 step for step the same
 * integers) for squared norms in [2^56, 2^60 + 2^55]: every blend with the
 * sign fix whose weights sum to at most 1 (its real part is at least the
 * pivot's weight, 1/4, and at most as long as the longest bone's). A
 * bone's quaternion comes from float and may be longer than 1 by float's
 * rounding (|q|^2 = 1 + 2^-22 is 2^60 + 2^38 here): a vertex on one bone
 * has exactly that blend, so the bound must leave room for it (at 2^60 +
 * 2^32 a third of a real body's batches fell to the scalar kernel). Up to
 * |real| < 1.016 the vector norms bound move4's intermediates below 2^30.82
 * (|r x v + w v| <= |real| |v|), still in int32. In stages (seed, Newton
 * steps, scale) so that chunk_norms can run each stage over a whole
 * chunk: one reciprocal is a chain of dependent multiplies, and the core
 * only overlaps chains that are close together in the instruction stream.
 * The seed replaces x by X in Q30 and *e_sh by e, and flags lanes outside
 * the range in *bad. */
static inline __attribute__((always_inline)) __m256i recip_seed4(__m256i *x, __m256i *e_sh, __m256i *bad)
{
	__m256i below = _mm256_setzero_si256();
#pragma GCC unroll 4
	for (int bit = 57; bit <= 60; bit++)
		below = _mm256_add_epi64(below, _mm256_cmpgt_epi64(epi64(1ll << bit), *x));
	*bad = _mm256_or_si256(_mm256_cmpgt_epi64(epi64(1ll << 56), *x),
			       _mm256_cmpgt_epi64(*x, epi64((1ll << 60) + (1ll << 55))));
	__m256i e = _mm256_sub_epi64(_mm256_setzero_si256(), below); /* x 2^e in [2^60, 2^61) */
	__m256i xq = _mm256_srli_epi64(_mm256_sllv_epi64(*x, e), 30);
	*x = xq;
	*e_sh = e;
	/* the segment in the low half of each lane is what vpermd reads; the
	 * high halves (zero) pick garbage, masked off for a */
	__m256i seg = _mm256_and_si256(_mm256_srli_epi64(xq, 27), epi64(7));
	__m256i a = _mm256_and_si256(_mm256_permutevar8x32_epi32(
					     _mm256_loadu_si256((const __m256i *)fx_recip_seed_a), seg),
				     epi64(0xffffffff));
	__m256i bs = _mm256_permutevar8x32_epi32(_mm256_loadu_si256((const __m256i *)fx_recip_seed_b), seg);
	return _mm256_sub_epi64(a, mul_round(bs, xq, 30));
}

static inline __attribute__((always_inline)) __m256i recip_step4(__m256i xq, __m256i y)
{
	__m256i xy = mul_round(xq, y, 30);
	return mul_round(y, _mm256_sub_epi64(epi64(1ll << 32), xy), 31);
}

/* 2 / |real|^2 = inv / 2^sh from 1 / X = y / 2^31 and e */
static inline void blend_scale4(__m256i *y, __m256i *e_sh)
{
	*y = _mm256_srli_epi64(_mm256_add_epi64(*y, epi64(1)), 1);
	*e_sh = _mm256_sub_epi64(epi64(29), *e_sh);
}

/* The transform takes 4 vertices at a time in 64-bit lanes, each value in
 * the low 32 bits where vpmuldq reads it: the even and the odd vertices of
 * a batch separately, so no product needs a shuffle. After a rounding
 * shift only the low 32 bits matter: a logical shift leaves the same low
 * bits as an arithmetic one while the shift is at most 32. */
static inline __m256i round_shift(__m256i x, int s)
{
	return _mm256_srl_epi64(_mm256_add_epi64(x, epi64(1ll << (s - 1))), _mm_cvtsi32_si128(s));
}

static inline __m256i mul4(__m256i a, __m256i b)
{
	return _mm256_mul_epi32(a, b);
}

/* fx_dq_transform_blend's move_blended on 4 lanes: v + (2 / s) (r x (r x v
 * + w v + dv) + w dv - dw r), dual = d + 4 or NULL for the normal; 2 / s =
 * inv / 2^sh; a normal's shifts cut instead of rounding, as there. Inside
 * the envelope the batch was checked against, no intermediate leaves int32,
 * so nothing saturates and the low 32 bits of each lane are the scalar
 * kernel's values. */
static inline __attribute__((always_inline)) void move4(const __m256i d[8], const __m256i *dual,
							  const __m256i v[3], __m256i inv, __m256i sh,
							  __m256i rnd, __m256i out[3])
{
	const __m256i w = d[0], *r = d + 1;
	__m256i a[3];
#pragma GCC unroll 3
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3, k = (i + 2) % 3;
		__m256i sum = _mm256_add_epi64(_mm256_sub_epi64(mul4(r[j], v[k]), mul4(r[k], v[j])), mul4(w, v[i]));
		a[i] = dual ? _mm256_add_epi64(round_shift(sum, 30), dual[i + 1]) : _mm256_srli_epi64(sum, 30);
	}
#pragma GCC unroll 3
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3, k = (i + 2) % 3;
		__m256i sum = _mm256_sub_epi64(mul4(r[j], a[k]), mul4(r[k], a[j]));
		if (dual)
			sum = _mm256_add_epi64(sum, _mm256_sub_epi64(mul4(w, dual[i + 1]), mul4(dual[0], r[i])));
		__m256i b = dual ? round_shift(sum, 30) : _mm256_srli_epi64(sum, 30);
		__m256i delta = mul4(b, inv);
		if (dual)
			delta = _mm256_add_epi64(delta, rnd);
		out[i] = _mm256_add_epi64(v[i], _mm256_srlv_epi64(delta, sh));
	}
}

static inline __attribute__((always_inline)) void transform4(const __m256i d[8], __m256i inv,
							       __m256i sh, const __m256i p[3],
							       const __m256i n[3], __m256i po[3],
							       __m256i no[3])
{
	const __m256i one = epi64(1);
	const __m256i rnd = _mm256_sllv_epi64(one, _mm256_sub_epi64(sh, one));
	move4(d, d + 4, p, inv, sh, rnd, po);
	move4(d, NULL, n, inv, sh, rnd, no);
}

/* 8 int32 lanes to the even (low halves already) and odd vertices */
static inline void split_lanes(const __m256i *a, __m256i *even, __m256i *odd, int count)
{
#pragma GCC unroll 8
	for (int i = 0; i < count; i++) {
		even[i] = a[i];
		odd[i] = _mm256_srli_epi64(a[i], 32);
	}
}

static inline __m256i join_lanes(__m256i even, __m256i odd)
{
	return _mm256_blend_epi32(even, _mm256_slli_epi64(odd, 32), 0xAA);
}

static __m256i q30_to_q16(__m256i v)
{
	return _mm256_srai_epi32(_mm256_add_epi32(v, _mm256_set1_epi32(1 << 13)), 14);
}

/* The work is split in three passes over a chunk of vertices (blend,
 * reciprocal norm, transform): the integer reciprocal is a chain of dependent
 * multiplies, which a short loop of its own lets the out-of-order core
 * overlap across batches, and each pass keeps fewer values live. */
#define CHUNK_BATCHES 8

typedef struct chunk {
	int32_t w01[CHUNK_BATCHES][SKIN_LANES], w23[CHUNK_BATCHES][SKIN_LANES];
	__m256i d[CHUNK_BATCHES][8];
	/* even, odd lanes: squared norm (then X in Q30); 1 / X, then inv;
	 * e, then sh (see blend_scale4) */
	__m256i n2[CHUNK_BATCHES][2], inv[CHUNK_BATCHES][2], sh[CHUNK_BATCHES][2];
	int bad[CHUNK_BATCHES];
} chunk;

/* Whether a vertex of the batch is outside what the vector path keeps
 * within int32 (see move4): a position coordinate of 4096 units or more
 * (x + 2^28 leaves [0, 2^29)), a normal component longer than 1. */
static int outside_envelope(const skin_soa *in, int v)
{
	const int32_t *const pos[3] = { in->fpx, in->fpy, in->fpz }, *const nrm[3] = { in->fnx, in->fny, in->fnz };
	const __m256i one = _mm256_set1_epi32(FX_Q30_ONE);
	__m256i p = _mm256_setzero_si256(), n = p;
#pragma GCC unroll 3
	for (int i = 0; i < 3; i++) {
		__m256i x = _mm256_load_si256((const __m256i *)(pos[i] + v));
		p = _mm256_or_si256(p, _mm256_add_epi32(x, _mm256_set1_epi32(1 << 28)));
		/* unsigned: INT32_MIN stays negative under abs */
		n = _mm256_max_epu32(n, _mm256_abs_epi32(_mm256_load_si256((const __m256i *)(nrm[i] + v))));
	}
	__m256i bad = _mm256_or_si256(_mm256_and_si256(p, _mm256_set1_epi32(~((1 << 29) - 1))),
				      _mm256_xor_si256(_mm256_max_epu32(n, one), one));
	return !_mm256_testz_si256(bad, bad);
}

/* The weights first, in a loop of their own: each batch's begin with
 * gathers and a multiply whose latency would otherwise stall the blend. */
static void chunk_blend(const skin_soa *in, const skin_bones *b, int v, int batches, chunk *c)
{
	for (int i = 0; i < batches; i++)
		c->bad[i] = blend_weights(in, v + i * SKIN_LANES, c->w01[i], c->w23[i]) |
			    outside_envelope(in, v + i * SKIN_LANES);
	for (int i = 0; i < batches; i++) {
		__m256i *d = c->d[i];
		blend(in, b, v + i * SKIN_LANES, c->w01[i], c->w23[i], d);
		__m256i even[4], odd[4];
		split_lanes(d, even, odd, 4);
		c->n2[i][0] = _mm256_add_epi64(_mm256_add_epi64(mul4(even[0], even[0]), mul4(even[1], even[1])),
					     _mm256_add_epi64(mul4(even[2], even[2]), mul4(even[3], even[3])));
		c->n2[i][1] = _mm256_add_epi64(_mm256_add_epi64(mul4(odd[0], odd[0]), mul4(odd[1], odd[1])),
					     _mm256_add_epi64(mul4(odd[2], odd[2]), mul4(odd[3], odd[3])));
	}
}

static void chunk_norms(int batches, chunk *c)
{
	for (int i = 0; i < batches; i++) {
		__m256i be, bo;
		c->inv[i][0] = recip_seed4(&c->n2[i][0], &c->sh[i][0], &be);
		c->inv[i][1] = recip_seed4(&c->n2[i][1], &c->sh[i][1], &bo);
		__m256i bad = _mm256_or_si256(be, bo);
		c->bad[i] |= !_mm256_testz_si256(bad, bad);
	}
	__m256i *xq = &c->n2[0][0], *y = &c->inv[0][0];
	for (int s = 0; s < FX_RECIP_STEPS; s++)
		for (int i = 0; i < 2 * batches; i++)
			y[i] = recip_step4(xq[i], y[i]);
	for (int i = 0; i < 2 * batches; i++)
		blend_scale4(&y[i], &c->sh[0][0] + i);
}

static void transform8(const skin_soa *in, const __m256i d[8], const __m256i inv[2],
		       const __m256i sh[2], int v, int valid, const skin_out *out)
{
	__m256i dh[2][8], ph[2][3], nh[2][3], po[2][3], no[2][3];
	const __m256i pos[3] = { _mm256_load_si256((const __m256i *)(in->fpx + v)),
				 _mm256_load_si256((const __m256i *)(in->fpy + v)),
				 _mm256_load_si256((const __m256i *)(in->fpz + v)) };
	const __m256i nrm[3] = { _mm256_load_si256((const __m256i *)(in->fnx + v)),
				 _mm256_load_si256((const __m256i *)(in->fny + v)),
				 _mm256_load_si256((const __m256i *)(in->fnz + v)) };
	split_lanes(d, dh[0], dh[1], 8);
	split_lanes(pos, ph[0], ph[1], 3);
	split_lanes(nrm, nh[0], nh[1], 3);
#pragma GCC unroll 2
	for (int h = 0; h < 2; h++)
		transform4(dh[h], inv[h], sh[h], ph[h], nh[h], po[h], no[h]);
	__m256i p[3], n[3];
#pragma GCC unroll 3
	for (int i = 0; i < 3; i++) {
		p[i] = join_lanes(po[0][i], po[1][i]);
		n[i] = q30_to_q16(join_lanes(no[0][i], no[1][i]));
	}
	skin_store_xyz8(out->fpos + 3 * v, _mm256_castsi256_ps(p[0]), _mm256_castsi256_ps(p[1]),
			_mm256_castsi256_ps(p[2]), valid);
	skin_store_xyz8(out->fnrm + 3 * v, _mm256_castsi256_ps(n[0]), _mm256_castsi256_ps(n[1]),
			_mm256_castsi256_ps(n[2]), valid);
}

void skin_dqbs_fixed_avx2(const skin_soa *in, const skin_bones *b, int first, int end,
			  const skin_out *out)
{
	_Static_assert(FX_POS_FRAC == 16, "the AVX2 fixed kernel writes fx_pos as Q16.16 directly");
	if (!b->simd_ok) {
		skin_dqbs_fixed(in, b, first, end, out);
		return;
	}
	chunk c;
	for (int v0 = first; v0 < end; v0 += CHUNK_BATCHES * SKIN_LANES) {
		int left = (end - v0 + SKIN_LANES - 1) / SKIN_LANES;
		int batches = left < CHUNK_BATCHES ? left : CHUNK_BATCHES;
		chunk_blend(in, b, v0, batches, &c);
		chunk_norms(batches, &c);
		for (int i = 0; i < batches; i++) {
			int v = v0 + i * SKIN_LANES;
			int valid = end - v < SKIN_LANES ? end - v : SKIN_LANES;
			if (c.bad[i])
				/* a norm outside the vector path's range (a blend
				 * that nearly cancelled), weights outside
				 * skin_soa_load's or a vertex outside the envelope:
				 * the scalar kernel handles them */
				skin_dqbs_fixed(in, b, v, v + valid, out);
			else
				transform8(in, c.d[i], c.inv[i], c.sh[i], v, valid, out);
		}
	}
}

#else
typedef int skin_fixed_avx2_not_built; /* the board chose the scalar kernels */
#endif
