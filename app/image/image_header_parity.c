/* Block 0 and the header copy both lost: parity group 0 still holds block
 * 0, but its layout is in the header. Every framed block names its own
 * index and kind, so the layout is read from them: block 1 gives the id;
 * the first block of the directory copy (kind 4, item 1) lies at D + P;
 * the last directory block (version 7: digest block) before it is the last
 * data block, D - 1. Block 0 is then the XOR of parity block D and the
 * group's other data blocks, and must prove itself: its frame, its
 * header's CRC, and the same layout stated. */
#include "image_header_parity.h"

#include <string.h>

#include "image_copies.h"

/* Block b of the image whose id is id, in buf: read whole, CRC good, framed
 * with its own index. Its kind, or 0. */
static int own_block(skp_image *im, uint32_t b, const uint8_t *id, uint8_t *buf, unsigned *item)
{
	if (skp_image_read_raw(im, b, buf) != SKP_BLOCK_OK || !skp_block_crc_ok(buf, im->dev->block_size) ||
	    (id && memcmp(buf, id, SKP_IMAGE_ID_BYTES)) || le_get32(buf + SKP_IMAGE_AT_INDEX) != b)
		return 0;
	*item = le_get16(buf + SKP_IMAGE_AT_ITEM);
	return buf[SKP_IMAGE_AT_KIND];
}

/* D and D + P from the frames; 0 when they are not found. */
static int find_layout(skp_image *im, const uint8_t *id, uint32_t *data, uint32_t *dir_copy)
{
	uint32_t last_data = 0;
	unsigned item;
	for (uint32_t b = 2; b < im->dev->block_count; b++) {
		int kind = own_block(im, b, id, im->scratch, &item);
		if (kind == SKP_KIND_DIRECTORY && item == 1) {
			*data = last_data + 1;
			*dir_copy = b;
			return last_data > 0 && b > *data;
		}
		if ((kind == SKP_KIND_DIRECTORY && item == 0) || kind == SKP_KIND_DIGESTS)
			last_data = b;
	}
	return 0;
}

int skp_image_parity_header(skp_image *im, skp_image_header *h)
{
	uint32_t bs = im->dev->block_size, data, dir_copy;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	unsigned item;
	if (im->dev->block_count < 4 || own_block(im, 1, NULL, im->buf, &item) == 0)
		return 0;
	memcpy(id, im->buf, sizeof id);
	if (!find_layout(im, id, &data, &dir_copy))
		return 0;
	uint32_t parity = dir_copy - data;
	if (parity > data || skp_image_read_raw(im, data, im->buf) != SKP_BLOCK_OK)
		return 0;
	for (uint32_t b = parity; b < data; b += parity) {
		if (skp_image_read_raw(im, b, im->scratch) != SKP_BLOCK_OK)
			return 0;
		for (uint32_t i = 0; i < bs; i++)
			im->buf[i] ^= im->scratch[i];
	}
	if (!skp_block_crc_ok(im->buf, bs) || memcmp(im->buf, id, sizeof id) ||
	    le_get32(im->buf + SKP_IMAGE_AT_INDEX) != 0 || im->buf[SKP_IMAGE_AT_KIND] != SKP_KIND_HEADER ||
	    !skp_image_header_get(im->buf + SKP_IMAGE_BLOCK_HDR, bs - SKP_IMAGE_BLOCK_HDR, h))
		return 0;
	return h->block_size == bs && h->data_blocks == data && h->parity_blocks == parity &&
	       h->dir_copy == dir_copy && !memcmp(h->id, id, sizeof id);
}
