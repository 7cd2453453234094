/* Whole images and mip chains through the ETC1 block search: see
 * tex_encode_etc1.h. */
#include "tex_encode_etc1.h"

#include <stdlib.h>

/* Block (bx, by) of the image, the last column and row repeated past the
 * edges: padding like the image's own border keeps the edge blocks'
 * colours from being pulled towards pixels nobody sees. */
static void gather_block(const uint8_t *rgb, int width, int height, int bx, int by, uint8_t out[48])
{
	for (int y = 0; y < 4; y++)
		for (int x = 0; x < 4; x++) {
			int sx = bx * 4 + x < width ? bx * 4 + x : width - 1;
			int sy = by * 4 + y < height ? by * 4 + y : height - 1;
			const uint8_t *p = rgb + ((size_t)sy * (size_t)width + (size_t)sx) * 3u;
			for (int c = 0; c < 3; c++)
				out[(y * 4 + x) * 3 + c] = p[c];
		}
}

/* The blocks of a size already checked, each row of them told to progress
 * (when there is one) as more blocks of all done of total. */
static void encode_blocks(const uint8_t *rgb, int width, int height, uint8_t *blocks,
			  const tex_encode_progress *progress, long *done, long total)
{
	int across = (width + 3) / 4, down = (height + 3) / 4;
	uint8_t pixels[48];
	for (int by = 0; by < down; by++) {
		for (int bx = 0; bx < across; bx++) {
			gather_block(rgb, width, height, bx, by, pixels);
			tex_encode_etc1_block(pixels, blocks + ((size_t)by * (size_t)across + (size_t)bx) * 8u);
		}
		if (progress && progress->fn) {
			*done += across;
			progress->fn(progress->ctx, *done, total);
		}
	}
}

skp_status tex_encode_etc1_image(const uint8_t *rgb, int width, int height,
				 uint8_t *blocks, size_t capacity, skp_error *err)
{
	skp_status st = tex_size_check(width, height, err);
	if (st != SKP_OK)
		return st;
	size_t need = tex_etc1_bytes(width, height);
	if (capacity < need)
		return skp_fail(err, SKP_ERR_RANGE, 0, "ETC1 %dx%d needs %lu bytes of blocks, the buffer holds %lu",
				width, height, (unsigned long)need, (unsigned long)capacity);
	encode_blocks(rgb, width, height, blocks, NULL, NULL, 0);
	return SKP_OK;
}

void tex_etc1_mipmaps_free(tex_etc1_mipmaps *m)
{
	free(m->blocks);
	m->blocks = NULL;
}

/* Encodes every level, each one downsampled from the one above into the
 * other of two scratch buffers. */
static skp_status encode_levels(const uint8_t *rgb, tex_etc1_mipmaps *out, uint8_t *scratch[2],
				const tex_encode_progress *progress, skp_error *err)
{
	const tex_mip_chain *chain = &out->chain;
	const uint8_t *level_rgb = rgb;
	long done = 0;
	for (int i = 0; i < chain->levels; i++) {
		const tex_level *l = &chain->level[i];
		encode_blocks(level_rgb, l->width, l->height, out->blocks + l->etc1_offset, progress, &done,
			      (long)(chain->etc1_bytes / TEX_ETC1_BLOCK_BYTES));
		if (i + 1 == chain->levels)
			break;
		skp_status st = tex_downsample_rgb8(level_rgb, l->width, l->height, scratch[i % 2],
						    chain->level[i + 1].rgb8_bytes, err);
		if (st != SKP_OK)
			return st;
		level_rgb = scratch[i % 2];
	}
	return SKP_OK;
}

skp_status tex_encode_etc1_mipmaps(const uint8_t *rgb, int width, int height, tex_etc1_mipmaps *out,
				   const tex_encode_progress *progress, skp_error *err)
{
	out->blocks = NULL;
	skp_status st = tex_mip_chain_make(width, height, &out->chain, err);
	if (st != SKP_OK)
		return st;
	/* level 1 is the largest a scratch buffer holds */
	size_t scratch_bytes = out->chain.levels > 1 ? out->chain.level[1].rgb8_bytes : 3u;
	uint8_t *scratch[2] = { malloc(scratch_bytes), malloc(scratch_bytes) };
	out->blocks = malloc(out->chain.etc1_bytes);
	if (!scratch[0] || !scratch[1] || !out->blocks)
		st = skp_fail(err, SKP_ERR_LIMIT, 0, "out of memory for a %dx%d texture's mip chain", width, height);
	else
		st = encode_levels(rgb, out, scratch, progress, err);
	free(scratch[0]);
	free(scratch[1]);
	if (st != SKP_OK)
		tex_etc1_mipmaps_free(out);
	return st;
}
