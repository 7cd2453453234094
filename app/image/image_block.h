/* Block I/O of the image reader (image_block.c): a block read whole, and
 * the checks of its frame (image_format.h), each failure named. A block's
 * digest (image_digests.h) and recovering a block that fails are
 * image_recover.h's. */
#ifndef IMAGE_BLOCK_H
#define IMAGE_BLOCK_H

#include <stdint.h>

typedef struct skp_image skp_image; /* image_read.h */

/* Why a block is not usable. */
typedef enum skp_block_state {
	SKP_BLOCK_OK = 0,
	SKP_BLOCK_IO,        /* the storage reported an error */
	SKP_BLOCK_SHORT,     /* fewer bytes than a block (truncated storage) */
	SKP_BLOCK_CRC,       /* CRC mismatch */
	SKP_BLOCK_FOREIGN,   /* good CRC, but another image's (its id) */
	SKP_BLOCK_MISPLACED, /* good CRC, but its index or kind is not this one's */
	SKP_BLOCK_COUNT,     /* a frames block whose frame count is not the directory's */
	SKP_BLOCK_DIGEST     /* good CRC and frame, but its content is not its digest's (version 7) */
} skp_block_state;

/* "CRC mismatch", "I/O error", ... */
const char *skp_block_state_name(skp_block_state st);

/* Whether a raw block's CRC-32 matches (no other check). */
int skp_block_crc_ok(const uint8_t *block, uint32_t block_size);

/* Reads block into buf and checks its frame (its CRC, the image's id, its
 * index, and when kind > 0 its kind and item). Its digest too:
 * skp_image_check_block (image_recover.h). */
skp_block_state skp_image_read_framed(skp_image *im, uint32_t block, int kind, unsigned item, uint8_t *buf);

/* Only the read (a whole block, no check): parity blocks have no frame. */
skp_block_state skp_image_read_raw(const skp_image *im, uint32_t block, uint8_t *buf);

/* The frame check of a block already in buf (CRC, id, index, kind). */
skp_block_state skp_image_frame_check(const skp_image *im, uint32_t block, int kind, unsigned item,
				      const uint8_t *buf);


#endif
