/* The bit layout of one ETC1 block (Khronos Data Format Specification,
 * "ETC1": OES_compressed_ETC1_RGB8_texture), apart from what its fields
 * mean, so that the decoder and the encoder share one description of it.
 *
 * A block is 64 bits stored big-endian (byte 0 holds bits 63..56):
 *   individual mode (diff bit 0): R1 R2 G1 G2 B1 B2, 4 bits each;
 *   differential mode (diff bit 1): R1 dR2 G1 dG2 B1 dB2, a 5-bit base and a
 *     3-bit two's complement delta each;
 *   then table 1 (3 bits), table 2 (3 bits), diff bit, flip bit (byte 3);
 *   then the pixel indices: 16 most significant bits, 16 least significant
 *     bits, pixel (x, y) at bit x * 4 + y of each (columns first). */
#ifndef TEX_ETC1_BLOCK_H
#define TEX_ETC1_BLOCK_H

#include <stdint.h>

#define TEX_ETC1_BLOCK_BYTES 8

/* A block's fields. Indices are 0..3, the value (msb << 1) | lsb, and run
 * row by row here (index[y * 4 + x]), the order images are stored in. */
typedef struct tex_etc1_fields {
	uint8_t differential; /* 0: individual, 1: differential */
	uint8_t flip;         /* 0: two 2x4 halves side by side, 1: two 4x2 halves stacked */
	/* the halves' base colours as stored: 4-bit values (individual) or
	 * 5-bit values (differential: base[1] is base[0] plus the delta) */
	uint8_t base[2][3];
	uint8_t table[2];     /* 0..7: the modifier table of each half */
	uint8_t index[16];
} tex_etc1_fields;

/* Reads a block. In differential mode base[1] is base[0] + delta taken
 * modulo 32: the specification leaves a sum outside 0..31 undefined (ETC2
 * gives it other meanings); wrapping keeps every block decodable. */
void tex_etc1_unpack(const uint8_t block[TEX_ETC1_BLOCK_BYTES], tex_etc1_fields *f);

/* Writes a block. Returns 0, or -1 (block untouched) when a field is out
 * of its range: a base or table too large, or in differential mode
 * base[1] - base[0] outside -4..3 on some channel. */
int tex_etc1_pack(const tex_etc1_fields *f, uint8_t block[TEX_ETC1_BLOCK_BYTES]);

/* 1 when pixel (x, y) of a 4x4 block lies in half 1 of a block with this
 * flip bit (the right half, or the bottom half when flipped). */
int tex_etc1_in_second_half(int flip, int x, int y);

#endif
