/* Version 8's texture coordinates and texture, read at the bind section's
 * end (image_format.h: BIND). Private to app/image. */
#ifndef IMAGE_LOAD_TEXTURE_H
#define IMAGE_LOAD_TEXTURE_H

#include "image_read.h"

/* Into m (uv, sampled, textured) and im->texture; a texture not kept sets
 * im->texture_skipped and leaves m->textured 0. */
skp_status image_get_texture(skp_image *im, mesh *m, skp_error *err);

#endif
