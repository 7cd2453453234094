/* Skinning: per-frame bone transforms and the three kernels (LBS, DQBS in
 * float, DQBS in fixed point) over vertex data laid out for SIMD.
 *
 * Bone transforms (contract): R_b = G_pose_b * G_bind_b^T and
 * t_b = head_pose_b - R_b * head_bind_b, with head the bone's start (its
 * parent's tip; the root's position) and G the FK rotation.
 *
 * Vertex data is a structure of arrays padded to SKIN_LANES vertices, with
 * exactly SKP_MAX_INFLUENCES (bone, weight) slots per vertex, largest weight
 * first (the DQBS pivot), unused slots weight 0. All arrays live in one
 * caller-provided block (skin_soa_bytes), so the runtime keeps it static and
 * a benchmark may allocate a bigger one. */
#ifndef SKIN_H
#define SKIN_H

#include <stddef.h>
#include <stdint.h>

#include "dq.h"
#include "fixed.h"
#include "fk.h"
#include "mesh.h"
#include "rigid.h"
#include "skin_weights.h"
#include "modes.h"
#include "skp_error.h"

#define SKIN_LANES 8
#define SKIN_ALIGN 32
/* Slot of an identity transform after the skeleton's bones: vertices with
 * no influence stay where they were bound. */
#define SKIN_IDENTITY_BONE SKP_MAX_BONES

typedef struct skin_soa {
	int count;                 /* vertices */
	int padded;                /* count rounded up to SKIN_LANES */
	float *px, *py, *pz;       /* bind-pose positions */
	float *nx, *ny, *nz;       /* bind-pose unit normals */
	uint16_t *bone[SKP_MAX_INFLUENCES];
	float *weight[SKP_MAX_INFLUENCES];
	/* the fixed-point kernel's copies: its per-frame path never converts */
	fx_pos *fpx, *fpy, *fpz;   /* Q15.16 */
	fx_q30 *fnx, *fny, *fnz;   /* Q2.30 */
	fx_w15 *fweight[SKP_MAX_INFLUENCES];
} skin_soa;

/* Bytes of the block skin_soa_attach needs for count vertices, as a
 * constant expression for static blocks: per padded vertex 6 float + 3
 * fx_pos + 3 fx_q30 + 4 float weights of 4 bytes and 4 bone + 4 fx_w15 of
 * 2 bytes, each array rounded up to SKIN_ALIGN. */
#define SKIN_SOA_ALIGN_UP(n) (((size_t)(n) + SKIN_ALIGN - 1) / SKIN_ALIGN * SKIN_ALIGN)
#define SKIN_SOA_PADDED(count) (((size_t)(count) + SKIN_LANES - 1) / SKIN_LANES * SKIN_LANES)
#define SKIN_SOA_BYTES(count)                                                              \
	((6 + 3 + 3 + SKP_MAX_INFLUENCES) * SKIN_SOA_ALIGN_UP(SKIN_SOA_PADDED(count) * 4) + \
	 2 * SKP_MAX_INFLUENCES * SKIN_SOA_ALIGN_UP(SKIN_SOA_PADDED(count) * 2))

/* The next array of a block being carved into arrays (skin_soa_attach,
 * skin_compact_attach): bytes long, the cursor moved past it to the next
 * SKIN_ALIGN boundary. */
static inline void *skin_carve(char **cursor, size_t bytes)
{
	void *p = *cursor;
	*cursor += SKIN_SOA_ALIGN_UP(bytes);
	return p;
}

/* SKIN_SOA_BYTES for a count known at run time. */
size_t skin_soa_bytes(int count);

/* Carves the arrays of s out of mem (SKIN_ALIGN-aligned, skin_soa_bytes
 * long) for count vertices. */
void skin_soa_attach(skin_soa *s, void *mem, int count);

/* Fills s (attached for m->vert_count vertices) from a mesh and its weights.
 * Fails on a weight naming a bone index >= bone_count, or a position out
 * of the fixed-point range. */
skp_status skin_soa_load(skin_soa *s, const mesh *m, const skin_weights *w, int bone_count,
			 skp_error *err);

/* See skin_bones.simd_ok. */
#define SKIN_SIMD_DUAL_LIMIT ((int32_t)1 << 26)

/* The SIMD boards' kernels look the DQBS sign fix up (see skin_bones). */
#if defined(SKP_SIMD_AVX2) || defined(SKP_SIMD_NEON)
#define SKIN_SIMD_FLIPS 1
#endif
/* The SIMD fixed kernel's rows, which skin_bones.fdq_at points into. */
#if defined(SKP_SIMD_AVX2)
#define SKIN_FIXED_ROWS fdq_halves
#elif defined(SKP_SIMD_NEON)
#define SKIN_FIXED_ROWS fdq_signed
#endif

/* Per-frame transforms of every bone, in the forms the kernels read. */
typedef struct skin_bones {
	int count;
	rigid mat[SKP_MAX_BONES + 1];
	dq dq[SKP_MAX_BONES + 1];
	fx_dq fdq[SKP_MAX_BONES + 1];
	/* flat copies for SIMD gathers: 3x4 row-major, and real|dual */
	float lbs12[SKP_MAX_BONES + 1][12];
	float dq8[SKP_MAX_BONES + 1][8];
#ifdef SKIN_SIMD_FLIPS
	/* The DQBS sign fix depends only on the pair (pivot bone, bone): the
	 * decision for every pair, computed once per frame with the dot
	 * product the scalar kernel uses (float for the float kernels, the
	 * exact int64 one for the fixed-point kernels), so the SIMD kernels
	 * look it up per vertex and bone (as they load the bone's row) instead
	 * of recomputing it: as the sign bit the float kernels xor into a row
	 * (flip_f, AVX2) or as the byte offset of the row to load, the bone's
	 * or its negation (the *_at tables). fdq_at [pivot][bone] is that
	 * offset in the fixed kernel's rows, SKIN_FIXED_ROWS (the bone's
	 * [bone][0], its negation [bone][1]). simd_ok is 0 when the frame's
	 * bones do not fit what the SIMD fixed kernel's rows can hold (see
	 * there): it then takes the scalar path for the frame. */
	uint16_t fdq_at[SKP_MAX_BONES + 1][SKP_MAX_BONES + 1];
	int simd_ok;
#endif
#ifdef SKP_SIMD_AVX2
	/* flip_f holds the sign bit, -0.0f (flip) or 0.0f, which the float
	 * kernels xor into the row as they load it (a row picked by offset
	 * measured slower here: its load waits on the offset's). */
	float flip_f[SKP_MAX_BONES + 1][SKP_MAX_BONES + 1];
	/* fdq ([0]) and its negation ([1]) with every component c split as
	 * c = hi * 2^16 + lo, lo and hi signed 16-bit halves, laid out as lo
	 * of components 0-3, hi of 0-3, lo of 4-7, hi of 4-7: a 16-bit unpack
	 * of two bones' rows then pairs their lo (or hi) halves component by
	 * component, and the AVX2 fixed kernel blends them with 16-bit
	 * multiply-adds. simd_ok is 0 when a dual component is 2^26 (1024
	 * units) or longer: beyond that the kernel's 32-bit intermediates
	 * could overflow where the scalar kernel saturates. */
	int16_t fdq_halves[SKP_MAX_BONES + 1][2][16];
#endif
#ifdef SKP_SIMD_NEON
	/* dq8 and fdq ([0]) with their negations ([1]), and at [pivot][bone]
	 * the byte offset of the row bone takes in a blend around pivot: the
	 * sign fix picks a row instead of negating the weight, one load per
	 * influence (on AVX2 the xor measured faster: there the row's load
	 * would wait on the offset's). simd_ok is 0 when a dual component of
	 * fdq saturated to INT32_MIN (a translation of 65536 units or more),
	 * whose negation int32 cannot hold. */
	float dq8_signed[SKP_MAX_BONES + 1][2][8];
	fx_dq fdq_signed[SKP_MAX_BONES + 1][2];
	uint16_t dq8_at[SKP_MAX_BONES + 1][SKP_MAX_BONES + 1];
#endif
#if FX_NARROW_MUL
	/* fdq split once a frame for the fixed kernel of a core without a
	 * 32 x 32 -> 64 multiply (Cortex-M0): each component c as its high
	 * half c >> 16 ([0]) and its low half c & 0xffff ([1]). */
	int32_t fdq_split[SKP_MAX_BONES + 1][2][8];
#endif
} skin_bones;

void skin_bones_compute(skin_bones *out, const skel *s, const skel_pose *bind,
			const skel_pose *pose);

/* Recomputes the SIMD kernels' tables (the sign fix's and the rows' from
 * dq, dq8 and fdq), for a caller that set fdq or dq itself. */
void skin_bones_derive(skin_bones *out);

/* Where a kernel writes: float kernels xyz triples in pos/nrm, the
 * fixed-point kernel Q16.16 triples (GL_FIXED) in fpos/fnrm, the compact
 * kernels (skin_compact.h) float positions in pos and 16-bit snorm normals
 * in nrm16. */
typedef struct skin_out {
	float *pos, *nrm;
	int32_t *fpos, *fnrm;
	int16_t *nrm16;
} skin_out;

/* Skins vertices [first, first + count) of in; first must be a multiple of
 * SKIN_LANES (worker threads split the mesh on lane boundaries). */
void skin_run(skin_algo algo, const skin_soa *in, const skin_bones *b, int first, int count,
	      const skin_out *out);

/* Part `slice` of `slices` (0-based) of padded vertices, as worker
 * threads take them: the parts split the mesh on lane boundaries. */
void skin_slice(int padded, int slice, int slices, int *first, int *count);

/* "avx2+fma" or "scalar": which float kernels skin_run uses. */
const char *skin_simd_name(void);

#endif
