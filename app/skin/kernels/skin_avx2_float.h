/* The float kernels' arithmetic on eight lanes, shared by the AVX2
 * kernels over the float vertex streams (skin_avx2.c) and over the compact
 * ones (skin_compact_avx2.c): the blends per vertex, the transforms in
 * lanes. Each kernel says where a batch's influences come from (infl8). */
#ifndef SKIN_AVX2_FLOAT_H
#define SKIN_AVX2_FLOAT_H

#include "skin_avx2_layout.h"
#include "skin_kernels.h"

#define SKIN_INLINE static inline __attribute__((always_inline))

typedef struct v3x8 {
	__m256 x, y, z;
} v3x8;

/* A batch's influences: bone k of lane j is element j of bone[k], an
 * array of uint16 or (bone_bytes 1) uint8 indices (a constant in each
 * kernel, so the test folds away), with weight weight[k][j]. */
typedef struct infl8 {
	const void *bone[SKP_MAX_INFLUENCES];
	int bone_bytes;
	const float *weight[SKP_MAX_INFLUENCES];
} infl8;

SKIN_INLINE int infl_bone(const infl8 *s, int k, int j)
{
	return s->bone_bytes == 2 ? ((const uint16_t *)s->bone[k])[j] : ((const uint8_t *)s->bone[k])[j];
}

SKIN_INLINE v3x8 normalize8(v3x8 a)
{
	__m256 len2 = _mm256_fmadd_ps(a.x, a.x, _mm256_fmadd_ps(a.y, a.y, _mm256_mul_ps(a.z, a.z)));
	__m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), _mm256_sqrt_ps(len2));
	v3x8 r = { _mm256_mul_ps(a.x, inv), _mm256_mul_ps(a.y, inv), _mm256_mul_ps(a.z, inv) };
	return r;
}

/* The same to about 1e-7 by an approximate reciprocal square root and one
 * Newton step: for normals that leave as 16-bit snorm (3e-5 a step). */
SKIN_INLINE v3x8 normalize8_fast(v3x8 a)
{
	__m256 len2 = _mm256_fmadd_ps(a.x, a.x, _mm256_fmadd_ps(a.y, a.y, _mm256_mul_ps(a.z, a.z)));
	__m256 y = _mm256_rsqrt_ps(len2);
	/* y (1.5 - len2 y^2 / 2) */
	__m256 h = _mm256_mul_ps(_mm256_mul_ps(len2, _mm256_set1_ps(0.5f)), _mm256_mul_ps(y, y));
	y = _mm256_mul_ps(y, _mm256_sub_ps(_mm256_set1_ps(1.5f), h));
	v3x8 r = { _mm256_mul_ps(a.x, y), _mm256_mul_ps(a.y, y), _mm256_mul_ps(a.z, y) };
	return r;
}

/* 8 rows of 4 values (vertex j in row j) to 4 lanes registers */
SKIN_INLINE void transpose8x4(const __m128 r[8], __m256 out[4])
{
	__m256 a[4];
#pragma GCC unroll 4
	for (int j = 0; j < 4; j++)
		a[j] = _mm256_insertf128_ps(_mm256_castps128_ps256(r[j]), r[j + 4], 1);
	__m256 t0 = _mm256_unpacklo_ps(a[0], a[1]), t1 = _mm256_unpackhi_ps(a[0], a[1]);
	__m256 t2 = _mm256_unpacklo_ps(a[2], a[3]), t3 = _mm256_unpackhi_ps(a[2], a[3]);
	out[0] = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
	out[1] = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
	out[2] = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
	out[3] = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
}

/* The blended 3x4 matrices of 8 vertices, m[i] = element i in lanes */
SKIN_INLINE void lbs_block(const infl8 *in, const skin_bones *b, __m256 m[12])
{
	__m256 head[SKIN_LANES];
	__m128 tail[SKIN_LANES];
#pragma GCC unroll 8
	for (int j = 0; j < SKIN_LANES; j++) {
		__m256 h = _mm256_setzero_ps();
		__m128 t = _mm_setzero_ps();
#pragma GCC unroll 4
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			const float *row = b->lbs12[infl_bone(in, k, j)];
			__m256 w = _mm256_broadcast_ss(in->weight[k] + j);
			h = _mm256_fmadd_ps(w, _mm256_loadu_ps(row), h);
			t = _mm_fmadd_ps(_mm256_castps256_ps128(w), _mm_loadu_ps(row + 8), t);
		}
		head[j] = h;
		tail[j] = t;
	}
	skin_transpose8(head);
#pragma GCC unroll 8
	for (int i = 0; i < 8; i++)
		m[i] = head[i];
	transpose8x4(tail, m + 8);
}

SKIN_INLINE v3x8 apply_rows(const __m256 m[12], v3x8 p, int with_translation)
{
	v3x8 r;
	__m256 *out[3] = { &r.x, &r.y, &r.z };
#pragma GCC unroll 12
	for (int row = 0; row < 3; row++) {
		const __m256 *q = m + 4 * row;
		__m256 acc = with_translation ? q[3] : _mm256_setzero_ps();
		acc = _mm256_fmadd_ps(q[0], p.x, acc);
		acc = _mm256_fmadd_ps(q[1], p.y, acc);
		*out[row] = _mm256_fmadd_ps(q[2], p.z, acc);
	}
	return r;
}

typedef struct dq8 {
	__m256 rw, rx, ry, rz, dw, dx, dy, dz;
} dq8;

/* Weighted sum with each influence's sign flipped when its real part
 * points away from the pivot (influence 0, the largest weight): the flip
 * per bone pair is looked up (flip_f, the scalar kernel's own test) and
 * xored into the bone's row as it is loaded, per vertex like the rows:
 * gathering the flips into lanes cost a third of the kernel's time. */
SKIN_INLINE dq8 dq_blend8(const infl8 *in, const skin_bones *b)
{
	__m256 r[SKIN_LANES];
#pragma GCC unroll 8
	for (int j = 0; j < SKIN_LANES; j++) {
		int pivot = infl_bone(in, 0, j);
		const float *flip = b->flip_f[pivot];
		__m256 acc = _mm256_mul_ps(_mm256_broadcast_ss(in->weight[0] + j), _mm256_loadu_ps(b->dq8[pivot]));
#pragma GCC unroll 4
		for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
			int bone = infl_bone(in, k, j);
			__m256 row = _mm256_xor_ps(_mm256_loadu_ps(b->dq8[bone]), _mm256_broadcast_ss(flip + bone));
			acc = _mm256_fmadd_ps(_mm256_broadcast_ss(in->weight[k] + j), row, acc);
		}
		r[j] = acc;
	}
	skin_transpose8(r);
	dq8 d = { r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7] };
	return d;
}

SKIN_INLINE v3x8 cross8(v3x8 a, v3x8 b)
{
	v3x8 r = { _mm256_fmsub_ps(a.y, b.z, _mm256_mul_ps(a.z, b.y)),
		   _mm256_fmsub_ps(a.z, b.x, _mm256_mul_ps(a.x, b.z)),
		   _mm256_fmsub_ps(a.x, b.y, _mm256_mul_ps(a.y, b.x)) };
	return r;
}

SKIN_INLINE v3x8 madd8(v3x8 a, v3x8 b, __m256 s)
{
	v3x8 r = { _mm256_fmadd_ps(b.x, s, a.x), _mm256_fmadd_ps(b.y, s, a.y),
		   _mm256_fmadd_ps(b.z, s, a.z) };
	return r;
}

SKIN_INLINE v3x8 add8(v3x8 a, v3x8 b)
{
	v3x8 r = { _mm256_add_ps(a.x, b.x), _mm256_add_ps(a.y, b.y), _mm256_add_ps(a.z, b.z) };
	return r;
}

/* 2 / |real|^2: an approximate reciprocal and one Newton step (relative
 * error about 1e-7, far inside the kernels' tolerance), where normalising
 * the blend would cost a square root and a division. */
SKIN_INLINE __m256 two_over_norm2(const dq8 *d)
{
	__m256 n2 = _mm256_fmadd_ps(d->rw, d->rw, _mm256_fmadd_ps(d->rx, d->rx,
				    _mm256_fmadd_ps(d->ry, d->ry, _mm256_mul_ps(d->rz, d->rz))));
	__m256 y = _mm256_rcp_ps(n2);
	y = _mm256_mul_ps(y, _mm256_fnmadd_ps(n2, y, _mm256_set1_ps(2.0f)));
	return _mm256_add_ps(y, y);
}

/* The unnormalised blend moves v to v + s (r x (r x v + w v + dv) + w dv -
 * dw r) with s = 2 / |real|^2 (fx_dq_transform_blend's form): the same as
 * normalising first and applying the rotation and translation, with one
 * cross product fewer and no square root. A normal takes the rotation
 * only. */
SKIN_INLINE v3x8 move8(const dq8 *d, __m256 s, v3x8 v, int with_dual)
{
	v3x8 r = { d->rx, d->ry, d->rz }, dv = { d->dx, d->dy, d->dz };
	v3x8 a = madd8(cross8(r, v), v, d->rw);
	if (with_dual)
		a = add8(a, dv);
	v3x8 b = cross8(r, a);
	if (with_dual)
		b = madd8(madd8(b, dv, d->rw), r, _mm256_sub_ps(_mm256_setzero_ps(), d->dw));
	return madd8(v, b, s);
}

#endif
