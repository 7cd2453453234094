/* The GPU's texture (rig_colour.h) as an image carries it (tex_image.h):
 * each side the power of two nearest its own (a 1000-pixel side becomes
 * 1024, a 600 one 512), at most the board's SKP_MAX_TEXTURE_SIDE; area
 * resampled where it shrinks; rows bottom first, as GL uploads them; ETC1
 * with every mip level. Host only: it allocates. */
#ifndef RIG_TEXTURE_H
#define RIG_TEXTURE_H

#include <stdint.h>

#include "skp_error.h"
#include "tex_encode_etc1.h"
#include "tex_image.h"

/* The side a texture of side pixels gets on this board. */
int rig_texture_side(int side);

/* Encodes the RGBA8 texture (w x h, top row first; alpha dropped) into
 * out, telling progress (NULL: nothing) as it goes. Fails (err said) when
 * the board keeps no texture or memory runs out. */
skp_status rig_texture_make(const uint8_t *rgba, int w, int h, tex_image *out, const tex_encode_progress *progress,
			    skp_error *err);

#endif
