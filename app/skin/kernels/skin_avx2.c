/* AVX2+FMA kernels over the float vertex streams: eight vertices per step
 * in structure-of-arrays form. The blend runs per vertex (its bones' rows
 * times its weights broadcast) and one transpose turns the eight results
 * into lanes: gathering every bone value into lanes first costs a gather
 * or a transpose per influence (skin_avx2_float.h). Built when the board
 * sets SIMD=avx2; results match skin_scalar.c to float rounding. The small
 * fixed loops carry `#pragma GCC unroll`: left rolled, GCC keeps their
 * vectors in stack arrays (DQBS ran 30% slower). */
#include "skin_kernels.h"

#ifdef SKP_SIMD_AVX2

#include "skin_avx2_float.h"

static v3x8 load3(const float *x, const float *y, const float *z, int v)
{
	v3x8 r = { _mm256_load_ps(x + v), _mm256_load_ps(y + v), _mm256_load_ps(z + v) };
	return r;
}

SKIN_INLINE infl8 influences(const skin_soa *in, int v)
{
	infl8 s;
	s.bone_bytes = 2;
#pragma GCC unroll 4
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		s.bone[k] = in->bone[k] + v;
		s.weight[k] = in->weight[k] + v;
	}
	return s;
}

void skin_lbs_avx2(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v += SKIN_LANES) {
		__m256 m[12];
		infl8 s = influences(in, v);
		lbs_block(&s, b, m);
		int valid = end - v < SKIN_LANES ? end - v : SKIN_LANES;
		v3x8 p = apply_rows(m, load3(in->px, in->py, in->pz, v), 1);
		v3x8 n = normalize8(apply_rows(m, load3(in->nx, in->ny, in->nz, v), 0));
		skin_store_xyz8(out->pos + 3 * v, p.x, p.y, p.z, valid);
		skin_store_xyz8(out->nrm + 3 * v, n.x, n.y, n.z, valid);
	}
}

void skin_dqbs_avx2(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v += SKIN_LANES) {
		infl8 s = influences(in, v);
		dq8 d = dq_blend8(&s, b);
		__m256 two_s = two_over_norm2(&d);
		v3x8 p = move8(&d, two_s, load3(in->px, in->py, in->pz, v), 1);
		v3x8 n = move8(&d, two_s, load3(in->nx, in->ny, in->nz, v), 0);
		int valid = end - v < SKIN_LANES ? end - v : SKIN_LANES;
		skin_store_xyz8(out->pos + 3 * v, p.x, p.y, p.z, valid);
		skin_store_xyz8(out->nrm + 3 * v, n.x, n.y, n.z, valid);
	}
}

#else
typedef int skin_avx2_not_built; /* the board chose the scalar kernels */
#endif
