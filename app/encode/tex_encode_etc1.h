/* The ETC1 encoder (host tool only: it allocates, and it searches, which
 * the boards never need to do). A block is searched exhaustively over what
 * matters: both flips, individual and differential modes, all 8 modifier
 * tables, and for each half the base colours around its mean; each pixel
 * then takes the modifier nearest to it. The error is plain squared RGB
 * error, which is what PSNR measures. tex_etc1.h decodes what it writes. */
#ifndef TEX_ENCODE_ETC1_H
#define TEX_ENCODE_ETC1_H

#include <stddef.h>
#include <stdint.h>

#include "skp_error.h"
#include "tex_etc1_block.h"
#include "tex_mip.h"

/* Encodes 16 pixels, RGB8 row by row (rgb[(y*4+x)*3]), into one block;
 * returns the block's squared error summed over pixels and channels. */
uint32_t tex_encode_etc1_block(const uint8_t rgb[4 * 4 * 3], uint8_t block[TEX_ETC1_BLOCK_BYTES]);

/* Encodes a width x height RGB8 image (rows packed) into
 * tex_etc1_bytes(width, height) bytes of blocks at blocks (capacity bytes),
 * left to right, top to bottom. Edge blocks are padded by repeating the
 * last column and row, which the decoder crops. */
skp_status tex_encode_etc1_image(const uint8_t *rgb, int width, int height,
				 uint8_t *blocks, size_t capacity, skp_error *err);

/* A whole mip chain as ETC1: level i's blocks at blocks + chain.level[i].etc1_offset. */
typedef struct tex_etc1_mipmaps {
	tex_mip_chain chain;
	uint8_t *blocks; /* chain.etc1_bytes, allocated; tex_etc1_mipmaps_free */
} tex_etc1_mipmaps;

/* Told after each row of blocks: the blocks done of every level's (a 1024
 * square takes seconds). */
typedef struct tex_encode_progress {
	void (*fn)(void *ctx, long done, long total);
	void *ctx;
} tex_encode_progress;

/* Encodes the image and every level below it (tex_downsample_rgb8 of the
 * level above, from the RGB8 source, never from decoded blocks); progress
 * NULL or told as it goes. */
skp_status tex_encode_etc1_mipmaps(const uint8_t *rgb, int width, int height, tex_etc1_mipmaps *out,
				   const tex_encode_progress *progress, skp_error *err);

void tex_etc1_mipmaps_free(tex_etc1_mipmaps *m);

#endif
