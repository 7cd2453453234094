/* Shared by the NEON kernels: moving four vertices between the per-vertex
 * and the per-lane layouts. Bit moves only, so the fixed-point kernel uses
 * them too (float vectors pass through vreinterpretq). */
#ifndef SKIN_NEON_H
#define SKIN_NEON_H

#include <arm_neon.h>
#include <string.h>

#define NEON_LANES 4

/* The kernels inline every helper (and unroll every loop) so that values
 * stay in registers: left to -O2, the helpers were calls passing arrays
 * of vectors through the stack, three to five times the instructions. */
#define NEON_INLINE static inline __attribute__((always_inline))

/* r[j] = 4 values of vertex j  ->  r[c] = value c of the 4 vertices */
static inline void skin_transpose4(int32x4_t r[4])
{
	int32x4_t t0 = vtrn1q_s32(r[0], r[1]), t1 = vtrn2q_s32(r[0], r[1]);
	int32x4_t t2 = vtrn1q_s32(r[2], r[3]), t3 = vtrn2q_s32(r[2], r[3]);
	r[0] = vreinterpretq_s32_s64(vtrn1q_s64(vreinterpretq_s64_s32(t0), vreinterpretq_s64_s32(t2)));
	r[1] = vreinterpretq_s32_s64(vtrn1q_s64(vreinterpretq_s64_s32(t1), vreinterpretq_s64_s32(t3)));
	r[2] = vreinterpretq_s32_s64(vtrn2q_s64(vreinterpretq_s64_s32(t0), vreinterpretq_s64_s32(t2)));
	r[3] = vreinterpretq_s32_s64(vtrn2q_s64(vreinterpretq_s64_s32(t1), vreinterpretq_s64_s32(t3)));
}

/* The first `valid` of 4 xyz triples of 32-bit values, interleaved, at dst. */
static inline void skin_store_xyz4(void *dst, int32x4_t x, int32x4_t y, int32x4_t z, int valid)
{
	int32x4x3_t t = { { x, y, z } };
	if (valid == NEON_LANES) {
		vst3q_s32((int32_t *)dst, t);
		return;
	}
	int32_t tmp[3 * NEON_LANES];
	vst3q_s32(tmp, t);
	memcpy(dst, tmp, sizeof(int32_t) * 3 * (size_t)valid);
}

#endif
