/* The image header's bytes (image_format.h), both versions. */
#include <string.h>

#include "crc32.h"
#include "image_format.h"
#include "image_parity.h"

void skp_image_header_put(uint8_t *p, const skp_image_header *h)
{
	memset(p, 0, SKP_IMAGE_HEADER_SIZE);
	memcpy(p, SKP_IMAGE_MAGIC, 8);
	le_put16(p + 8, SKP_IMAGE_VERSION);
	le_put16(p + 10, SKP_IMAGE_HEADER_SIZE);
	le_put32(p + 12, h->block_size);
	le_put32(p + 16, h->block_count);
	le_put64(p + 20, h->sequence);
	le_put32(p + 28, h->bones);
	le_put32(p + 32, h->dofs);
	le_put32(p + 36, h->verts);
	le_put32(p + 40, h->tris);
	le_put32(p + 44, h->influences);
	le_put32(p + 48, h->clips);
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		le_put32(p + 52 + 12 * i, h->sec[i].first);
		le_put32(p + 56 + 12 * i, h->sec[i].count);
		le_put32(p + 60 + 12 * i, h->sec[i].bytes);
	}
	le_put32(p + 100, h->data_blocks);
	le_put32(p + 104, h->parity_blocks);
	le_put32(p + 108, h->copy_block);
	le_put32(p + 112, crc32_compute(p, SKP_IMAGE_HEADER_SIZE - 4));
}

int skp_image_header_get(const uint8_t *p, uint32_t n, skp_image_header *h)
{
	memset(h, 0, sizeof *h);
	if (n < SKP_IMAGE_HEADER_V1 || memcmp(p, SKP_IMAGE_MAGIC, 8))
		return 0;
	h->version = le_get16(p + 8);
	h->header_size = le_get16(p + 10);
	h->block_size = le_get32(p + 12);
	h->block_count = le_get32(p + 16);
	h->sequence = le_get64(p + 20);
	h->bones = le_get32(p + 28);
	h->dofs = le_get32(p + 32);
	h->verts = le_get32(p + 36);
	h->tris = le_get32(p + 40);
	h->influences = le_get32(p + 44);
	h->clips = le_get32(p + 48);
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		h->sec[i].first = le_get32(p + 52 + 12 * i);
		h->sec[i].count = le_get32(p + 56 + 12 * i);
		h->sec[i].bytes = le_get32(p + 60 + 12 * i);
	}
	uint32_t size = h->version == 1 ? SKP_IMAGE_HEADER_V1 : SKP_IMAGE_HEADER_SIZE;
	if (h->version < 1 || h->version > SKP_IMAGE_VERSION || h->header_size != size || n < size)
		return 0;
	if (h->version == 1) {
		h->data_blocks = h->block_count;
	} else {
		h->data_blocks = le_get32(p + 100);
		h->parity_blocks = le_get32(p + 104);
		h->copy_block = le_get32(p + 108);
	}
	h->crc = le_get32(p + size - 4);
	return crc32_compute(p, size - 4) == h->crc;
}

void skp_block_seal(uint8_t *block, uint32_t block_size)
{
	le_put32(block + block_size - 4, crc32_compute(block, block_size - 4));
}
