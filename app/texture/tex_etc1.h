/* ETC1 decoding (OES_compressed_ETC1_RGB8_texture, Khronos Data Format
 * Specification, "ETC1"): a block into RGB8, and a whole image into RGB565
 * rows for a GPU that cannot sample ETC1 itself. The block layout is in
 * tex_etc1_block.h. */
#ifndef TEX_ETC1_H
#define TEX_ETC1_H

#include <stddef.h>
#include <stdint.h>

#include "skp_error.h"
#include "tex_etc1_block.h"

/* The specification's 8 intensity modifier tables, by pixel index
 * (msb << 1 | lsb): +a, +b, -a, -b. */
extern const int16_t tex_etc1_modifier[8][4];

/* A stored base colour channel to 8 bits: 4-bit values as v * 17, 5-bit
 * ones as (v << 3) | (v >> 2). */
int tex_etc1_expand4(int v);
int tex_etc1_expand5(int v);

/* The 8-bit base colours of both halves of a block. */
void tex_etc1_base_colours(const tex_etc1_fields *f, int rgb[2][3]);

/* Decodes one block into 16 pixels, RGB8, row by row (rgb[(y*4+x)*3]). */
void tex_etc1_decode_block(const uint8_t block[TEX_ETC1_BLOCK_BYTES], uint8_t rgb[4 * 4 * 3]);

/* Decodes a width x height image stored as ceil(w/4) * ceil(h/4) blocks,
 * left to right, top to bottom (blocks_bytes of them at blocks), into
 * RGB565 rows of width pixels (rgb565_bytes at rgb565): the edge blocks'
 * padding is cropped. Fails, writing nothing, on a bad size or a buffer
 * too small. */
skp_status tex_etc1_decode_rgb565(const uint8_t *blocks, size_t blocks_bytes, int width, int height,
				  uint16_t *rgb565, size_t rgb565_bytes, skp_error *err);

#endif
