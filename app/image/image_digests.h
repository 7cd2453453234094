/* Every data block's own digest (format version 7, image_format.h's
 * DIGESTS): a two-level hash tree over the blocks, as dm-verity and
 * fs-verity build one, so that a block whose content changed but whose
 * CRC was made again is a bad block when it is read, not a wrong frame.
 * The writer's half is in image_write.c; the reader keeps one digest
 * block and each digest block's leaf (image_read.h's skp_image). */
#ifndef IMAGE_DIGESTS_H
#define IMAGE_DIGESTS_H

#include "image_block.h"
#include "image_format.h"
#include "skp_error.h"

/* Leaves a digest block holds at block size bs. */
uint32_t skp_digest_per_block(uint32_t bs);

/* The first block of the digest section (H: the blocks with a leaf), 0
 * for an image older than version 7. */
uint32_t skp_digest_first(const skp_image_header *h);

/* Digest blocks for leaves blocks with a leaf. */
uint32_t skp_digest_blocks(uint32_t leaves, uint32_t bs);

/* A block's leaf: the first SKP_IMAGE_LEAF_BYTES of its SHA-256. */
void skp_block_leaf(const uint8_t *block, uint32_t bs, uint8_t leaf[SKP_IMAGE_LEAF_BYTES]);

/* Reads the digest blocks of an opened image's header and checks them
 * against its root: im->digests is then 1 (every block read is checked
 * against its leaf), or 0 when the image has no digests (older than
 * version 7) or they do not give the root (im->digests_broken: blocks are
 * then checked by their CRCs alone). A digest block that is bad, or that
 * the root says was altered, is rebuilt from parity. Fails only on a
 * digest section larger than the board keeps (SKP_IMAGE_MAX_DIGEST_BLOCKS). */
skp_status skp_image_digests_open(skp_image *im, skp_error *err);

/* Whether block (a data block, in buf) matches its leaf: SKP_BLOCK_OK, or
 * SKP_BLOCK_DIGEST. Blocks without a leaf (block 0, the digest blocks,
 * parity, copies), and every block while the check is off, pass. */
skp_block_state skp_image_leaf_check(skp_image *im, uint32_t block, const uint8_t *buf);

#endif
