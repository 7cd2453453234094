/* The checks a block must pass (its frame, then its digest) and reading a
 * block with its recovery (image_recover.c): from the block's parity group
 * (image_parity.h), else from its copy (image_copies.h). */
#ifndef IMAGE_RECOVER_H
#define IMAGE_RECOVER_H

#include "image_block.h"

/* Reads block into buf and checks it: its frame (its CRC, the image's id,
 * its index, and when kind > 0 its kind and item), then its digest
 * (image_digests.h). No recovery: what the storage holds. */
skp_block_state skp_image_check_block(skp_image *im, uint32_t block, int kind, unsigned item,
				      uint8_t *buf);

/* The frame check, then the digest's, of a block already in buf. */
skp_block_state skp_image_content_check(skp_image *im, uint32_t block, int kind, unsigned item,
					const uint8_t *buf);

/* Reads block into buf and checks it: its CRC, the image's id, its index,
 * and when kind > 0 its kind and item. A block that fails is recovered when
 * it can be (skp_image_recover: then SKP_BLOCK_OK, on_rebuild told);
 * otherwise the first failure is returned. */
skp_block_state skp_image_read_block(skp_image *im, uint32_t block, int kind, unsigned item,
				     uint8_t *buf);

/* Recovers a bad block into buf: a data block from its parity group, else
 * from its copy (block 0 from the header; a directory block from the
 * directory copy); a copy from what it copies. SKP_BLOCK_OK when buf now
 * holds the block as packed, else why not. */
skp_block_state skp_image_recover(skp_image *im, uint32_t block, int kind, unsigned item, uint8_t *buf);

#endif
