/* Reading a block with its recovery: a block that fails its check is
 * rebuilt from its parity group (image_parity.c), else from its copy
 * (block 0 from the header, a directory block from the other directory),
 * and the image counts it. */
#include "image_recover.h"

#include "image_copies.h"
#include "image_digests.h"
#include "image_parity.h"
#include "image_read.h"

skp_block_state skp_image_content_check(skp_image *im, uint32_t block, int kind, unsigned item,
					const uint8_t *buf)
{
	skp_block_state st = skp_image_frame_check(im, block, kind, item, buf);
	return st != SKP_BLOCK_OK ? st : skp_image_leaf_check(im, block, buf);
}

skp_block_state skp_image_check_block(skp_image *im, uint32_t block, int kind, unsigned item,
				      uint8_t *buf)
{
	skp_block_state st = skp_image_read_framed(im, block, kind, item, buf);
	return st != SKP_BLOCK_OK ? st : skp_image_leaf_check(im, block, buf);
}

skp_block_state skp_image_read_block(skp_image *im, uint32_t block, int kind, unsigned item,
				     uint8_t *buf)
{
	skp_block_state st = skp_image_check_block(im, block, kind, item, buf);
	if (st == SKP_BLOCK_OK || skp_image_recover(im, block, kind, item, buf) != SKP_BLOCK_OK)
		return st;
	im->rebuilt++;
	if (im->on_rebuild)
		im->on_rebuild(im->on_rebuild_ctx, block);
	return SKP_BLOCK_OK;
}

/* Which directory block b is (0-based), or -1. */
static long dir_index(const skp_image_header *h, uint32_t b, uint32_t first)
{
	uint32_t count = h->sec[SKP_SEC_DIRECTORY].count;
	return b >= first && b - first < count ? (long)(b - first) : -1;
}

/* A directory block from the other copy: the primary (from parity at
 * most) for a copy block, the copy for a primary block. */
static skp_block_state dir_from_other(skp_image *im, uint32_t block, long i, int to_copy, uint8_t *buf)
{
	const skp_image_header *h = &im->hdr;
	uint32_t from = to_copy ? h->sec[SKP_SEC_DIRECTORY].first + (uint32_t)i : h->dir_copy + (uint32_t)i;
	skp_block_state st = skp_image_check_block(im, from, SKP_KIND_DIRECTORY, to_copy ? 0 : 1, buf);
	if (st != SKP_BLOCK_OK && to_copy)
		st = skp_image_rebuild(im, from, SKP_KIND_DIRECTORY, 0, buf);
	if (st == SKP_BLOCK_OK)
		skp_dir_block_reframe(buf, h, block, to_copy ? 1 : 0);
	return st;
}

skp_block_state skp_image_recover(skp_image *im, uint32_t block, int kind, unsigned item, uint8_t *buf)
{
	const skp_image_header *h = &im->hdr;
	skp_block_state st = block < h->data_blocks ? skp_image_rebuild(im, block, kind, item, buf) : SKP_BLOCK_CRC;
	long i;
	im->rebuilt_from = "parity";
	if (st == SKP_BLOCK_OK && (st = skp_image_leaf_check(im, block, buf)) == SKP_BLOCK_OK)
		return st;
	if (block == 0 || block == h->copy_block) {
		(block == 0 ? skp_header_block_frame : skp_header_copy_frame)(buf, h);
		im->rebuilt_from = "the header";
	} else if ((i = dir_index(h, block, h->sec[SKP_SEC_DIRECTORY].first)) >= 0) {
		if (dir_from_other(im, block, i, 0, buf) != SKP_BLOCK_OK)
			return st;
		im->rebuilt_from = "the directory copy";
	} else if ((i = dir_index(h, block, h->dir_copy)) >= 0) {
		if ((st = dir_from_other(im, block, i, 1, buf)) != SKP_BLOCK_OK)
			return st;
		im->rebuilt_from = "the directory";
	} else {
		return st;
	}
	return skp_image_content_check(im, block, kind, item, buf);
}
