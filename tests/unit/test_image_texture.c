/* Version 8's texture in the bind section (app/image/image_format.h): the
 * texture coordinates, which vertices sample, and the ETC1 mip chain come
 * back as written; a reader that keeps no texture plays the body in its
 * colours; a damaged texture block is rebuilt from parity like any other;
 * a version 7 image still reads (no texture); a chain whose bytes do not
 * match its size is refused. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "tex_encode_etc1.h"
#include "tex_image.h"
#include "test_box.h"
#include "test_imgpack.h"

TEST_IMGPACK_STORAGE;
static tex_image tex, tex2;
static float bind2[SKP_MAX_DOF];

/* The box body with texture coordinates from its positions (some outside
 * 0..1: they repeat), every third vertex its colour alone, and a 64x32
 * gradient texture's ETC1 chain. */
static void textured_body(void)
{
	skp_error err;
	frame_count = test_tiny_inputs(&s, frames, 64, &m, &w);
	m.textured = 1;
	for (int v = 0; v < m.vert_count; v++) {
		m.uv[v][0] = m.pos[v].x * 0.37f - 0.5f;
		m.uv[v][1] = m.pos[v].y * 0.21f + 1.25f;
		m.sampled[v] = v % 3 != 0;
	}
	static uint8_t rgb[64 * 32 * 3];
	for (int y = 0; y < 32; y++)
		for (int x = 0; x < 64; x++) {
			uint8_t *p = rgb + (y * 64 + x) * 3;
			p[0] = (uint8_t)(x * 4), p[1] = (uint8_t)(y * 8), p[2] = (uint8_t)((x + y) * 2);
		}
	tex_etc1_mipmaps mips;
	assert_int_equal(tex_encode_etc1_mipmaps(rgb, 64, 32, &mips, NULL, &err), SKP_OK);
	assert_int_equal(tex_image_begin(&tex, 64, 32, &err), SKP_OK);
	assert_int_equal(tex.chain.etc1_bytes, mips.chain.etc1_bytes);
	memcpy(tex.etc1, mips.blocks, mips.chain.etc1_bytes);
	tex_etc1_mipmaps_free(&mips);
	test_imgpack_texture(&tex);
	test_imgpack_version(0);
}

static skp_status load(tex_image *keep, skp_error *err)
{
	long number;
	skp_status rc = test_imgpack_open(&pk, img_size, err);
	im.texture = keep;
	if (!rc) rc = skp_image_load_skel(&im, &s2, err);
	return rc ? rc : skp_image_load_bind(&im, &s2, &m2, &w2, bind2, &number, err);
}

static void assert_texture_back(void)
{
	assert_int_equal(m2.textured, 1);
	assert_int_equal(im.texture_skipped, 0);
	assert_int_equal(tex2.width, 64);
	assert_int_equal(tex2.height, 32);
	assert_int_equal(tex2.chain.levels, 7);
	assert_memory_equal(tex2.etc1, tex.etc1, tex.chain.etc1_bytes);
	assert_memory_equal(m2.sampled, m.sampled, (size_t)m.vert_count);
	/* 16-bit steps over the bounds: within half a step */
	for (int v = 0; v < m.vert_count; v++)
		for (int i = 0; i < 2; i++)
			assert_true(fabsf(m2.uv[v][i] - m.uv[v][i]) < 2e-4f);
}

static void test_round_trip(void **state)
{
	(void)state;
	skp_error err;
	textured_body();
	test_imgpack_pack(&pk, 1, NULL, -1);
	assert_int_equal(load(&tex2, &err), SKP_OK);
	assert_int_equal(im.hdr.version, 8);
	assert_texture_back();
}

/* No texture asked for: the body loads, in its colours. */
static void test_not_kept(void **state)
{
	(void)state;
	skp_error err;
	textured_body();
	test_imgpack_pack(&pk, 1, NULL, -1);
	assert_int_equal(load(NULL, &err), SKP_OK);
	assert_int_equal(m2.textured, 0);
	assert_int_equal(im.texture_skipped, 1);
}

/* A byte of the texture's last block flipped: rebuilt from parity. */
static void test_damaged_block_rebuilt(void **state)
{
	(void)state;
	skp_error err;
	textured_body();
	test_imgpack_pack(&pk, 1, NULL, 0);
	assert_int_equal(test_imgpack_open(&pk, img_size, &err), SKP_OK);
	const skp_image_section *bind = &im.hdr.sec[SKP_SEC_BIND];
	img[(size_t)(bind->first + bind->count - 1) * TEST_IMGPACK_BS + 100] ^= 0x5a;
	assert_int_equal(load(&tex2, &err), SKP_OK);
	assert_true(im.rebuilt >= 1);
	assert_texture_back();
}

/* Version 7 (before textures) still reads: no texture, the colours kept. */
static void test_version_7_reads(void **state)
{
	(void)state;
	skp_error err;
	textured_body();
	m.coloured = 1;
	memset(m.colour, 200, sizeof m.colour);
	test_imgpack_version(7);
	test_imgpack_pack(&pk, 1, NULL, -1);
	test_imgpack_version(0);
	m.coloured = 0;
	assert_int_equal(load(&tex2, &err), SKP_OK);
	assert_int_equal(im.hdr.version, 7);
	assert_int_equal(m2.textured, 0);
	assert_int_equal(m2.coloured, 1);
	assert_int_equal(m2.colour[0][0], 200);
}

/* A chain whose bytes are not its size's (a 64x32 texture said to be
 * 64x64): refused, naming what. */
static void test_wrong_size_refused(void **state)
{
	(void)state;
	skp_error err;
	textured_body();
	tex.height = 64;
	test_imgpack_pack(&pk, 1, NULL, -1);
	assert_int_equal(load(&tex2, &err), SKP_ERR_CORRUPT);
	if (!strstr(err.msg, "texture bytes differ"))
		fail_msg("got '%s'", err.msg);
	test_imgpack_texture(NULL);
}

int main(void)
{
	(void)pl; /* the storage's clip stream: these tests play no clip */
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_round_trip),
		cmocka_unit_test(test_not_kept),
		cmocka_unit_test(test_damaged_block_rebuilt),
		cmocka_unit_test(test_version_7_reads),
		cmocka_unit_test(test_wrong_size_refused),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
