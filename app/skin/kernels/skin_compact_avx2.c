/* AVX2+FMA kernels over the compact vertex streams (skin_compact.h):
 * each batch of eight decoded in lanes (positions from their 16-bit steps,
 * normals from octahedral pairs, the pivot's weight from the others'),
 * then the float kernels' arithmetic (skin_avx2_float.h), normals written
 * as 16-bit snorm. Results match skin_compact_scalar.c to float rounding. */
#include "skin_kernels.h"

#ifdef SKP_SIMD_AVX2

#include "skin_avx2_float.h"

static __m256 load_u16(const uint16_t *src)
{
	return _mm256_cvtepi32_ps(_mm256_cvtepu16_epi32(_mm_load_si128((const __m128i *)src)));
}

static __m256 load_i16(const int16_t *src)
{
	return _mm256_cvtepi32_ps(_mm256_cvtepi16_epi32(_mm_load_si128((const __m128i *)src)));
}

SKIN_INLINE v3x8 load_positions(const skin_compact *in, int v)
{
	v3x8 p = { _mm256_fmadd_ps(load_u16(in->qx + v), _mm256_set1_ps(in->step[0]), _mm256_set1_ps(in->origin[0])),
		   _mm256_fmadd_ps(load_u16(in->qy + v), _mm256_set1_ps(in->step[1]), _mm256_set1_ps(in->origin[1])),
		   _mm256_fmadd_ps(load_u16(in->qz + v), _mm256_set1_ps(in->step[2]), _mm256_set1_ps(in->origin[2])) };
	return p;
}

/* skin_oct_decode on 8 lanes; normalised unless the caller normalises
 * after (LBS: only the decoded normal's direction matters there) */
SKIN_INLINE v3x8 load_normals(const skin_compact *in, int v, int normalise)
{
	const __m256 sign = _mm256_set1_ps(-0.0f), scale = _mm256_set1_ps(1.0f / SKIN_COMPACT_NORMAL_ONE);
	__m256 x = _mm256_mul_ps(load_i16(in->ox + v), scale), y = _mm256_mul_ps(load_i16(in->oy + v), scale);
	__m256 z = _mm256_sub_ps(_mm256_sub_ps(_mm256_set1_ps(1.0f), _mm256_andnot_ps(sign, x)),
				 _mm256_andnot_ps(sign, y));
	__m256 t = _mm256_max_ps(_mm256_sub_ps(_mm256_setzero_ps(), z), _mm256_setzero_ps());
	/* x - t with x's sign: x >= 0 moves down by t, x < 0 up */
	v3x8 n = { _mm256_sub_ps(x, _mm256_or_ps(t, _mm256_and_ps(x, sign))),
		   _mm256_sub_ps(y, _mm256_or_ps(t, _mm256_and_ps(y, sign))), z };
	return normalise ? normalize8_fast(n) : n;
}

/* The batch's weights as floats in ws (the pivot's the rest of 65535),
 * and where its bones are. */
SKIN_INLINE infl8 influences(const skin_compact *in, int v, float ws[SKP_MAX_INFLUENCES][SKIN_LANES])
{
	const __m256 scale = _mm256_set1_ps(1.0f / (float)SKIN_COMPACT_WEIGHT_ONE);
	__m256i rest = _mm256_set1_epi32((int)SKIN_COMPACT_WEIGHT_ONE);
	infl8 s;
	s.bone_bytes = 1;
#pragma GCC unroll 4
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		__m256i w = _mm256_cvtepu16_epi32(_mm_load_si128((const __m128i *)(in->weight[k - 1] + v)));
		rest = _mm256_sub_epi32(rest, w);
		_mm256_store_ps(ws[k], _mm256_mul_ps(_mm256_cvtepi32_ps(w), scale));
	}
	_mm256_store_ps(ws[0], _mm256_mul_ps(_mm256_cvtepi32_ps(rest), scale));
	/* read back through memory: forwarded in registers, GCC broadcasts
	 * them with shuffles, where a broadcast load costs only a load */
	__asm__("" : "+m"(*(float(*)[SKP_MAX_INFLUENCES][SKIN_LANES])ws));
#pragma GCC unroll 4
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		s.bone[k] = in->bone[k] + v;
		s.weight[k] = ws[k];
	}
	return s;
}

/* The 24 values of store_snorm8: a's halves hold 8 each, b's low quarters 4 */
SKIN_INLINE void store_halves(int16_t *to, __m256i a, __m256i b)
{
	_mm_storeu_si128((__m128i *)to, _mm256_castsi256_si128(a));
	_mm_storel_epi64((__m128i *)(to + 8), _mm256_castsi256_si128(b));
	_mm_storeu_si128((__m128i *)(to + 12), _mm256_extracti128_si256(a, 1));
	_mm_storel_epi64((__m128i *)(to + 20), _mm256_extracti128_si256(b, 1));
}

/* 8 unit normals as 24 interleaved snorm16 values at dst (the first
 * `valid` triples). Per 128-bit half (4 vertices): packed x|y and z|z,
 * byte shuffles interleave them into 8 values (x0 y0 z0 x1 y1 z1 x2 y2)
 * and 4 (z2 x3 y3 z3). */
SKIN_INLINE void store_snorm8(int16_t *dst, v3x8 n, int valid)
{
	const __m256 one = _mm256_set1_ps(SKIN_COMPACT_NORMAL_ONE);
	__m256i xy = _mm256_packs_epi32(_mm256_cvtps_epi32(_mm256_mul_ps(n.x, one)),
					_mm256_cvtps_epi32(_mm256_mul_ps(n.y, one)));
	__m256i zz = _mm256_cvtps_epi32(_mm256_mul_ps(n.z, one));
	zz = _mm256_packs_epi32(zz, zz);
	/* int16 k of the source to each slot: bytes 2k, 2k + 1; -1 zero */
#define W(k) (char)(2 * (k)), (char)(2 * (k) + 1)
#define Z (char)-1, (char)-1
	const __m256i a_xy = _mm256_setr_epi8(W(0), W(4), Z, W(1), W(5), Z, W(2), W(6),
					      W(0), W(4), Z, W(1), W(5), Z, W(2), W(6));
	const __m256i a_z = _mm256_setr_epi8(Z, Z, W(0), Z, Z, W(1), Z, Z, Z, Z, W(0), Z, Z, W(1), Z, Z);
	const __m256i b_xy = _mm256_setr_epi8(Z, W(3), W(7), Z, Z, Z, Z, Z, Z, W(3), W(7), Z, Z, Z, Z, Z);
	const __m256i b_z = _mm256_setr_epi8(W(2), Z, Z, W(3), Z, Z, Z, Z, W(2), Z, Z, W(3), Z, Z, Z, Z);
#undef W
#undef Z
	__m256i a = _mm256_or_si256(_mm256_shuffle_epi8(xy, a_xy), _mm256_shuffle_epi8(zz, a_z));
	__m256i b = _mm256_or_si256(_mm256_shuffle_epi8(xy, b_xy), _mm256_shuffle_epi8(zz, b_z));
	if (valid == SKIN_LANES) {
		store_halves(dst, a, b);
		return;
	}
	int16_t tmp[3 * SKIN_LANES];
	store_halves(tmp, a, b);
	memcpy(dst, tmp, sizeof(int16_t) * 3 * (size_t)valid);
}

void skin_lbs_compact_avx2(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	float ws[SKP_MAX_INFLUENCES][SKIN_LANES] __attribute__((aligned(32)));
	for (int v = first; v < end; v += SKIN_LANES) {
		__m256 m[12];
		infl8 s = influences(in, v, ws);
		lbs_block(&s, b, m);
		int valid = end - v < SKIN_LANES ? end - v : SKIN_LANES;
		v3x8 p = apply_rows(m, load_positions(in, v), 1);
		v3x8 n = normalize8_fast(apply_rows(m, load_normals(in, v, 0), 0));
		skin_store_xyz8(out->pos + 3 * v, p.x, p.y, p.z, valid);
		store_snorm8(out->nrm16 + 3 * v, n, valid);
	}
}

void skin_dqbs_compact_avx2(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	float ws[SKP_MAX_INFLUENCES][SKIN_LANES] __attribute__((aligned(32)));
	for (int v = first; v < end; v += SKIN_LANES) {
		infl8 s = influences(in, v, ws);
		dq8 d = dq_blend8(&s, b);
		__m256 two_s = two_over_norm2(&d);
		v3x8 p = move8(&d, two_s, load_positions(in, v), 1);
		v3x8 n = move8(&d, two_s, load_normals(in, v, 1), 0);
		int valid = end - v < SKIN_LANES ? end - v : SKIN_LANES;
		skin_store_xyz8(out->pos + 3 * v, p.x, p.y, p.z, valid);
		store_snorm8(out->nrm16 + 3 * v, n, valid);
	}
}

#else
typedef int skin_compact_avx2_not_built; /* the board chose the scalar kernels */
#endif
