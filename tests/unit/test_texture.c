/* The texture codec (app/texture, and app/encode's ETC1 encoder):
 * - blocks made by hand from the ETC1 specification decode to the pixels
 *   worked out by hand (individual and differential modes, a negative
 *   delta, the flip bit, the column-first index planes);
 * - encoded then decoded: a flat block within a few levels, gradients and
 *   real textures (Debian's assimp-testmodels) above a PSNR floor;
 * - mip chains' sizes, the box filter on a known 4x4;
 * - bad sizes and buffers too small: an error, nothing written past them. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "png_writer.h"
#include "test_paths.h"
#include "tex_encode_etc1.h"
#include "tex_etc1.h"
#include "tex_etc1_block.h"
#include "tex_mip.h"
#include "tex_rgb565.h"

/* Debian's assimp-testmodels */
#define MODELS "/usr/share/assimp/models/"

static void assert_pixel(const uint8_t rgb[48], int x, int y, int r, int g, int b)
{
	const uint8_t *p = rgb + (y * 4 + x) * 3;
	if (p[0] != r || p[1] != g || p[2] != b)
		fail_msg("pixel (%d, %d): %d %d %d, expected %d %d %d", x, y, p[0], p[1], p[2], r, g, b);
}

/* Individual mode, side by side (flip 0): bases 0xA 0x5 0x0 and 0x3 0xC
 * 0xF (170 85 0, 51 204 255), tables 2 (9, 29) and 5 (24, 80). Index
 * planes: msb 0x00F0 is column 1 (bits x * 4 + y), lsb 0x0F0F columns 0
 * and 2: columns 0..3 take +b, -a, +b, +a. */
static void test_individual_block_by_hand(void **state)
{
	(void)state;
	const uint8_t block[8] = { 0xA3, 0x5C, 0x0F, 0x54, 0x00, 0xF0, 0x0F, 0x0F };
	uint8_t rgb[48];
	tex_etc1_decode_block(block, rgb);
	for (int y = 0; y < 4; y++) {
		assert_pixel(rgb, 0, y, 170 + 29, 85 + 29, 0 + 29);
		assert_pixel(rgb, 1, y, 170 - 9, 85 - 9, 0);       /* -9 clamps to 0 */
		assert_pixel(rgb, 2, y, 51 + 80, 255, 255);         /* 284, 335 clamp */
		assert_pixel(rgb, 3, y, 51 + 24, 204 + 24, 255);
	}
}

/* Differential mode, stacked (flip 1): base 20 5 31 (165 41 255), deltas
 * -3 +3 -4 give 17 8 27 (140 66 222); tables 0 (2, 8) and 7 (47, 183).
 * msb 0x1111 is row 0, lsb 0x8888 row 3: rows 0..3 take -a, +a, +a, +b. */
static void test_differential_block_by_hand(void **state)
{
	(void)state;
	uint8_t block[8] = { 0xA5, 0x2B, 0xFC, 0x1F, 0x11, 0x11, 0x88, 0x88 };
	uint8_t rgb[48];
	tex_etc1_decode_block(block, rgb);
	for (int x = 0; x < 4; x++) {
		assert_pixel(rgb, x, 0, 165 - 2, 41 - 2, 255 - 2);
		assert_pixel(rgb, x, 1, 165 + 2, 41 + 2, 255);
		assert_pixel(rgb, x, 2, 140 + 47, 66 + 47, 255);
		assert_pixel(rgb, x, 3, 255, 66 + 183, 255);
	}
	/* the flip bit cleared: the halves are the left and right columns */
	block[3] = 0x1E;
	tex_etc1_decode_block(block, rgb);
	assert_pixel(rgb, 0, 2, 165 + 2, 41 + 2, 255);
	assert_pixel(rgb, 1, 3, 165 + 8, 41 + 8, 255);
	assert_pixel(rgb, 2, 0, 140 - 47, 66 - 47, 222 - 47);
	assert_pixel(rgb, 3, 3, 255, 66 + 183, 255);
}

/* Each of the 8 tables, as the specification lists them (+a +b; -a -b
 * are their negatives), in both halves: grey base 0x8 (136) in
 * individual mode, the four columns on indices 0..3 (msb plane 0xFF00:
 * columns 2 and 3; lsb plane 0xF0F0: columns 1 and 3). */
static void test_every_table(void **state)
{
	(void)state;
	static const int spec[8][2] = {
		{ 2, 8 }, { 5, 17 }, { 9, 29 }, { 13, 42 }, { 18, 60 }, { 24, 80 }, { 33, 106 }, { 47, 183 },
	};
	for (int t = 0; t < 8; t++)
		for (int flip = 0; flip < 2; flip++) {
			const uint8_t block[8] = { 0x88, 0x88, 0x88, (uint8_t)(t << 5 | t << 2 | flip),
						   0xFF, 0x00, 0xF0, 0xF0 };
			const int want[4] = { 136 + spec[t][0], 136 + spec[t][1], 136 - spec[t][0], 136 - spec[t][1] };
			uint8_t rgb[48];
			tex_etc1_decode_block(block, rgb);
			for (int y = 0; y < 4; y++)
				for (int x = 0; x < 4; x++) {
					int v = want[x] < 0 ? 0 : want[x] > 255 ? 255 : want[x];
					assert_pixel(rgb, x, y, v, v, v);
				}
		}
}

/* Packing is unpacking's inverse, over every mode and many fields; a
 * delta out of reach is refused. */
static void test_pack_unpack(void **state)
{
	(void)state;
	unsigned seed = 12345;
	for (int n = 0; n < 2000; n++) {
		tex_etc1_fields f, g;
		uint8_t block[8];
		memset(&f, 0, sizeof f);
		f.differential = (uint8_t)(n & 1);
		f.flip = (uint8_t)(n >> 1 & 1);
		for (int c = 0; c < 3; c++) {
			seed = seed * 1103515245u + 12345u;
			f.base[0][c] = (uint8_t)((seed >> 8) % (f.differential ? 32u : 16u));
			int other = f.differential ? f.base[0][c] + (int)((seed >> 20) % 8u) - 4
						   : (int)((seed >> 20) % 16u);
			f.base[1][c] = (uint8_t)(other < 0 ? 0 : other > 31 ? 31 : other);
		}
		f.table[0] = (uint8_t)(n % 8);
		f.table[1] = (uint8_t)(n / 8 % 8);
		for (int i = 0; i < 16; i++)
			f.index[i] = (uint8_t)((seed >> (i % 16)) & 3u);
		assert_int_equal(tex_etc1_pack(&f, block), 0);
		tex_etc1_unpack(block, &g);
		assert_memory_equal(&f, &g, sizeof f);
	}
	tex_etc1_fields f;
	uint8_t block[8] = { 1, 2, 3, 4, 5, 6, 7, 8 };
	memset(&f, 0, sizeof f);
	f.differential = 1;
	f.base[0][1] = 10;
	f.base[1][1] = 14; /* +4: out of -4..3 */
	assert_int_equal(tex_etc1_pack(&f, block), -1);
	assert_int_equal(block[0], 1);
}

static void test_rgb565(void **state)
{
	(void)state;
	uint8_t rgb[3];
	assert_int_equal(tex_rgb565_from_rgb8(0, 0, 0), 0);
	assert_int_equal(tex_rgb565_from_rgb8(255, 255, 255), 0xFFFF);
	/* 4 of 255 is 0.49 of a 5-bit step (rounds down), 5 is 0.61 (up) */
	assert_int_equal(tex_rgb565_from_rgb8(4, 0, 0), 0);
	assert_int_equal(tex_rgb565_from_rgb8(5, 0, 0), 1 << 11);
	assert_int_equal(tex_rgb565_from_rgb8(0, 3, 0), 1 << 5);
	tex_rgb565_to_rgb8(0xFFFF, rgb);
	assert_int_equal(rgb[0] & rgb[1] & rgb[2], 255);
	tex_rgb565_to_rgb8((uint16_t)(16 << 11 | 32 << 5 | 1), rgb);
	assert_int_equal(rgb[0], 132); /* 10000 -> 10000100 */
	assert_int_equal(rgb[1], 130); /* 100000 -> 10000010 */
	assert_int_equal(rgb[2], 8);
	/* every 8-bit value comes back within half a step */
	for (int v = 0; v < 256; v++) {
		tex_rgb565_to_rgb8(tex_rgb565_from_rgb8((uint8_t)v, (uint8_t)v, (uint8_t)v), rgb);
		assert_true(abs(rgb[0] - v) <= 4 && abs(rgb[1] - v) <= 2 && abs(rgb[2] - v) <= 4);
	}
}

/* A flat block of any colour decodes within a few levels. */
static void test_flat_blocks(void **state)
{
	(void)state;
	for (int v = 0; v < 256 * 8; v += 7) {
		uint8_t in[48], out[48], block[8];
		uint8_t colour[3] = { (uint8_t)(v % 256), (uint8_t)(v * 5 % 256), (uint8_t)(255 - v % 256) };
		for (int i = 0; i < 16; i++)
			memcpy(in + i * 3, colour, 3);
		tex_encode_etc1_block(in, block);
		tex_etc1_decode_block(block, out);
		for (int i = 0; i < 48; i++)
			if (abs(out[i] - in[i]) > 3)
				fail_msg("flat %d %d %d: channel %d decodes to %d", colour[0], colour[1], colour[2],
					 i % 3, out[i]);
	}
}

/* Peak signal to noise ratio in dB of the ETC1 decoding of blocks
 * against the RGB8 image it was encoded from. */
static double etc1_psnr(const uint8_t *rgb, int w, int h, const uint8_t *blocks)
{
	int across = (w + 3) / 4;
	double sum = 0;
	uint8_t px[48];
	for (int by = 0; by < (h + 3) / 4; by++)
		for (int bx = 0; bx < across; bx++) {
			tex_etc1_decode_block(blocks + ((size_t)by * (size_t)across + (size_t)bx) * 8u, px);
			for (int y = 0; y < 4 && by * 4 + y < h; y++)
				for (int x = 0; x < 4 && bx * 4 + x < w; x++)
					for (int c = 0; c < 3; c++) {
						double d = px[(y * 4 + x) * 3 + c] -
							   rgb[((size_t)(by * 4 + y) * (size_t)w + (size_t)(bx * 4 + x)) * 3u + (size_t)c];
						sum += d * d;
					}
		}
	double mse = sum / ((double)w * h * 3);
	return mse > 0 ? 10 * log10(255.0 * 255.0 / mse) : 99.0;
}

static double encode_psnr(const uint8_t *rgb, int w, int h)
{
	skp_error err;
	size_t bytes = tex_etc1_bytes(w, h);
	uint8_t *blocks = malloc(bytes);
	assert_non_null(blocks);
	assert_int_equal(tex_encode_etc1_image(rgb, w, h, blocks, bytes, &err), SKP_OK);
	double psnr = etc1_psnr(rgb, w, h, blocks);
	free(blocks);
	return psnr;
}

/* Smooth ramps, in one channel and across all three, and a diagonal. */
static void test_gradients(void **state)
{
	(void)state;
	enum { W = 64, H = 64 };
	static uint8_t rgb[W * H * 3];
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++) {
			uint8_t *p = rgb + (y * W + x) * 3;
			p[0] = (uint8_t)(x * 4);
			p[1] = (uint8_t)(y * 4);
			p[2] = (uint8_t)((x + y) * 2);
		}
	double psnr = encode_psnr(rgb, W, H);
	print_message("gradient 64x64: ETC1 %.2f dB\n", psnr);
	assert_true(psnr > 38.0);
}

/* RGBA from a PNG into RGB8; NULL (and the test skips) when absent. */
static uint8_t *load_rgb(const char *path, int *w, int *h)
{
	enum { MAX_BYTES = 2048 * 2048 * 4 };
	uint8_t *rgba = malloc(MAX_BYTES);
	skp_error err;
	assert_non_null(rgba);
	if (png_read_rgba(path, rgba, MAX_BYTES, w, h, &err) != 0) {
		free(rgba);
		return NULL;
	}
	size_t n = (size_t)*w * (size_t)*h;
	for (size_t i = 0; i < n; i++)
		memmove(rgba + i * 3, rgba + i * 4, 3);
	return rgba;
}

/* The side x side pixels at column x0 of a w x h RGB8 image, in place
 * (side 0: all of it). */
static void crop(uint8_t *rgb, int *w, int *h, int x0, int side)
{
	if (side <= 0 || x0 + side > *w || side > *h)
		return;
	for (int y = 0; y < side; y++)
		memmove(rgb + (size_t)y * (size_t)side * 3u, rgb + ((size_t)y * (size_t)*w + (size_t)x0) * 3u,
			(size_t)side * 3u);
	*w = *h = side;
}

typedef struct real_texture {
	const char *path;
	int crop_x;      /* a square from the top row at this column ... */
	int crop;        /* ... this wide, to keep the test short; 0: all of it */
	double floor_db; /* a little under what was measured */
} real_texture;

/* Real textures, PSNR printed and held to a floor a little under what the
 * encoder reached when the floor was set. */
static void test_real_textures(void **state)
{
	(void)state;
	/* the smallest first: the one taken under the sanitizers or an
	 * emulator (the milk truck's 2048x2048 PNG took 1.4 s to load under
	 * qemu, its crop 1.2 s to encode; test_mipmaps loads it as well) */
	static const real_texture textures[] = {
		{ MODELS "glTF2/BoxTextured-glTF/CesiumLogoFlat.png", 0, 0, 36.0 },
		{ MODELS "glTF/CesiumMilkTruck/CesiumMilkTruck.png", 512, 512, 39.5 },
		{ MODELS "3DS/test.png", 0, 0, 37.5 },
		{ MODELS "glTF2/ClearCoat-glTF/RibsNormal.png", 0, 0, 38.5 },
		{ MODELS "ReferenceImages/UVTransform/UVTransform_Normal.png", 0, 0, 43.5 },
		/* a photographed fabric, where blender-data is installed */
		{ "/usr/share/blender/scripts/addons/archimesh/images/fabric_diffuse.png", 0, 0, 40.0 },
	};
	const int slow = test_slow();
	int found = 0;
	/* under the sanitizers or an emulator (10x slower and more) the first
	 * texture found: the same code, and the native run measures them all */
	for (size_t i = 0; i < sizeof textures / sizeof textures[0] && !(slow && found); i++) {
		int w, h;
		uint8_t *rgb = load_rgb(textures[i].path, &w, &h);
		if (!rgb)
			continue;
		found++;
		crop(rgb, &w, &h, textures[i].crop_x, textures[i].crop);
		double psnr = encode_psnr(rgb, w, h);
		print_message("%s %dx%d: ETC1 %.2f dB\n", strrchr(textures[i].path, '/') + 1, w, h, psnr);
		assert_true(psnr > textures[i].floor_db);
		free(rgb);
	}
	if (!found)
		skip();
}

static void assert_level(const tex_mip_chain *c, int i, int w, int h, size_t etc1, size_t offset)
{
	assert_int_equal(c->level[i].width, w);
	assert_int_equal(c->level[i].height, h);
	assert_int_equal(c->level[i].etc1_bytes, etc1);
	assert_int_equal(c->level[i].etc1_offset, offset);
	assert_int_equal(c->level[i].rgb565_bytes, (size_t)w * (size_t)h * 2u);
	assert_int_equal(c->level[i].rgb8_bytes, (size_t)w * (size_t)h * 3u);
}

/* Sizes worked out by hand: levels halve, rounded down, to 1x1; ETC1
 * pads each level to whole 4x4 blocks of 8 bytes. */
static void test_mip_chain_sizes(void **state)
{
	(void)state;
	tex_mip_chain c;
	skp_error err;
	assert_int_equal(tex_mip_chain_make(1, 1, &c, &err), SKP_OK);
	assert_int_equal(c.levels, 1);
	assert_level(&c, 0, 1, 1, 8, 0);
	assert_int_equal(c.etc1_bytes, 8);
	assert_int_equal(c.rgb565_bytes, 2);

	assert_int_equal(tex_mip_chain_make(3, 5, &c, &err), SKP_OK);
	assert_int_equal(c.levels, 3);
	assert_level(&c, 0, 3, 5, 16, 0);
	assert_level(&c, 1, 1, 2, 8, 16);
	assert_level(&c, 2, 1, 1, 8, 24);
	assert_int_equal(c.etc1_bytes, 32);
	assert_int_equal(c.rgb565_bytes, 30 + 4 + 2);

	assert_int_equal(tex_mip_chain_make(256, 256, &c, &err), SKP_OK);
	assert_int_equal(c.levels, 9);
	assert_level(&c, 0, 256, 256, 32768, 0);
	assert_level(&c, 6, 4, 4, 8, 32768 + 8192 + 2048 + 512 + 128 + 32);
	assert_level(&c, 8, 1, 1, 8, 43696);
	assert_int_equal(c.etc1_bytes, 43704);
	assert_int_equal(c.rgb565_bytes, 2 * 87381);

	assert_int_equal(tex_mip_chain_make(1024, 512, &c, &err), SKP_OK);
	assert_int_equal(c.levels, 11);
	assert_level(&c, 0, 1024, 512, 262144, 0);
	assert_level(&c, 1, 512, 256, 65536, 262144);
	assert_level(&c, 8, 4, 2, 8, 349520);
	assert_level(&c, 9, 2, 1, 8, 349528);
	assert_level(&c, 10, 1, 1, 8, 349536);
	assert_int_equal(c.etc1_bytes, 349544);
}

/* A known 4x4 to 2x2 to 1x1, each mean rounded; an odd side's last
 * target takes three source pixels, a side of 1 stays 1. */
static void test_downsample_known(void **state)
{
	(void)state;
	static const uint8_t red[16] = { 0, 10, 20, 30, 40, 50, 60, 70, 1, 2, 3, 4, 5, 6, 7, 9 };
	uint8_t src[48], two[12], one[3];
	skp_error err;
	for (int i = 0; i < 16; i++) {
		src[i * 3] = red[i];
		src[i * 3 + 1] = (uint8_t)(255 - red[i]);
		src[i * 3 + 2] = 7;
	}
	assert_int_equal(tex_downsample_rgb8(src, 4, 4, two, sizeof two, &err), SKP_OK);
	/* red 100/4, 180/4, 14/4 = 3.5 -> 4, 23/4 = 5.75 -> 6 */
	static const uint8_t want_two[12] = { 25, 230, 7, 45, 210, 7, 4, 252, 7, 6, 249, 7 };
	assert_memory_equal(two, want_two, sizeof two);
	assert_int_equal(tex_downsample_rgb8(two, 2, 2, one, sizeof one, &err), SKP_OK);
	/* 80/4 = 20; 941/4 = 235.25 -> 235 */
	static const uint8_t want_one[3] = { 20, 235, 7 };
	assert_memory_equal(one, want_one, sizeof one);

	const uint8_t row3[9] = { 0, 0, 0, 3, 30, 200, 9, 90, 255 };
	assert_int_equal(tex_downsample_rgb8(row3, 3, 1, one, sizeof one, &err), SKP_OK);
	assert_int_equal(one[0], 4);   /* 12/3 */
	assert_int_equal(one[1], 40);  /* 120/3 */
	assert_int_equal(one[2], 152); /* 455/3 = 151.7 */
	assert_int_equal(tex_downsample_rgb8(row3, 1, 3, one, sizeof one, &err), SKP_OK);
	assert_int_equal(one[0], 4);
}

/* A 7x5 image (padded to 2x2 blocks) decodes to 7x5 RGB565 rows, each
 * pixel the block decoder's pixel rounded to 565; the buffers are exactly
 * their size, so a write past them is the sanitizer's to see. */
static void test_decode_rgb565_crops(void **state)
{
	(void)state;
	enum { W = 7, H = 5 };
	uint8_t rgb[W * H * 3];
	skp_error err;
	for (int i = 0; i < W * H * 3; i++)
		rgb[i] = (uint8_t)(i * 37 % 251);
	size_t bytes = tex_etc1_bytes(W, H);
	assert_int_equal(bytes, 2 * 2 * 8);
	uint8_t *blocks = malloc(bytes);
	uint16_t *out = malloc(tex_rgb565_bytes(W, H));
	assert_int_equal(tex_encode_etc1_image(rgb, W, H, blocks, bytes, &err), SKP_OK);
	assert_int_equal(tex_etc1_decode_rgb565(blocks, bytes, W, H, out, tex_rgb565_bytes(W, H), &err), SKP_OK);
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++) {
			uint8_t px[48];
			tex_etc1_decode_block(blocks + ((y / 4) * 2 + x / 4) * 8, px);
			const uint8_t *p = px + ((y % 4) * 4 + x % 4) * 3;
			assert_int_equal(out[y * W + x], tex_rgb565_from_rgb8(p[0], p[1], p[2]));
		}
	free(blocks);
	free(out);
}

/* Bad sizes and buffers one byte short: an error, and not a byte written. */
static void test_bad_input(void **state)
{
	(void)state;
	tex_mip_chain c;
	skp_error err;
	assert_int_equal(tex_mip_chain_make(0, 4, &c, &err), SKP_ERR_RANGE);
	assert_int_equal(tex_mip_chain_make(4, -3, &c, &err), SKP_ERR_RANGE);
	assert_int_equal(tex_mip_chain_make(TEX_MAX_SIDE + 1, 1, &c, &err), SKP_ERR_LIMIT);
	assert_int_equal(tex_mip_chain_make(1, TEX_MAX_SIDE + 1, &c, &err), SKP_ERR_LIMIT);
	assert_non_null(strstr(err.msg, "TEX_MAX_SIDE"));
	assert_int_equal(tex_mip_chain_make(TEX_MAX_SIDE, TEX_MAX_SIDE, &c, &err), SKP_OK);
	assert_int_equal(c.levels, TEX_MAX_LEVELS);
	assert_int_equal(tex_etc1_bytes(0, 4), 0);
	assert_int_equal(tex_rgb565_bytes(4, TEX_MAX_SIDE + 1), 0);

	uint8_t rgb[8 * 8 * 3], blocks[4 * 8 + 1], small[4 * 4 * 3 + 1];
	uint16_t out[8 * 8 + 1];
	memset(rgb, 100, sizeof rgb);
	memset(blocks, 0xCD, sizeof blocks);
	memset(small, 0xCD, sizeof small);
	memset(out, 0xCD, sizeof out);
	assert_int_equal(tex_encode_etc1_image(rgb, 8, 8, blocks, 4 * 8 - 1, &err), SKP_ERR_RANGE);
	assert_int_equal(tex_encode_etc1_image(rgb, 0, 8, blocks, sizeof blocks, &err), SKP_ERR_RANGE);
	assert_int_equal(blocks[0], 0xCD);
	assert_int_equal(tex_downsample_rgb8(rgb, 8, 8, small, 4 * 4 * 3 - 1, &err), SKP_ERR_RANGE);
	assert_int_equal(tex_downsample_rgb8(rgb, 8, -1, small, sizeof small, &err), SKP_ERR_RANGE);
	assert_int_equal(small[0], 0xCD);
	assert_int_equal(tex_etc1_decode_rgb565(blocks, 4 * 8 - 1, 8, 8, out, sizeof out, &err), SKP_ERR_RANGE);
	assert_int_equal(tex_etc1_decode_rgb565(blocks, sizeof blocks, 8, 8, out, 8 * 8 * 2 - 1, &err), SKP_ERR_RANGE);
	assert_int_equal(tex_etc1_decode_rgb565(blocks, sizeof blocks, TEX_MAX_SIDE + 4, 8, out, sizeof out, &err),
			 SKP_ERR_LIMIT);
	assert_int_equal(out[0], 0xCDCD);

	tex_etc1_mipmaps m;
	assert_int_equal(tex_encode_etc1_mipmaps(rgb, 0, 0, &m, NULL, &err), SKP_ERR_RANGE);
	assert_null(m.blocks);
}

/* The whole chain: each level is its own encoding of the box filter of
 * the level above, and decodes close to it; the time it takes for a
 * 256x256 texture is printed. */
static void test_mipmaps(void **state)
{
	(void)state;
	int w, h;
	uint8_t *rgb = load_rgb(MODELS "glTF/CesiumMilkTruck/CesiumMilkTruck.png", &w, &h);
	if (!rgb)
		skip();
	/* the 256x256 square around the first logo */
	for (int y = 0; y < 256; y++)
		memmove(rgb + (size_t)y * 256u * 3u, rgb + ((size_t)(y + 64) * (size_t)w + 512u) * 3u, 256u * 3u);
	w = h = 256;
	tex_etc1_mipmaps m;
	skp_error err;
	/* processor time, said not judged: the machine may be shared */
	clock_t t0 = clock();
	assert_int_equal(tex_encode_etc1_mipmaps(rgb, w, h, &m, NULL, &err), SKP_OK);
	print_message("256x256 with its 8 mip levels: %.1f ms of processor time to encode\n",
		      (double)(clock() - t0) * 1e3 / CLOCKS_PER_SEC);
	assert_int_equal(m.chain.levels, 9);
	uint8_t *level = malloc(tex_rgb8_bytes(w, h)), *next = malloc(tex_rgb8_bytes(w, h));
	uint8_t *blocks = malloc(m.chain.etc1_bytes);
	memcpy(level, rgb, tex_rgb8_bytes(w, h));
	for (int i = 0; i < m.chain.levels; i++) {
		const tex_level *l = &m.chain.level[i];
		assert_int_equal(tex_encode_etc1_image(level, l->width, l->height, blocks, l->etc1_bytes, &err), SKP_OK);
		assert_memory_equal(blocks, m.blocks + l->etc1_offset, l->etc1_bytes);
		double psnr = etc1_psnr(level, l->width, l->height, m.blocks + l->etc1_offset);
		print_message("level %d %dx%d: ETC1 %.2f dB\n", i, l->width, l->height, psnr);
		/* a small level of a logo is all edges: measured 40.2 36.9 33.9
		 * 31.0 down to 32x32, then 27.6 23.3 22.6 29.3 52.9 */
		assert_true(psnr > (l->width >= 32 ? 30.0 : 21.0));
		if (i + 1 < m.chain.levels) {
			assert_int_equal(tex_downsample_rgb8(level, l->width, l->height, next, tex_rgb8_bytes(w, h), &err), SKP_OK);
			memcpy(level, next, m.chain.level[i + 1].rgb8_bytes);
		}
	}
	free(blocks);
	free(level);
	free(next);
	free(rgb);
	tex_etc1_mipmaps_free(&m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_individual_block_by_hand),
		cmocka_unit_test(test_differential_block_by_hand),
		cmocka_unit_test(test_every_table),
		cmocka_unit_test(test_pack_unpack),
		cmocka_unit_test(test_rgb565),
		cmocka_unit_test(test_flat_blocks),
		cmocka_unit_test(test_gradients),
		cmocka_unit_test(test_real_textures),
		cmocka_unit_test(test_mip_chain_sizes),
		cmocka_unit_test(test_downsample_known),
		cmocka_unit_test(test_decode_rgb565_crops),
		cmocka_unit_test(test_bad_input),
		cmocka_unit_test(test_mipmaps),
	};
	return cmocka_run_group_tests_name("texture", tests, NULL, NULL);
}
