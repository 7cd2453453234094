/* Inside the image reader: a section read as one byte stream across its
 * blocks (each block checked, and recovered, as it is read). Private to
 * app/image. */
#ifndef IMAGE_SECTION_H
#define IMAGE_SECTION_H

#include "image_read.h"

/* Starts reading section sec, whose blocks are of kind and item. */
void sec_open(skp_image *im, const skp_image_section *sec, uint8_t kind, uint16_t item);
/* The next n bytes of the open section. */
skp_status sec_get(skp_image *im, void *out, uint32_t n, skp_error *err);
/* The block the stream's last bytes came from, for messages. */
long sec_block(const skp_image *im);
/* A corrupt section: what is wrong, at the current block. */
skp_status sec_bad(skp_image *im, skp_error *err, const char *what);
/* Little-endian values, floats, and a length-prefixed name. */
skp_status sec_u8(skp_image *im, uint8_t *v, skp_error *err);
skp_status sec_u16(skp_image *im, uint16_t *v, skp_error *err);
skp_status sec_u32(skp_image *im, uint32_t *v, skp_error *err);
skp_status sec_floats(skp_image *im, float *v, int n, skp_error *err);
skp_status sec_str(skp_image *im, char *s, skp_error *err);

#endif
