/* The ETC1 encoder's measure of one half block (app/encode, private to
 * tex_encode_etc1*.c): its 8 pixels against a base colour, every table
 * tried, each pixel on its nearest modifier. */
#ifndef TEX_ENCODE_ETC1_HALF_H
#define TEX_ENCODE_ETC1_HALF_H

#include <stdint.h>

/* The 8 pixels of one half and where each sits in the block (y * 4 + x). */
typedef struct half_pixels {
	int rgb[8][3];
	int pos[8];
} half_pixels;

/* A half encoded with one base colour (in the stored precision). */
typedef struct half_fit {
	uint32_t error;
	uint8_t base[3];
	uint8_t table;
	uint8_t index[8];
} half_fit;

/* The pixels of half 0 or 1 of a block (16 RGB8 pixels, row by row)
 * with this flip bit. */
void tex_half_gather(const uint8_t rgb[48], int flip, int half, half_pixels *hp);

/* The best table for a stored base colour (bits: 4 or 5 a channel);
 * fit->error is UINT32_MAX when none beats bound. Table first_table is
 * tried first: a neighbour's best table is usually this colour's too, and
 * the bound it sets at once cuts the other tables short after a pixel or
 * two. */
void tex_half_fit(const half_pixels *hp, const int base[3], int bits, int first_table,
		  uint32_t bound, half_fit *fit);

#endif
