#include "image_copies.h"

#include <string.h>

#include "image_error.h"

void skp_header_block_frame(uint8_t *buf, const skp_image_header *h)
{
	memset(buf, 0, h->block_size);
	skp_block_frame(buf, h->id, 0, SKP_KIND_HEADER, 0);
	skp_image_header_put(buf + SKP_IMAGE_BLOCK_HDR, h);
	skp_block_seal(buf, h->block_size);
}

void skp_header_copy_frame(uint8_t *buf, const skp_image_header *h)
{
	uint32_t bs = h->block_size;
	memset(buf, 0, bs);
	skp_block_frame(buf, h->id, h->copy_block, SKP_KIND_HEADER, 1);
	skp_image_header_put(buf + bs - SKP_IMAGE_TAIL, h);
	skp_block_seal(buf, bs);
}

void skp_dir_block_reframe(uint8_t *buf, const skp_image_header *h, uint32_t index, unsigned item)
{
	skp_block_frame(buf, h->id, index, SKP_KIND_DIRECTORY, item);
	skp_block_seal(buf, h->block_size);
}

int skp_image_copy_at(const uint8_t *p, uint64_t at, skp_image_header *h)
{
	if (memcmp(p, SKP_IMAGE_MAGIC, 8) || !skp_image_header_get(p, SKP_IMAGE_HEADER_SIZE, h))
		return 0;
	uint32_t bs = h->block_size;
	return bs >= SKP_IMAGE_MIN_BLOCK && bs % 16 == 0 && h->block_count > 0 && h->copy_block == h->block_count - 1 &&
	       at + SKP_IMAGE_TAIL == ((uint64_t)h->copy_block + 1) * bs;
}

/* A copy's header ends 4 bytes before a block boundary, and blocks are
 * multiples of 16 bytes: it starts at an offset = -SKP_IMAGE_TAIL mod 16. */
#define COPY_PHASE ((16 - SKP_IMAGE_TAIL % 16) % 16)

/* Whether a block of some image could start at byte offset at (p: its
 * first SKP_IMAGE_BLOCK_HDR bytes): an index that puts it at a block size
 * the format allows, a kind, the zero byte. Evidence enough to search on
 * for the header copy. */
static int block_frame_at(const uint8_t *p, uint64_t at)
{
	uint32_t index = le_get32(p + 16);
	if (index == 0 || p[20] < SKP_KIND_HEADER || p[20] > SKP_KIND_DIGESTS || p[21] != 0 || at % index)
		return 0;
	uint64_t bs = at / index;
	return bs >= SKP_IMAGE_MIN_BLOCK && bs <= SKP_IMAGE_BLOCK_SIZE && bs % 16 == 0;
}

int skp_image_find_copy(skp_reader rd, uint8_t *win, uint32_t cap, skp_image_header *h, uint64_t *at)
{
	const uint32_t keep = SKP_IMAGE_HEADER_SIZE + 16;
	uint64_t base = 0, next = COPY_PHASE;   /* win[0]'s offset; the next candidate */
	uint32_t fill = 0;
	int seen = 0;                           /* a block frame met */
	long n;
	if (cap < 2 * keep)
		return 0;
	while ((n = rd.read(rd.ctx, win + fill, cap - fill)) > 0) {
		fill += (uint32_t)n;
		for (; next + SKP_IMAGE_HEADER_SIZE <= base + fill; next += 16) {
			if (skp_image_copy_at(win + (next - base), next, h)) {
				*at = next;
				return 1;
			}
			/* the block boundary candidate 16 - COPY_PHASE bytes on */
			uint64_t b = next + 16 - COPY_PHASE;
			if (!seen && b + SKP_IMAGE_BLOCK_HDR <= base + fill)
				seen = block_frame_at(win + (b - base), b);
		}
		if (!seen && base + fill >= SKP_IMAGE_FIND_BARREN)
			return 0;
		if (fill == cap) {
			memmove(win, win + cap - keep, keep);
			base += cap - keep;
			fill = keep;
		}
	}
	return 0;
}

int skp_image_copy_header(skp_image *im, skp_image_header *h)
{
	const skp_blockdev *dev = im->dev;
	uint32_t bs = dev->block_size, last = dev->block_count ? dev->block_count - 1 : 0;
	uint64_t at;
	/* where it usually is: the storage's last block */
	if (dev->block_count >= 2 && dev->read(dev->ctx, last, im->buf) == (int)bs &&
	    skp_image_copy_at(im->buf + bs - SKP_IMAGE_TAIL, (uint64_t)last * bs + bs - SKP_IMAGE_TAIL, h))
		return 1;
	skp_blockdev_stream st;
	skp_reader rd = skp_blockdev_reader(&st, dev, im->scratch, 0, (uint64_t)dev->block_count * bs);
	return skp_image_find_copy(rd, im->buf, SKP_IMAGE_BLOCK_SIZE, h, &at) && h->block_size == bs;
}

skp_status skp_image_write_copies(const skp_blockdev *dev, const skp_image_header *h, uint8_t *buf,
				  skp_error *err)
{
	const skp_image_section *dir = &h->sec[SKP_SEC_DIRECTORY];
	for (uint32_t i = 0; i < dir->count; i++) {
		if (dev->read(dev->ctx, dir->first + i, buf) != (int)h->block_size)
			return image_block_fail(err, SKP_ERR_IO, dir->first + i, "cannot read it back to copy the directory");
		skp_dir_block_reframe(buf, h, h->dir_copy + i, 1);
		if (dev->write(dev->ctx, h->dir_copy + i, buf) < 0)
			return image_block_fail(err, SKP_ERR_IO, h->dir_copy + i, "cannot write this directory copy block");
	}
	skp_header_copy_frame(buf, h);
	if (dev->write(dev->ctx, h->copy_block, buf) < 0)
		return image_block_fail(err, SKP_ERR_IO, h->copy_block, "cannot write the header copy");
	return SKP_OK;
}
