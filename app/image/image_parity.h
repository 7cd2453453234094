/* Parity for the image writer and repair (image_format.h). The reader's
 * side, skp_image_rebuild, is declared in image_read.h. */
#ifndef IMAGE_PARITY_H
#define IMAGE_PARITY_H

#include "blockdev.h"
#include "image_format.h"
#include "skp_error.h"

/* P for D data blocks and groups of at most `group` blocks (0: the default,
 * 8, or larger so that parity and the header copy stay within 15%). */
uint32_t skp_parity_blocks(uint32_t data_blocks, uint32_t group);

/* Writes h's parity blocks (after its data blocks) from the data blocks on
 * dev, block 0 taken from block0 when not NULL (it is written last). acc
 * and tmp: two block buffers. */
skp_status skp_parity_write(const skp_blockdev *dev, const skp_image_header *h, const uint8_t *block0,
			    uint8_t *acc, uint8_t *tmp, skp_error *err);

#endif
