/* DQBS in fixed point with AVX2 integer instructions, eight vertices per
 * step. Same formats and rounding as skin_fixed.c; products are 32x32->64
 * (vpmuldq) on the even and odd lanes separately, sums are kept in 64 bits
 * and rounded once. No floating-point instruction: `make test` disassembles
 * this object to check (tests/check_simd_integer.sh). */
#include "skin.h"

#ifdef SKP_SIMD_AVX2

#include "skin_avx2.h"

/* 8 products as two vectors of 4 int64: lanes 0,2,4,6 and 1,3,5,7 */
typedef struct wide {
	__m256i e, o;
} wide;

typedef struct ivec {
	__m256i x, y, z;
} ivec;

/* Odd lanes moved to the even positions vpmuldq reads: a shuffle, so it
 * runs on the shuffle port while the multiplies and shifts use the others. */
static inline __m256i odd_lanes(__m256i a)
{
	return _mm256_shuffle_epi32(a, _MM_SHUFFLE(3, 3, 1, 1));
}

static inline wide wmul(__m256i a, __m256i b)
{
	wide r = { _mm256_mul_epi32(a, b), _mm256_mul_epi32(odd_lanes(a), odd_lanes(b)) };
	return r;
}

static inline wide wadd(wide a, wide b)
{
	wide r = { _mm256_add_epi64(a.e, b.e), _mm256_add_epi64(a.o, b.o) };
	return r;
}

static inline wide wsub(wide a, wide b)
{
	wide r = { _mm256_sub_epi64(a.e, b.e), _mm256_sub_epi64(a.o, b.o) };
	return r;
}

/* Round and shift right by s (<= 32), back to 8 int32 lanes: the even
 * products shift down to the low halves, the odd ones up to the high
 * halves. A logical shift keeps the same 32 bits as an arithmetic one, and
 * results fit in 32 bits. */
static inline __m256i narrow(wide w, int s)
{
	__m256i rnd = _mm256_set1_epi64x((long long)1 << (s - 1));
	__m256i e = _mm256_srl_epi64(_mm256_add_epi64(w.e, rnd), _mm_cvtsi32_si128(s));
	__m256i o = _mm256_sll_epi64(_mm256_add_epi64(w.o, rnd), _mm_cvtsi32_si128(32 - s));
	return _mm256_blend_epi32(e, o, 0xAA);
}

static __m256i load_weights(const fx_w15 *w, int v)
{
	return _mm256_cvtepu16_epi32(_mm_load_si128((const __m128i *)(w + v)));
}

/* Signed weights as 16-bit multiply-add operands: (w, 0) multiplies the
 * low half of a split component, (0, w) the high half. Slot 0 (the pivot,
 * never flipped) may hold 32768, which int16 cannot: it enters as w - 1 and
 * blend_half adds its component once more. */
typedef struct wpair {
	__m256i lo, hi;
} wpair;

/* Weights with the sign fix (looked up per bone pair, see skin_bones).
 * Returns nonzero when a lane breaks what the 16-bit products need and
 * skin_soa_load guarantees (weights summing to at most 1.0, a full weight
 * only in slot 0): the caller then takes the scalar path. */
static inline __attribute__((always_inline)) int blend_weights(const skin_soa *in,
								const skin_bones *b, int v,
								wpair w[SKP_MAX_INFLUENCES])
{
	const int *flip = &b->flip_x[0][0];
	const __m256i low16 = _mm256_set1_epi32(0xffff), full = _mm256_set1_epi32(FX_W15_ONE);
	__m256i bad = _mm256_setzero_si256(), sum = _mm256_setzero_si256();
#pragma GCC unroll 8
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		__m256i x = load_weights(in->fweight[k], v);
		sum = _mm256_add_epi32(sum, x);
		if (k == 0) {
			x = _mm256_sub_epi32(x, _mm256_set1_epi32(1));
		} else {
			__m256i neg = _mm256_i32gather_epi32(flip, skin_flip_index(in->bone[0], in->bone[k], v), 4);
			bad = _mm256_or_si256(bad, _mm256_cmpeq_epi32(x, full));
			x = _mm256_sub_epi32(_mm256_xor_si256(x, neg), neg);
		}
		w[k].lo = _mm256_and_si256(x, low16);
		w[k].hi = _mm256_slli_epi32(x, 16);
	}
	bad = _mm256_or_si256(bad, _mm256_cmpgt_epi32(sum, full));
	return !_mm256_testz_si256(bad, bad);
}

/* One half (real: 0, dual: 4) of the weighted sum, rounded back to Q30 /
 * fx_pos. With c = hi 2^16 + lo, sum(w c) = 2^16 sum(w hi) + sum(w lo),
 * and both sums fit in 32 bits because sum |w| <= 2^15; so the rounded
 * shift by 15 is 2 sum(w hi) + round(sum(w lo) / 2^15), exactly the
 * scalar kernel's 64-bit result. */
static inline __attribute__((always_inline)) void blend_half(const skin_soa *in, const skin_bones *b,
							       int v, const wpair w[SKP_MAX_INFLUENCES],
							       int half, __m256i out[4])
{
	__m256i lo[4], hi[4];
#pragma GCC unroll 8
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		const float *row[8];
		__m256 d[4];
#pragma GCC unroll 8
		for (int j = 0; j < 8; j++)
			row[j] = (const float *)&b->fdq_split[in->bone[k][v + j]][half];
		skin_transpose8x4(row, d);
#pragma GCC unroll 8
		for (int c = 0; c < 4; c++) {
			__m256i a = _mm256_castps_si256(d[c]);
			__m256i pl = _mm256_madd_epi16(a, w[k].lo), ph = _mm256_madd_epi16(a, w[k].hi);
			if (k == 0) {
				/* the pivot's missing 1 * c */
				lo[c] = _mm256_add_epi32(pl, _mm256_srai_epi32(_mm256_slli_epi32(a, 16), 16));
				hi[c] = _mm256_add_epi32(ph, _mm256_srai_epi32(a, 16));
			} else {
				lo[c] = _mm256_add_epi32(lo[c], pl);
				hi[c] = _mm256_add_epi32(hi[c], ph);
			}
		}
	}
	const __m256i rnd = _mm256_set1_epi32(1 << 14);
#pragma GCC unroll 8
	for (int c = 0; c < 4; c++)
		out[c] = _mm256_add_epi32(_mm256_add_epi32(hi[c], hi[c]),
					  _mm256_srai_epi32(_mm256_add_epi32(lo[c], rnd), 15));
}

/* Nonzero when the batch must take the scalar path (see blend_weights). */
static inline __attribute__((always_inline)) int blend(const skin_soa *in, const skin_bones *b, int v,
							 __m256i out[8])
{
	wpair w[SKP_MAX_INFLUENCES];
	int bad = blend_weights(in, b, v, w);
	blend_half(in, b, v, w, 0, out);
	blend_half(in, b, v, w, 4, out + 4);
	return bad;
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

/* fx_rsqrt_q60 on 4 lanes, step for step the same integers, for squared
 * norms in [2^56, 2^62) (every blend with the sign fix: its real part is at
 * least the pivot's weight, 1/4, long). Lanes outside are flagged in *bad. */
static inline __attribute__((always_inline)) void rsqrt4(__m256i x, __m256i *m, __m256i *shift, __m256i *bad)
{
	__m256i lt60 = _mm256_cmpgt_epi64(epi64(1ll << 60), x);
	__m256i lt58 = _mm256_cmpgt_epi64(epi64(1ll << 58), x);
	*bad = _mm256_or_si256(_mm256_cmpgt_epi64(epi64(1ll << 56), x),
			       _mm256_cmpgt_epi64(x, epi64((1ll << 62) - 1)));
	__m256i e = _mm256_sub_epi64(_mm256_setzero_si256(), _mm256_add_epi64(lt60, lt58));
	x = _mm256_sllv_epi64(x, _mm256_add_epi64(e, e));
	__m256i xq = _mm256_srli_epi64(x, 30); /* floor, < 2^32 */
	__m256i y = _mm256_sub_epi64(epi64((long long)FX_RSQRT_SEED_A),
				     mul_round(epi64((long long)FX_RSQRT_SEED_B), xq, 30));
	const __m256i three_halves = epi64(3ll << 30);
	#pragma GCC unroll 8
	for (int i = 0; i < FX_RSQRT_STEPS; i++) {
		__m256i y2 = mul_round(y, y, 31);
		__m256i h = mul_round(xq, y2, 31);
		__m256i f = _mm256_andnot_si256(_mm256_cmpgt_epi64(h, three_halves),
						_mm256_sub_epi64(three_halves, h));
		y = mul_round(y, f, 31);
	}
	__m256i big = _mm256_cmpgt_epi64(y, epi64(INT32_MAX));
	*m = _mm256_blendv_epi8(y, epi64(INT32_MAX), big);
	*shift = _mm256_sub_epi64(epi64(31), e);
}

/* v * m >> shift per lane, rounded */
static inline __attribute__((always_inline)) __m256i scale(__m256i v, __m256i m, __m256i shift)
{
	wide p = wmul(v, m);
	__m256i se = _mm256_and_si256(shift, _mm256_set1_epi64x(0xffffffff));
	__m256i so = _mm256_srli_epi64(shift, 32);
	__m256i one = _mm256_set1_epi64x(1);
	__m256i re = _mm256_sllv_epi64(one, _mm256_sub_epi64(se, one));
	__m256i ro = _mm256_sllv_epi64(one, _mm256_sub_epi64(so, one));
	__m256i e = _mm256_srlv_epi64(_mm256_add_epi64(p.e, re), se);
	__m256i o = _mm256_slli_epi64(_mm256_srlv_epi64(_mm256_add_epi64(p.o, ro), so), 32);
	return _mm256_blend_epi32(e, o, 0xAA);
}

/* v + 2 r x (r x v + w v) with r, w in Q30: sums of products in 64 bits */
static inline __attribute__((always_inline)) ivec rotate(const __m256i q[4], ivec v)
{
	__m256i w = q[0];
	ivec r = { q[1], q[2], q[3] };
	ivec t = {
		narrow(wadd(wsub(wmul(r.y, v.z), wmul(r.z, v.y)), wmul(w, v.x)), 30),
		narrow(wadd(wsub(wmul(r.z, v.x), wmul(r.x, v.z)), wmul(w, v.y)), 30),
		narrow(wadd(wsub(wmul(r.x, v.y), wmul(r.y, v.x)), wmul(w, v.z)), 30),
	};
	ivec o = {
		_mm256_add_epi32(v.x, narrow(wsub(wmul(r.y, t.z), wmul(r.z, t.y)), 29)),
		_mm256_add_epi32(v.y, narrow(wsub(wmul(r.z, t.x), wmul(r.x, t.z)), 29)),
		_mm256_add_epi32(v.z, narrow(wsub(wmul(r.x, t.y), wmul(r.y, t.x)), 29)),
	};
	return o;
}

/* 2 (w d_v - d_w r_v + r_v x d_v) */
static inline __attribute__((always_inline)) ivec translation(const __m256i q[8])
{
	const __m256i *r = q, *d = q + 4;
	ivec t = {
		narrow(wadd(wsub(wmul(r[0], d[1]), wmul(d[0], r[1])), wsub(wmul(r[2], d[3]), wmul(r[3], d[2]))), 29),
		narrow(wadd(wsub(wmul(r[0], d[2]), wmul(d[0], r[2])), wsub(wmul(r[3], d[1]), wmul(r[1], d[3]))), 29),
		narrow(wadd(wsub(wmul(r[0], d[3]), wmul(d[0], r[3])), wsub(wmul(r[1], d[2]), wmul(r[2], d[1]))), 29),
	};
	return t;
}

static ivec load_ivec(const int32_t *x, const int32_t *y, const int32_t *z, int v)
{
	ivec r = { _mm256_load_si256((const __m256i *)(x + v)), _mm256_load_si256((const __m256i *)(y + v)),
		   _mm256_load_si256((const __m256i *)(z + v)) };
	return r;
}

static void store_ivec(int32_t *dst, ivec a, int valid)
{
	skin_store_xyz8(dst, _mm256_castsi256_ps(a.x), _mm256_castsi256_ps(a.y),
			_mm256_castsi256_ps(a.z), valid);
}

static __m256i q30_to_q16(__m256i v)
{
	return _mm256_srai_epi32(_mm256_add_epi32(v, _mm256_set1_epi32(1 << 13)), 14);
}

/* The work is split in three passes over a chunk of vertices (blend,
 * reciprocal norm, transform) because the integer rsqrt is a long chain of
 * dependent multiplies: in one loop body it would leave the multipliers
 * idle, in a short loop of its own the out-of-order core overlaps the
 * chains of several batches. */
#define CHUNK_BATCHES 8

typedef struct chunk {
	__m256i d[CHUNK_BATCHES][8];
	__m256i n2e[CHUNK_BATCHES], n2o[CHUNK_BATCHES];
	__m256i m[CHUNK_BATCHES], shift[CHUNK_BATCHES];
	int bad[CHUNK_BATCHES];
} chunk;

static void chunk_blend(const skin_soa *in, const skin_bones *b, int v, int batches, chunk *c)
{
	for (int i = 0; i < batches; i++) {
		__m256i *d = c->d[i];
		c->bad[i] = blend(in, b, v + i * SKIN_LANES, d);
		wide n2 = wadd(wadd(wmul(d[0], d[0]), wmul(d[1], d[1])),
			       wadd(wmul(d[2], d[2]), wmul(d[3], d[3])));
		c->n2e[i] = n2.e;
		c->n2o[i] = n2.o;
	}
}

static void chunk_norms(int batches, chunk *c)
{
	for (int i = 0; i < batches; i++) {
		__m256i me, se, be, mo, so, bo;
		rsqrt4(c->n2e[i], &me, &se, &be);
		rsqrt4(c->n2o[i], &mo, &so, &bo);
		c->m[i] = _mm256_blend_epi32(me, _mm256_slli_epi64(mo, 32), 0xAA);
		c->shift[i] = _mm256_blend_epi32(se, _mm256_slli_epi64(so, 32), 0xAA);
		__m256i bad = _mm256_or_si256(be, bo);
		c->bad[i] |= !_mm256_testz_si256(bad, bad);
	}
}

static void transform8(const skin_soa *in, __m256i d[8], __m256i m, __m256i shift, int v,
		       int valid, const skin_out *out)
{
	#pragma GCC unroll 8
	for (int c = 0; c < 8; c++)
		d[c] = scale(d[c], m, shift);
	ivec t = translation(d);
	ivec p = rotate(d, load_ivec(in->fpx, in->fpy, in->fpz, v));
	p.x = _mm256_add_epi32(p.x, t.x);
	p.y = _mm256_add_epi32(p.y, t.y);
	p.z = _mm256_add_epi32(p.z, t.z);
	ivec n = rotate(d, load_ivec(in->fnx, in->fny, in->fnz, v));
	n.x = q30_to_q16(n.x);
	n.y = q30_to_q16(n.y);
	n.z = q30_to_q16(n.z);
	store_ivec(out->fpos + 3 * v, p, valid);
	store_ivec(out->fnrm + 3 * v, n, valid);
}

void skin_dqbs_fixed_avx2(const skin_soa *in, const skin_bones *b, int first, int end,
			  const skin_out *out)
{
	_Static_assert(FX_POS_FRAC == 16, "the AVX2 fixed kernel writes fx_pos as Q16.16 directly");
	if (!b->split_ok) {
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
				 * that nearly cancelled): the scalar kernel handles it */
				skin_dqbs_fixed(in, b, v, v + valid, out);
			else
				transform8(in, c.d[i], c.m[i], c.shift[i], v, valid, out);
		}
	}
}

#else
typedef int skin_fixed_avx2_not_built; /* the board chose the scalar kernels */
#endif
