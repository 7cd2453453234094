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

static inline __m256i odd_lanes(__m256i a)
{
	return _mm256_srli_epi64(a, 32);
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

/* Round and shift right by s, back to 8 int32 lanes. A logical shift gives
 * the same low 32 bits as an arithmetic one, and results fit in 32 bits. */
static inline __m256i narrow(wide w, int s)
{
	__m256i rnd = _mm256_set1_epi64x((long long)1 << (s - 1));
	__m128i cnt = _mm_cvtsi32_si128(s);
	__m256i e = _mm256_srl_epi64(_mm256_add_epi64(w.e, rnd), cnt);
	__m256i o = _mm256_slli_epi64(_mm256_srl_epi64(_mm256_add_epi64(w.o, rnd), cnt), 32);
	return _mm256_blend_epi32(e, o, 0xAA);
}

/* The 8-int32 fx_dq of each of 8 vertices' bones, transposed to lanes. */
static void load_dq(const skin_bones *b, const uint16_t *bone, int v, __m256i d[8])
{
	__m256 r[8];
	for (int j = 0; j < 8; j++)
		r[j] = _mm256_loadu_ps((const float *)&b->fdq[bone[v + j]]);
	skin_transpose8(r);
	for (int c = 0; c < 8; c++)
		d[c] = _mm256_castps_si256(r[c]);
}

static __m256i load_weights(const fx_w15 *w, int v)
{
	return _mm256_cvtepu16_epi32(_mm_load_si128((const __m128i *)(w + v)));
}

/* Lanes whose 64-bit dot product is negative, as a 32-bit lane mask. */
static __m256i negative_mask(wide dot)
{
	__m256i zero = _mm256_setzero_si256();
	__m256i e = _mm256_cmpgt_epi64(zero, dot.e), o = _mm256_cmpgt_epi64(zero, dot.o);
	return _mm256_blend_epi32(e, o, 0xAA);
}

/* Weighted sum (Q45 real, Q31+ dual in 64 bits) with the sign fix against
 * influence 0, rounded back to Q30 / fx_pos. */
static void blend(const skin_soa *in, const skin_bones *b, int v, __m256i out[8])
{
	__m256i pivot[8], d[8];
	wide acc[8];
	load_dq(b, in->bone[0], v, pivot);
	__m256i w0 = load_weights(in->fweight[0], v);
	for (int c = 0; c < 8; c++)
		acc[c] = wmul(w0, pivot[c]);
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		load_dq(b, in->bone[k], v, d);
		wide dot = wadd(wadd(wmul(d[0], pivot[0]), wmul(d[1], pivot[1])),
				wadd(wmul(d[2], pivot[2]), wmul(d[3], pivot[3])));
		__m256i neg = negative_mask(dot);
		__m256i w = _mm256_sub_epi32(_mm256_xor_si256(load_weights(in->fweight[k], v), neg), neg);
		for (int c = 0; c < 8; c++)
			acc[c] = wadd(acc[c], wmul(w, d[c]));
	}
	for (int c = 0; c < 8; c++)
		out[c] = narrow(acc[c], 15);
}

/* 1/|real| per lane through the scalar Newton iteration (a few per block:
 * AVX2 has no 64-bit leading-zero count), as multiplier and shift. */
static int reciprocal_norms(const __m256i d[8], __m256i *m, __m256i *shift)
{
	wide n2 = wadd(wadd(wmul(d[0], d[0]), wmul(d[1], d[1])),
		       wadd(wmul(d[2], d[2]), wmul(d[3], d[3])));
	uint64_t e[4], o[4];
	int32_t mm[8], ss[8], degenerate = 0;
	_mm256_storeu_si256((__m256i *)e, n2.e);
	_mm256_storeu_si256((__m256i *)o, n2.o);
	for (int i = 0; i < 8; i++) {
		uint64_t x = i & 1 ? o[i / 2] : e[i / 2];
		uint32_t r = fx_rsqrt_q60(x, &ss[i]);
		degenerate |= r == 0;
		mm[i] = r > INT32_MAX ? INT32_MAX : (int32_t)r;
		if (r == 0)
			ss[i] = 1;
	}
	*m = _mm256_loadu_si256((const __m256i *)mm);
	*shift = _mm256_loadu_si256((const __m256i *)ss);
	return degenerate;
}

/* v * m >> shift per lane, rounded */
static __m256i scale(__m256i v, __m256i m, __m256i shift)
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
static ivec rotate(const __m256i q[4], ivec v)
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
static ivec translation(const __m256i q[8])
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

void skin_dqbs_fixed_avx2(const skin_soa *in, const skin_bones *b, int first, int end,
			  const skin_out *out)
{
	_Static_assert(FX_POS_FRAC == 16, "the AVX2 fixed kernel writes fx_pos as Q16.16 directly");
	for (int v = first; v < end; v += SKIN_LANES) {
		__m256i d[8], m, shift;
		blend(in, b, v, d);
		if (reciprocal_norms(d, &m, &shift)) {
			/* a blend that cancelled out: let the scalar kernel apply
			 * its identity fallback to this block */
			skin_dqbs_fixed(in, b, v, v + SKIN_LANES < end ? v + SKIN_LANES : end, out);
			continue;
		}
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
		int valid = end - v < SKIN_LANES ? end - v : SKIN_LANES;
		store_ivec(out->fpos + 3 * v, p, valid);
		store_ivec(out->fnrm + 3 * v, n, valid);
	}
}

#else
typedef int skin_fixed_avx2_not_built; /* the board chose the scalar kernels */
#endif
