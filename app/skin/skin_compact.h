/* Compact vertex streams: the bound mesh in 20 bytes a vertex instead of
 * the float streams' 48, for the compact kernels (skin_run_compact), which
 * write positions as float and normals as 16-bit snorm (GL_SHORT,
 * normalised): 38 bytes moved per vertex against the float path's 72.
 *
 *   position   3 x u16   origin + q * step over the mesh's bounds
 *   normal     2 x i16   octahedral (32767 = 1), about 3e-5 rad
 *   weights    3 x u16   influences 1..3 in 1/65535; the pivot's (the
 *                        largest, influence 0) is 65535 minus their sum,
 *                        so they always sum to exactly 1
 *   bones      4 x u8    bone index (SKP_MAX_BONES < 256)
 *
 * The error this adds to a skinned position is at most half a step on each
 * axis (skin_compact_position_bound) plus what the weights' 1/65535 steps
 * move it; tests/integration/test_skin_reference.c measures it on every
 * frame of a CMU walk and on the twist and bend scenes, and requires it
 * below 1e-4 of the mesh's extent. */
#ifndef SKIN_COMPACT_H
#define SKIN_COMPACT_H

#include <math.h>

#include "skin.h"

_Static_assert(SKP_MAX_BONES < 256, "compact streams hold bone indices (and the identity slot) in 8 bits");

#define SKIN_COMPACT_NORMAL_ONE 32767.0f
#define SKIN_COMPACT_WEIGHT_ONE 65535u

typedef struct skin_compact {
	int count, padded;
	float origin[3], step[3];                  /* position = origin + q * step */
	uint16_t *qx, *qy, *qz;
	int16_t *ox, *oy;                          /* octahedral normal */
	uint16_t *weight[SKP_MAX_INFLUENCES - 1];  /* influences 1.. (see above) */
	uint8_t *bone[SKP_MAX_INFLUENCES];
} skin_compact;

/* Bytes of the block skin_compact_attach needs, as a constant expression:
 * per padded vertex 5 + 3 arrays of 2 bytes and 4 of 1 byte, each rounded
 * up to SKIN_ALIGN. */
#define SKIN_COMPACT_BYTES(count)                                                                \
	((5 + SKP_MAX_INFLUENCES - 1) * SKIN_SOA_ALIGN_UP(SKIN_SOA_PADDED(count) * 2) +        \
	 SKP_MAX_INFLUENCES * SKIN_SOA_ALIGN_UP(SKIN_SOA_PADDED(count)))

/* Bytes a compact kernel reads and writes per vertex. */
#define SKIN_COMPACT_BYTES_MOVED (2 * (5 + SKP_MAX_INFLUENCES - 1) + SKP_MAX_INFLUENCES + 12 + 6)

size_t skin_compact_bytes(int count);

/* Carves c's arrays out of mem (SKIN_ALIGN-aligned, skin_compact_bytes
 * long) for count vertices. */
void skin_compact_attach(skin_compact *c, void *mem, int count);

/* Quantises the float streams s (loaded for the same count) into c. */
void skin_compact_load(skin_compact *c, const skin_soa *s);

/* The largest distance a decoded position lies from the float one: half a
 * step on each axis (plus the decode's float rounding, an ulp or two of
 * the coordinate). */
float skin_compact_position_bound(const skin_compact *c);

/* The quantisation the compact streams and the image's bind section
 * (format version 3) share. Bounds of count values `stride` floats apart:
 * origin the least, step the 16-bit step covering them (0 when they are
 * all the same). */
void skin_quant_bounds(const float *values, int count, int stride, float *origin, float *step);
/* The nearest q of origin + q * step (0 for step 0), clamped to 0..65535. */
uint16_t skin_quantise(float x, float origin, float step);
/* The octahedral pair nearest the unit normal n. */
void skin_oct_encode(vec3 n, int16_t *ox, int16_t *oy);

/* The unit normal an octahedral pair stands for (before normalising: the
 * kernels normalise it as they load it). */
static inline vec3 skin_oct_decode(int16_t ox, int16_t oy)
{
	float x = (float)ox / SKIN_COMPACT_NORMAL_ONE, y = (float)oy / SKIN_COMPACT_NORMAL_ONE;
	float z = 1.0f - fabsf(x) - fabsf(y), t = z < 0.0f ? -z : 0.0f;
	return vec3_make(x >= 0.0f ? x - t : x + t, y >= 0.0f ? y - t : y + t, z);
}

/* Skins vertices [first, first + count) of in (first a multiple of
 * SKIN_LANES) with LBS or DQBS into out->pos (float xyz) and out->nrm16
 * (snorm16 xyz); the other algorithms have no compact kernel. */
void skin_run_compact(skin_algo algo, const skin_compact *in, const skin_bones *b, int first, int count,
		      const skin_out *out);

#endif
