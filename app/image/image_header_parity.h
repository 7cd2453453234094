/* The header when block 0 and its copy are both lost (image_format.h,
 * COPIES and PARITY): block 0 rebuilt from parity group 0, whose layout is
 * read from the blocks themselves (image_header_parity.c). */
#ifndef IMAGE_HEADER_PARITY_H
#define IMAGE_HEADER_PARITY_H

#include "image_read.h"

/* 1 with the header rebuilt into h: block 0 made again from parity group
 * 0 (the data blocks and the parity block found by their frames), framed
 * as block 0 with the image's id, its header whole and the layout it
 * states the one found. 0 when the blocks do not give one. Uses im->buf
 * and im->scratch. */
int skp_image_parity_header(skp_image *im, skp_image_header *h);

#endif
