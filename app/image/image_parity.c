/* XOR parity over interleaved groups of blocks (image_format.h):
 * rebuilding a data block at read time, and computing the parity blocks when
 * an image is written or repaired. Fixed memory: the caller's block buffers. */
#include "image_parity.h"

#include <string.h>

#include "image_copies.h"
#include "image_error.h"
#include "image_read.h"

static void xor_into(uint8_t *acc, const uint8_t *b, uint32_t n)
{
	for (uint32_t i = 0; i < n; i++)
		acc[i] ^= b[i];
}

skp_block_state skp_image_rebuild(skp_image *im, uint32_t block, int kind, unsigned item, uint8_t *buf)
{
	const skp_image_header *h = &im->hdr;
	uint32_t p = h->parity_blocks, bs = h->block_size;
	if (p == 0 || block >= h->data_blocks)
		return SKP_BLOCK_CRC;
	uint32_t g = block % p;
	skp_block_state st = skp_image_read_raw(im, h->data_blocks + g, buf);
	for (uint32_t b = g; b < h->data_blocks && st == SKP_BLOCK_OK; b += p) {
		if (b == block)
			continue;
		st = skp_image_read_raw(im, b, im->scratch);
		/* block 0 holds the header alone: made again from it (its copy
		 * gave it) when block 0 itself is bad, so its group's other bad
		 * block still rebuilds */
		if (b == 0 && (st != SKP_BLOCK_OK || !skp_block_crc_ok(im->scratch, bs) ||
			       memcmp(im->scratch, h->id, SKP_IMAGE_ID_BYTES))) {
			skp_header_block_frame(im->scratch, h);
			st = SKP_BLOCK_OK;
		}
		xor_into(buf, im->scratch, bs);
	}
	return st != SKP_BLOCK_OK ? st : skp_image_frame_check(im, block, kind, item, buf);
}

uint32_t skp_parity_blocks(uint32_t data_blocks, uint32_t group)
{
	if (data_blocks == 0)
		return 0;
	if (group == 0) {
		/* the default: groups of 8, larger when parity and the header
		 * copy would be more than 15% */
		group = SKP_IMAGE_DEFAULT_GROUP;
		while (group < data_blocks &&
		       (uint64_t)((data_blocks + group - 1) / group + 1) * 100 > (uint64_t)data_blocks * 15)
			group++;
	}
	return (data_blocks + group - 1) / group;
}

skp_status skp_parity_write(const skp_blockdev *dev, const skp_image_header *h, const uint8_t *block0,
			    uint8_t *acc, uint8_t *tmp, skp_error *err)
{
	uint32_t bs = h->block_size, p = h->parity_blocks;
	for (uint32_t g = 0; g < p; g++) {
		memset(acc, 0, bs);
		for (uint32_t b = g; b < h->data_blocks; b += p) {
			const uint8_t *src = b == 0 && block0 ? block0 : tmp;
			if (src == tmp && dev->read(dev->ctx, b, tmp) != (int)bs)
				return image_block_fail(err, SKP_ERR_IO, b, "cannot read it back to compute parity");
			xor_into(acc, src, bs);
		}
		uint32_t parity_block = h->data_blocks + g;
		if (dev->write(dev->ctx, parity_block, acc) < 0)
			return image_block_fail(err, SKP_ERR_IO, parity_block, "cannot write this parity block");
	}
	return SKP_OK;
}
