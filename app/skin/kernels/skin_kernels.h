/* The skinning kernels, private to app/skin: skin_run() and
 * skin_run_compact() (skin.c) are the only way in for the rest of the
 * program. One file per instruction set and stream form: skin_scalar.c,
 * skin_fixed.c and skin_compact_scalar.c (portable, always built; the SIMD
 * kernels fall back to them), skin_avx2.c, skin_fixed_avx2.c and
 * skin_compact_avx2.c (x86-64 AVX2 + FMA, SIMD=avx2), skin_neon.c (float
 * and compact) and skin_fixed_neon.c (AArch64, SIMD=neon). A new kernel: a
 * file here, its declaration below, its case in skin.c, and its name in the
 * KERNELS_<simd> list of the SIMD settings that build it (app/sources.mk; a
 * board picks its setting with SIMD in board.mk). Each skins vertices
 * [first, end) of in with bones b into out. */
#ifndef SKIN_KERNELS_H
#define SKIN_KERNELS_H

#include "skin.h"
#include "skin_compact.h"

/* One vertex of the portable float kernels, shared with the compact ones:
 * idx and w its influences (pivot first), p and n its bind position and
 * normal. */
void skin_lbs_vertex(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES],
		     const float w[SKP_MAX_INFLUENCES], vec3 p, vec3 n, vec3 *po, vec3 *no);
void skin_dqbs_vertex(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES],
		      const float w[SKP_MAX_INFLUENCES], vec3 p, vec3 n, vec3 *po, vec3 *no);
/* A unit normal component as the compact kernels write it (rounded to
 * nearest, even on ties, as the SIMD conversion rounds). */
int16_t skin_snorm16_of(float x);

void skin_lbs_scalar(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_scalar(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_fixed(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);

void skin_lbs_compact_scalar(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_compact_scalar(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out);

#ifdef SKP_SIMD_AVX2
void skin_lbs_compact_avx2(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_compact_avx2(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_lbs_avx2(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_avx2(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_fixed_avx2(const skin_soa *in, const skin_bones *b, int first, int end,
			  const skin_out *out);
#endif

#ifdef SKP_SIMD_NEON
void skin_lbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_lbs_compact_neon(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_compact_neon(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_fixed_neon(const skin_soa *in, const skin_bones *b, int first, int end,
			  const skin_out *out);
#endif

#endif
