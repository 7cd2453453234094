/* The image header's bytes and the block frame (image_format.h). */
#include <string.h>

#include "crc32.h"
#include "image_format.h"

/* The fields of the header, in order, after magic, version and size. */
static void put_layout(uint8_t *p, const skp_image_header *h)
{
	le_put32(p + 12, h->block_size);
	le_put32(p + 16, h->block_count);
	le_put64(p + 20, h->sequence);
	memcpy(p + 28, h->id, SKP_IMAGE_ID_BYTES);
	const uint32_t needs[6] = { h->bones, h->dofs, h->verts, h->tris, h->influences, h->clips };
	for (int i = 0; i < 6; i++)
		le_put32(p + 44 + 4 * i, needs[i]);
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		le_put32(p + 68 + 12 * i, h->sec[i].first);
		le_put32(p + 72 + 12 * i, h->sec[i].count);
		le_put32(p + 76 + 12 * i, h->sec[i].bytes);
	}
	le_put32(p + 116, h->data_blocks);
	le_put32(p + 120, h->parity_blocks);
	le_put32(p + 124, h->dir_copy);
	le_put32(p + 128, h->copy_block);
	memcpy(p + 132, h->digest, SKP_IMAGE_DIGEST_BYTES);
}

static void get_layout(const uint8_t *p, skp_image_header *h)
{
	h->block_size = le_get32(p + 12);
	h->block_count = le_get32(p + 16);
	h->sequence = le_get64(p + 20);
	memcpy(h->id, p + 28, SKP_IMAGE_ID_BYTES);
	uint32_t *needs[6] = { &h->bones, &h->dofs, &h->verts, &h->tris, &h->influences, &h->clips };
	for (int i = 0; i < 6; i++)
		*needs[i] = le_get32(p + 44 + 4 * i);
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		h->sec[i].first = le_get32(p + 68 + 12 * i);
		h->sec[i].count = le_get32(p + 72 + 12 * i);
		h->sec[i].bytes = le_get32(p + 76 + 12 * i);
	}
	h->data_blocks = le_get32(p + 116);
	h->parity_blocks = le_get32(p + 120);
	h->dir_copy = le_get32(p + 124);
	h->copy_block = le_get32(p + 128);
	memcpy(h->digest, p + 132, SKP_IMAGE_DIGEST_BYTES);
}

void skp_image_header_put(uint8_t *p, const skp_image_header *h)
{
	memset(p, 0, SKP_IMAGE_HEADER_SIZE);
	memcpy(p, SKP_IMAGE_MAGIC, 8);
	le_put16(p + 8, h->version ? h->version : SKP_IMAGE_VERSION);
	le_put16(p + 10, SKP_IMAGE_HEADER_SIZE);
	put_layout(p, h);
	le_put32(p + SKP_IMAGE_HEADER_SIZE - 4, crc32_compute(p, SKP_IMAGE_HEADER_SIZE - 4));
}

int skp_image_header_get(const uint8_t *p, uint32_t n, skp_image_header *h)
{
	memset(h, 0, sizeof *h);
	if (n < 12 || memcmp(p, SKP_IMAGE_MAGIC, 8))
		return 0;
	h->version = le_get16(p + 8);
	h->header_size = le_get16(p + 10);
	if (h->version < SKP_IMAGE_VERSION_MIN || h->version > SKP_IMAGE_VERSION || h->header_size != SKP_IMAGE_HEADER_SIZE || n < SKP_IMAGE_HEADER_SIZE)
		return 0;
	get_layout(p, h);
	h->crc = le_get32(p + SKP_IMAGE_HEADER_SIZE - 4);
	return crc32_compute(p, SKP_IMAGE_HEADER_SIZE - 4) == h->crc;
}

void skp_block_frame(uint8_t *block, const uint8_t id[SKP_IMAGE_ID_BYTES], uint32_t index, int kind,
		     unsigned item)
{
	memcpy(block, id, SKP_IMAGE_ID_BYTES);
	le_put32(block + SKP_IMAGE_AT_INDEX, index);
	block[SKP_IMAGE_AT_KIND] = (uint8_t)kind;
	block[SKP_IMAGE_AT_KIND + 1] = 0;
	le_put16(block + SKP_IMAGE_AT_ITEM, (uint16_t)item);
}

void skp_block_seal(uint8_t *block, uint32_t block_size)
{
	le_put32(block + block_size - 4, crc32_compute(block, block_size - 4));
}
