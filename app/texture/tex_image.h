/* A body's base colour texture as an image carries it and the device keeps
 * it: an ETC1 mip chain down to 1x1, level 0 first (tex_mip.h), each side a
 * power of two (GLES 2 mipmaps and repeats no other) up to the board's
 * SKP_MAX_TEXTURE_SIDE. Fixed memory, sized by the board. */
#ifndef TEX_IMAGE_H
#define TEX_IMAGE_H

#include <stdint.h>

#include "board_limits.h"
#include "skp_error.h"
#include "tex_mip.h"

/* The whole chain of a SKP_MAX_TEXTURE_SIDE square (a third more than
 * level 0's side * side / 2 bytes, and the 1x1, 2x2 levels' whole blocks). */
#define TEX_IMAGE_MAX_BYTES ((SKP_MAX_TEXTURE_SIDE * SKP_MAX_TEXTURE_SIDE / 2) / 3 * 4 + 64)

typedef struct tex_image {
	int width, height;  /* 0: none */
	tex_mip_chain chain;
	uint8_t etc1[TEX_IMAGE_MAX_BYTES];
} tex_image;

/* 1 when n is a power of two (1, 2, 4, ...). */
int tex_is_power_of_two(int n);

/* SKP_OK when this board keeps a width x height texture: both sides powers
 * of two, neither over SKP_MAX_TEXTURE_SIDE; SKP_ERR_LIMIT (said in err)
 * otherwise. */
skp_status tex_image_fits(int width, int height, skp_error *err);

/* Makes t an empty width x height texture: its chain laid out, its bytes
 * (t->chain.etc1_bytes) to be filled; fails as tex_image_fits does. */
skp_status tex_image_begin(tex_image *t, int width, int height, skp_error *err);

#endif
