/* Shared by the AVX2 kernels: moving eight vertices between the
 * per-vertex (AoS) and per-lane (SoA) layouts.
 * No floating-point arithmetic here, so the fixed-point kernel may use
 * them too. */
#ifndef SKIN_AVX2_LAYOUT_H
#define SKIN_AVX2_LAYOUT_H

#include <immintrin.h>
#include <stdint.h>
#include <string.h>

#include "board_limits.h"

/* Rows r[j] = 8 values of vertex j become r[c] = value c of the 8 vertices. */
static inline void skin_transpose8(__m256 r[8])
{
	__m256 t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
	__m256 t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
	__m256 t4 = _mm256_unpacklo_ps(r[4], r[5]), t5 = _mm256_unpackhi_ps(r[4], r[5]);
	__m256 t6 = _mm256_unpacklo_ps(r[6], r[7]), t7 = _mm256_unpackhi_ps(r[6], r[7]);
	__m256 s0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
	__m256 s1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
	__m256 s2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
	__m256 s3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
	__m256 s4 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(1, 0, 1, 0));
	__m256 s5 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(3, 2, 3, 2));
	__m256 s6 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(1, 0, 1, 0));
	__m256 s7 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(3, 2, 3, 2));
	r[0] = _mm256_permute2f128_ps(s0, s4, 0x20);
	r[1] = _mm256_permute2f128_ps(s1, s5, 0x20);
	r[2] = _mm256_permute2f128_ps(s2, s6, 0x20);
	r[3] = _mm256_permute2f128_ps(s3, s7, 0x20);
	r[4] = _mm256_permute2f128_ps(s0, s4, 0x31);
	r[5] = _mm256_permute2f128_ps(s1, s5, 0x31);
	r[6] = _mm256_permute2f128_ps(s2, s6, 0x31);
	r[7] = _mm256_permute2f128_ps(s3, s7, 0x31);
}

/* 8 xyz triples from three lane registers to 24 interleaved values at dst
 * (only the first `valid` triples are written). */
static inline void skin_store_xyz8(void *dst, __m256 x, __m256 y, __m256 z, int valid)
{
	__m256 rxy = _mm256_shuffle_ps(x, y, _MM_SHUFFLE(2, 0, 2, 0));
	__m256 ryz = _mm256_shuffle_ps(y, z, _MM_SHUFFLE(3, 1, 3, 1));
	__m256 rzx = _mm256_shuffle_ps(z, x, _MM_SHUFFLE(3, 1, 2, 0));
	__m256 r03 = _mm256_shuffle_ps(rxy, rzx, _MM_SHUFFLE(2, 0, 2, 0));
	__m256 r14 = _mm256_shuffle_ps(ryz, rxy, _MM_SHUFFLE(3, 1, 2, 0));
	__m256 r25 = _mm256_shuffle_ps(rzx, ryz, _MM_SHUFFLE(3, 1, 3, 1));
	__m256 o[3] = { _mm256_permute2f128_ps(r03, r14, 0x20),
			_mm256_permute2f128_ps(r25, r03, 0x30),
			_mm256_permute2f128_ps(r14, r25, 0x31) };
	if (valid == 8) {
		_mm256_storeu_ps((float *)dst, o[0]);
		_mm256_storeu_ps((float *)dst + 8, o[1]);
		_mm256_storeu_ps((float *)dst + 16, o[2]);
		return;
	}
	memcpy(dst, o, 4 * 3 * (size_t)valid);
}

#endif
