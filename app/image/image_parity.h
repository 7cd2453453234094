/* XOR parity (image_format.h): the reader's rebuild of a data block, and
 * the parity blocks the writer and repair compute. */
#ifndef IMAGE_PARITY_H
#define IMAGE_PARITY_H

#include "blockdev.h"
#include "image_block.h"
#include "image_format.h"
#include "skp_error.h"

/* Rebuilds data block `block` into buf from its parity group (the other
 * data blocks of the group and the group's parity block, read through
 * im->scratch) and checks it. SKP_BLOCK_OK when the result is the block;
 * else why not (no parity, another bad block in the group). */
skp_block_state skp_image_rebuild(skp_image *im, uint32_t block, int kind, unsigned item, uint8_t *buf);

/* P for D data blocks and groups of at most `group` blocks (0: the default,
 * 8, or larger so that parity and the header copy stay within 15%). */
uint32_t skp_parity_blocks(uint32_t data_blocks, uint32_t group);

/* Writes h's parity blocks (after its data blocks) from the data blocks on
 * dev, block 0 taken from block0 when not NULL (it is written last). acc
 * and tmp: two block buffers. */
skp_status skp_parity_write(const skp_blockdev *dev, const skp_image_header *h, const uint8_t *block0,
			    uint8_t *acc, uint8_t *tmp, skp_error *err);

#endif
