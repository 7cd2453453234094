/* ETC1 decoding: see tex_etc1.h. */
#include "tex_etc1.h"

#include "tex_mip.h"
#include "tex_rgb565.h"

const int16_t tex_etc1_modifier[8][4] = {
	{ 2, 8, -2, -8 },
	{ 5, 17, -5, -17 },
	{ 9, 29, -9, -29 },
	{ 13, 42, -13, -42 },
	{ 18, 60, -18, -60 },
	{ 24, 80, -24, -80 },
	{ 33, 106, -33, -106 },
	{ 47, 183, -47, -183 },
};

int tex_etc1_expand4(int v)
{
	return v << 4 | v;
}

int tex_etc1_expand5(int v)
{
	return v << 3 | v >> 2;
}

void tex_etc1_base_colours(const tex_etc1_fields *f, int rgb[2][3])
{
	for (int h = 0; h < 2; h++)
		for (int c = 0; c < 3; c++)
			rgb[h][c] = f->differential ? tex_etc1_expand5(f->base[h][c])
						    : tex_etc1_expand4(f->base[h][c]);
}

static uint8_t clamp255(int v)
{
	return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
}

void tex_etc1_decode_block(const uint8_t block[TEX_ETC1_BLOCK_BYTES], uint8_t rgb[4 * 4 * 3])
{
	tex_etc1_fields f;
	int base[2][3];
	tex_etc1_unpack(block, &f);
	tex_etc1_base_colours(&f, base);
	for (int y = 0; y < 4; y++)
		for (int x = 0; x < 4; x++) {
			int h = tex_etc1_in_second_half(f.flip, x, y);
			int m = tex_etc1_modifier[f.table[h]][f.index[y * 4 + x]];
			for (int c = 0; c < 3; c++)
				rgb[(y * 4 + x) * 3 + c] = clamp255(base[h][c] + m);
		}
}

static skp_status decode_sizes_check(size_t blocks_bytes, int width, int height,
				     size_t rgb565_bytes, skp_error *err)
{
	skp_status st = tex_size_check(width, height, err);
	if (st != SKP_OK)
		return st;
	size_t need_in = tex_etc1_bytes(width, height), need_out = tex_rgb565_bytes(width, height);
	if (blocks_bytes < need_in)
		return skp_fail(err, SKP_ERR_RANGE, 0, "ETC1 %dx%d needs %lu bytes of blocks, got %lu",
				width, height, (unsigned long)need_in, (unsigned long)blocks_bytes);
	if (rgb565_bytes < need_out)
		return skp_fail(err, SKP_ERR_RANGE, 0, "RGB565 %dx%d needs %lu bytes, the buffer holds %lu",
				width, height, (unsigned long)need_out, (unsigned long)rgb565_bytes);
	return SKP_OK;
}

/* The visible part of block (bx, by) into its place in the rows. */
static void put_block(const uint8_t rgb[4 * 4 * 3], int bx, int by, int width, int height, uint16_t *rows)
{
	for (int y = 0; y < 4 && by * 4 + y < height; y++)
		for (int x = 0; x < 4 && bx * 4 + x < width; x++) {
			const uint8_t *p = rgb + (y * 4 + x) * 3;
			rows[(size_t)(by * 4 + y) * (size_t)width + (size_t)(bx * 4 + x)] =
				tex_rgb565_from_rgb8(p[0], p[1], p[2]);
		}
}

skp_status tex_etc1_decode_rgb565(const uint8_t *blocks, size_t blocks_bytes, int width, int height,
				  uint16_t *rgb565, size_t rgb565_bytes, skp_error *err)
{
	skp_status st = decode_sizes_check(blocks_bytes, width, height, rgb565_bytes, err);
	if (st != SKP_OK)
		return st;
	int across = (width + 3) / 4, down = (height + 3) / 4;
	uint8_t rgb[4 * 4 * 3];
	for (int by = 0; by < down; by++)
		for (int bx = 0; bx < across; bx++) {
			size_t k = (size_t)by * (size_t)across + (size_t)bx;
			tex_etc1_decode_block(blocks + k * TEX_ETC1_BLOCK_BYTES, rgb);
			put_block(rgb, bx, by, width, height, rgb565);
		}
	return SKP_OK;
}
