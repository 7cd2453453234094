/* Mip chains: each level's size as GLES2 wants it (half the one above,
 * rounded down, at least 1, down to 1x1), its bytes as ETC1 blocks and as
 * RGB565, and the box filter that makes each level from the one above. */
#ifndef TEX_MIP_H
#define TEX_MIP_H

#include <stddef.h>
#include <stdint.h>

#include "skp_error.h"

/* The largest side a texture may have: GL_MAX_TEXTURE_SIZE of the
 * Raspberry Pi 4's V3D (4096), which keeps every byte count in 32 bits. */
#define TEX_MAX_SIDE 4096
/* 4096 -> 2048 -> ... -> 1: 13 levels. */
#define TEX_MAX_LEVELS 13

typedef struct tex_level {
	int width, height;
	size_t etc1_bytes;   /* ceil(w/4) * ceil(h/4) blocks of 8 bytes */
	size_t etc1_offset;  /* where the level starts in the whole chain's blocks */
	size_t rgb565_bytes; /* w * h * 2, rows packed */
	size_t rgb8_bytes;   /* w * h * 3, rows packed */
} tex_level;

typedef struct tex_mip_chain {
	int levels;
	tex_level level[TEX_MAX_LEVELS];
	size_t etc1_bytes;   /* every level's blocks, level 0 first */
	size_t rgb565_bytes; /* every level as RGB565 */
} tex_mip_chain;

/* SKP_OK, SKP_ERR_RANGE for a side under 1, SKP_ERR_LIMIT for a side over
 * TEX_MAX_SIDE. */
skp_status tex_size_check(int width, int height, skp_error *err);

/* Bytes of a width x height image as ETC1 blocks (edge blocks padded to 4x4),
 * as RGB565 and as RGB8; 0 when the size fails tex_size_check. */
size_t tex_etc1_bytes(int width, int height);
size_t tex_rgb565_bytes(int width, int height);
size_t tex_rgb8_bytes(int width, int height);

/* Fills chain with every level of a width x height texture down to 1x1. */
skp_status tex_mip_chain_make(int width, int height, tex_mip_chain *chain, skp_error *err);

/* The next level's side: half, rounded down, at least 1. */
int tex_mip_next_side(int side);

/* Makes the next level of an RGB8 image (rows packed) into dst, which
 * holds dst_capacity bytes: tex_mip_next_side of each side. Each target
 * pixel is the rounded mean of the 2x2 source pixels under it; a side of 1
 * repeats its row or column, and an odd side's last target row or column
 * takes in the source's last row or column too (3 wide), so no source
 * pixel is dropped. */
skp_status tex_downsample_rgb8(const uint8_t *src, int width, int height,
			       uint8_t *dst, size_t dst_capacity, skp_error *err);

#endif
