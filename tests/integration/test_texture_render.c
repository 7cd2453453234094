/* The device draws a body's texture (image format version 8): the box
 * body bound with a red and blue checkerboard texture, packed, played
 * headless. With --texture=auto (the ETC1 blocks to the GPU where it
 * samples them) and --texture=rgb565 (each level decoded first) both
 * colours of the board show on the body and the two pictures agree;
 * --texture=off draws it in its (white) colour alone; where the texture
 * is not sampled (every vertex's sampled 0) it is not seen. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "png_writer.h"
#include "tex_encode_etc1.h"
#include "test_box.h"
#include "test_imgpack.h"
#include "test_paths.h"
#include "test_run.h"

#define W 320
#define H 240

TEST_IMGPACK_STORAGE;
static tex_image tex;
static uint8_t px[W * H * 4], px2[W * H * 4];

/* A 64x64 board of 8-pixel squares, red and blue. */
static void checkerboard(void)
{
	static uint8_t rgb[64 * 64 * 3];
	skp_error err;
	for (int y = 0; y < 64; y++)
		for (int x = 0; x < 64; x++) {
			uint8_t *p = rgb + (y * 64 + x) * 3;
			int red = ((x / 8) + (y / 8)) % 2;
			p[0] = red ? 230 : 40, p[1] = red ? 40 : 70, p[2] = red ? 40 : 230;
		}
	tex_etc1_mipmaps mips;
	assert_int_equal(tex_encode_etc1_mipmaps(rgb, 64, 64, &mips, NULL, &err), SKP_OK);
	assert_int_equal(tex_image_begin(&tex, 64, 64, &err), SKP_OK);
	memcpy(tex.etc1, mips.blocks, mips.chain.etc1_bytes);
	tex_etc1_mipmaps_free(&mips);
}

/* The box body, white, its coordinates from its positions (the board
 * repeats over it), packed into <scratch>/name with the board. */
static const char *pack_box(const char *name, int sampled)
{
	frame_count = test_tiny_inputs(&s, frames, 64, &m, &w);
	m.coloured = m.textured = 1;
	memset(m.colour, 255, sizeof m.colour);
	for (int v = 0; v < m.vert_count; v++) {
		m.uv[v][0] = (m.pos[v].x + m.pos[v].z) * 0.15f;
		m.uv[v][1] = m.pos[v].y * 0.15f;
		m.sampled[v] = (uint8_t)sampled;
	}
	checkerboard();
	test_imgpack_texture(&tex);
	test_imgpack_pack(&pk, 1, NULL, 0);
	test_imgpack_texture(NULL);
	const char *path = test_scratch(name);
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(img, 1, img_size, f), img_size);
	assert_int_equal(fclose(f), 0);
	return path;
}

typedef struct hues {
	long red, blue, white;
} hues;

/* Plays the image one frame with --texture=mode into px (or into); its
 * stderr kept in <scratch>/mode.err. */
static hues play(const char *image, const char *mode, uint8_t *into)
{
	char dir[64], log[64];
	snprintf(dir, sizeof dir, "frames-%s", mode);
	snprintf(log, sizeof log, "%s.err", mode);
	const char *out = test_scratch(dir), *err_path = test_scratch(log);
	assert_int_equal(test_run("rm -rf '%s' && %s --image '%s' --platform surfaceless --size %dx%d --hud off "
				  "--algo dqbs --frames 1 --texture=%s -o '%s' >'%s' 2>&1",
				  out, test_tool_path("skinplay"), image, W, H, mode, out, err_path),
			 0);
	char png[128];
	snprintf(png, sizeof png, "%s/frame_000001.png", out);
	skp_error err;
	int pw, ph;
	assert_int_equal(png_read_rgba(png, into, W * H * 4, &pw, &ph, &err), SKP_OK);
	assert_int_equal(pw, W);
	hues c = { 0, 0, 0 };
	for (long i = 0; i < (long)W * H; i++) {
		const uint8_t *p = into + 4 * i;
		c.red += p[0] > p[2] + 60 && p[0] > p[1] + 60;
		c.blue += p[2] > p[0] + 60 && p[2] > p[1] + 40;
		c.white += p[0] > 120 && p[1] > 120 && p[2] > 120 && abs(p[0] - p[2]) < 40;
	}
	char *said = test_read_file(err_path, NULL), *line = said ? strstr(said, "texture: ") : NULL;
	if (line)
		line[strcspn(line, "\n")] = '\0';
	print_message("--texture=%s: %ld red, %ld blue, %ld white pixels%s%s\n", mode, c.red, c.blue, c.white,
		      line ? "; " : "", line ? line : "");
	free(said);
	if (getenv("SKP_KEEP_FRAMES"))
		test_run("cp '%s' '%s/texture-%s.png'", png, getenv("SKP_KEEP_FRAMES"), mode);
	return c;
}

static void test_board_seen(void **state)
{
	(void)state;
	if (test_emulator())
		skip();   /* llvmpipe emulated draws one frame in tens of minutes (tests/cross_run.sh) */
	const char *image = pack_box("board.skn", 1);
	hues a = play(image, "auto", px), b = play(image, "rgb565", px2);
	assert_true(a.red > 300 && a.blue > 300);
	assert_true(b.red > 300 && b.blue > 300);
	static const char *const said[] = { "texture: 64x64, 7 levels", NULL };
	test_assert_contains_all(test_scratch("auto.err"), said);
	static const char *const decoded[] = { "RGB565", "decoded at start-up", NULL };
	test_assert_contains_all(test_scratch("rgb565.err"), decoded);
	/* the GPU's ETC1 (or the same decode) and ours: the same picture,
	 * but for RGB565's rounding */
	long differ = 0;
	for (long i = 0; i < (long)W * H * 4; i++)
		differ += abs(px[i] - px2[i]) > 24;
	print_message("auto and rgb565: %ld channel values differ by more than 24\n", differ);
	assert_true(differ < (long)W * H / 100);
	hues off = play(image, "off", px);
	assert_true(off.red < a.red / 20 && off.blue < a.blue / 20);
	assert_true(off.white > a.red);
}

static void test_unsampled_not_seen(void **state)
{
	(void)state;
	if (test_emulator())
		skip();
	hues c = play(pack_box("plain.skn", 0), "auto", px);
	assert_true(c.red < 30 && c.blue < 30);
	assert_true(c.white > 300);
}

/* the storage's other images, for the tests that open them */
static void unused_storage(void)
{
	(void)s2, (void)m2, (void)w2, (void)pl;
}

int main(void)
{
	unused_storage();
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_board_seen),
		cmocka_unit_test(test_unsampled_not_seen),
	};
	return cmocka_run_group_tests_name("texture_render", tests, test_scratch_setup, test_scratch_teardown);
}
