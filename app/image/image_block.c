/* Block I/O of the image reader: one block read whole, and the checks of
 * its frame (image_format.h: CRC, image id, index, kind and item). No
 * recovery here: image_recover.c rebuilds what fails. */
#include "image_block.h"

#include <string.h>

#include "crc32.h"
#include "image_read.h"
#include "skp_format.h"

static const char *const state_names[] = {
	"good", "I/O error", "short read", "CRC mismatch", "block of another image",
	"block out of place", "frame count differs from the directory's",
	"content differs from its digest (a block altered, its CRC made again)"
};

const char *skp_block_state_name(skp_block_state st)
{
	return (unsigned)st < sizeof state_names / sizeof state_names[0] ? state_names[st] : "?";
}

int skp_block_crc_ok(const uint8_t *block, uint32_t block_size)
{
	return crc32_compute(block, block_size - 4) == le_get32(block + block_size - 4);
}

skp_block_state skp_image_frame_check(const skp_image *im, uint32_t block, int kind, unsigned item,
				      const uint8_t *buf)
{
	uint32_t bs = im->hdr.block_size;
	if (!skp_block_crc_ok(buf, bs))
		return SKP_BLOCK_CRC;
	if (memcmp(buf, im->hdr.id, SKP_IMAGE_ID_BYTES))
		return SKP_BLOCK_FOREIGN;
	if (le_get32(buf + SKP_IMAGE_AT_INDEX) != block ||
	    (kind > 0 && (buf[SKP_IMAGE_AT_KIND] != kind || le_get16(buf + SKP_IMAGE_AT_ITEM) != item)))
		return SKP_BLOCK_MISPLACED;
	return SKP_BLOCK_OK;
}

skp_block_state skp_image_read_raw(const skp_image *im, uint32_t block, uint8_t *buf)
{
	int n = im->dev->read(im->dev->ctx, block, buf);
	if (n < 0)
		return n == SKP_BD_ERANGE ? SKP_BLOCK_SHORT : SKP_BLOCK_IO;
	return (uint32_t)n < im->hdr.block_size ? SKP_BLOCK_SHORT : SKP_BLOCK_OK;
}

skp_block_state skp_image_read_framed(skp_image *im, uint32_t block, int kind, unsigned item, uint8_t *buf)
{
	skp_block_state st = skp_image_read_raw(im, block, buf);
	return st != SKP_BLOCK_OK ? st : skp_image_frame_check(im, block, kind, item, buf);
}
