/* The skinning kernels, private to app/skin: skin_run() (skin.c) is the
 * only way in for the rest of the program. One file per instruction set:
 * skin_scalar.c and skin_fixed.c (portable, always built; the SIMD kernels
 * fall back to them), skin_avx2.c and skin_fixed_avx2.c (x86-64 AVX2 + FMA,
 * SIMD=avx2), skin_neon.c and skin_fixed_neon.c (AArch64, SIMD=neon). A new kernel: a file here,
 * its declaration below, its case in skin.c, its board in board.mk. Each
 * skins vertices [first, end) of in with bones b into out. */
#ifndef SKIN_KERNELS_H
#define SKIN_KERNELS_H

#include "skin.h"

void skin_lbs_scalar(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_scalar(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_fixed(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);

#ifdef SKP_SIMD_AVX2
void skin_lbs_avx2(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_avx2(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_fixed_avx2(const skin_soa *in, const skin_bones *b, int first, int end,
			  const skin_out *out);
#endif

#ifdef SKP_SIMD_NEON
void skin_lbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_neon(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out);
void skin_dqbs_fixed_neon(const skin_soa *in, const skin_bones *b, int first, int end,
			  const skin_out *out);
#endif

#endif
