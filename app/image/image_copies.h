/* The copies of an image (image_format.h, COPIES): block 0 is the header
 * and zeros, the header copy the header at the end of the last block, the
 * directory copy the directory's payloads again after the parity. Reading:
 * finding the header copy when block 0 is bad, rebuilding a block from its
 * copy. Writing (pack, repair): the copies from the data blocks. */
#ifndef IMAGE_COPIES_H
#define IMAGE_COPIES_H

#include "image_read.h"

/* The header copy of the storage of im (im->dev, whose block size the copy
 * must have): at the storage's last block, else searched for from the
 * start. 1 with the header in *h, else 0. Uses im->buf and im->scratch. */
int skp_image_copy_header(skp_image *im, skp_image_header *h);

/* Block 0 as packed: the header h and zeros, framed and sealed. */
void skp_header_block_frame(uint8_t *buf, const skp_image_header *h);

/* The header copy block of h, framed and sealed, into buf. */
void skp_header_copy_frame(uint8_t *buf, const skp_image_header *h);

/* Reframes a directory block read in buf as the block `index`, item as
 * given (1 for the copy, 0 for the primary), and seals it. */
void skp_dir_block_reframe(uint8_t *buf, const skp_image_header *h, uint32_t index, unsigned item);

/* Writes h's directory copy (from the directory blocks on dev, read back
 * into buf) and its header copy. */
skp_status skp_image_write_copies(const skp_blockdev *dev, const skp_image_header *h, uint8_t *buf,
				  skp_error *err);

#endif
