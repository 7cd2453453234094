/* Mip chain geometry and the box filter: see tex_mip.h. */
#include "tex_mip.h"

skp_status tex_size_check(int width, int height, skp_error *err)
{
	if (width < 1 || height < 1)
		return skp_fail(err, SKP_ERR_RANGE, 0, "texture size %dx%d: each side must be at least 1",
				width, height);
	if (width > TEX_MAX_SIDE || height > TEX_MAX_SIDE)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "texture size %dx%d: a side over %d (TEX_MAX_SIDE)",
				width, height, TEX_MAX_SIDE);
	return SKP_OK;
}

static int size_ok(int width, int height)
{
	return width >= 1 && height >= 1 && width <= TEX_MAX_SIDE && height <= TEX_MAX_SIDE;
}

size_t tex_etc1_bytes(int width, int height)
{
	if (!size_ok(width, height))
		return 0;
	return (size_t)((width + 3) / 4) * (size_t)((height + 3) / 4) * 8u;
}

size_t tex_rgb565_bytes(int width, int height)
{
	return size_ok(width, height) ? (size_t)width * (size_t)height * 2u : 0;
}

size_t tex_rgb8_bytes(int width, int height)
{
	return size_ok(width, height) ? (size_t)width * (size_t)height * 3u : 0;
}

int tex_mip_next_side(int side)
{
	return side > 1 ? side / 2 : 1;
}

static void level_fill(tex_level *l, int width, int height, size_t etc1_offset)
{
	l->width = width;
	l->height = height;
	l->etc1_bytes = tex_etc1_bytes(width, height);
	l->etc1_offset = etc1_offset;
	l->rgb565_bytes = tex_rgb565_bytes(width, height);
	l->rgb8_bytes = tex_rgb8_bytes(width, height);
}

skp_status tex_mip_chain_make(int width, int height, tex_mip_chain *chain, skp_error *err)
{
	skp_status st = tex_size_check(width, height, err);
	if (st != SKP_OK)
		return st;
	chain->levels = 0;
	chain->etc1_bytes = 0;
	chain->rgb565_bytes = 0;
	for (;;) {
		tex_level *l = &chain->level[chain->levels++];
		level_fill(l, width, height, chain->etc1_bytes);
		chain->etc1_bytes += l->etc1_bytes;
		chain->rgb565_bytes += l->rgb565_bytes;
		if (width == 1 && height == 1)
			return SKP_OK;
		width = tex_mip_next_side(width);
		height = tex_mip_next_side(height);
	}
}

/* The source span [*first, *end) under target pixel i of a side of n
 * source pixels: two pixels, one when n is 1, three for an odd side's last. */
static void source_span(int i, int n, int *first, int *end)
{
	int targets = tex_mip_next_side(n);
	*first = n > 1 ? 2 * i : 0;
	*end = i == targets - 1 ? n : *first + 2;
}

static void box_mean(const uint8_t *src, int width, int x0, int x1, int y0, int y1, uint8_t out[3])
{
	unsigned sum[3] = { 0, 0, 0 }, count = (unsigned)((x1 - x0) * (y1 - y0));
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++)
			for (int c = 0; c < 3; c++)
				sum[c] += src[((size_t)y * (size_t)width + (size_t)x) * 3u + (size_t)c];
	for (int c = 0; c < 3; c++)
		out[c] = (uint8_t)((sum[c] + count / 2u) / count);
}

skp_status tex_downsample_rgb8(const uint8_t *src, int width, int height,
			       uint8_t *dst, size_t dst_capacity, skp_error *err)
{
	skp_status st = tex_size_check(width, height, err);
	if (st != SKP_OK)
		return st;
	int tw = tex_mip_next_side(width), th = tex_mip_next_side(height);
	size_t need = tex_rgb8_bytes(tw, th);
	if (dst_capacity < need)
		return skp_fail(err, SKP_ERR_RANGE, 0, "mip level %dx%d needs %lu bytes, the buffer holds %lu",
				tw, th, (unsigned long)need, (unsigned long)dst_capacity);
	for (int ty = 0; ty < th; ty++) {
		int y0, y1;
		source_span(ty, height, &y0, &y1);
		for (int tx = 0; tx < tw; tx++) {
			int x0, x1;
			source_span(tx, width, &x0, &x1);
			box_mean(src, width, x0, x1, y0, y1, dst + ((size_t)ty * (size_t)tw + (size_t)tx) * 3u);
		}
	}
	return SKP_OK;
}
