/* Characters keep their colours (issue 44): a rigged file's material base
 * colours, base colour textures and vertex colours become each vertex's
 * colour (sRGB), packed into the image and drawn by skinplay.
 *   - props_rig.gltf (tests/data/rigs/make_props_rig.py): the body's
 *     material, linear 0.5 0.1 0.1, is sRGB 188 89 89 at every vertex;
 *     the helmet's gold, whose texture is missing, is 255 203 89 with a
 *     warning naming texture and material; the lance's vertex colours are
 *     pure red at the floor and blue at the top; the crate, without a
 *     material, white.
 *   - CesiumMan.glb (its PNG texture embedded): the texture kept for the
 *     GPU, every vertex sampling it at UVs inside it, its seams' twins at
 *     one place with one normal; sampled at the vertices it is white, blue
 *     and green; packed (ETC1 with mips at 1024x1024) and played, the frame
 *     shows them, and so does the texture baked when the GPU cannot have
 *     it.
 *   - A file without materials keeps the skin colour (the MakeHuman-based
 *     glb in ../shared, when it is there). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "png_writer.h"
#include "rig_colour.h"
#include "rig_scene.h"
#include "rig_texture.h"
#include "tex_etc1.h"
#include "test_paths.h"
#include "test_run.h"

static mesh m;
static rig_scene scene;

static void import(const char *path)
{
	skp_error err;
	scene.mesh = &m;
	if (rig_import(path, NULL, &scene, &err) != SKP_OK)
		fail_msg("%s: %s", path, err.msg);
}

/* Every vertex where where() holds has colour rgb; returns how many. */
static int all_coloured(int (*where)(vec3), int r, int g, int b)
{
	int n = 0;
	for (int v = 0; v < m.vert_count; v++) {
		if (!where(m.pos[v]))
			continue;
		const uint8_t *c = m.colour[v];
		if (c[0] != r || c[1] != g || c[2] != b)
			fail_msg("vertex %d at %.2f %.2f %.2f: %d %d %d, wanted %d %d %d", v, (double)m.pos[v].x,
				 (double)m.pos[v].y, (double)m.pos[v].z, c[0], c[1], c[2], r, g, b);
		n++;
	}
	return n;
}

static int in_hips(vec3 p) { return p.y > 0.92f && p.y < 1.18f && fabsf(p.x) < 0.2f && fabsf(p.z) < 0.1f; }
static int in_helmet(vec3 p) { return p.y > 1.6f && fabsf(p.x) > 0.1f && fabsf(p.x) < 0.12f; }
static int lance_foot(vec3 p) { return fabsf(p.x - 0.78f) < 0.011f && p.y < 0.01f; }
static int lance_top(vec3 p) { return fabsf(p.x - 0.78f) < 0.011f && p.y > 1.99f; }
static int in_crate(vec3 p) { return p.x > 0.79f && p.z < -0.59f; }

static void test_materials_and_vertex_colours(void **state)
{
	(void)state;
	import("tests/data/rigs/props_rig.gltf");
	assert_int_equal(m.coloured, 1);
	assert_true(all_coloured(in_hips, 188, 89, 89) >= 8);
	assert_int_equal(all_coloured(in_helmet, 255, 203, 89), 8);
	assert_int_equal(all_coloured(lance_foot, 255, 0, 0), 4);
	assert_int_equal(all_coloured(lance_top, 0, 0, 255), 4);
	assert_int_equal(all_coloured(in_crate, 255, 255, 255), 8);
	assert_int_equal(scene.texture_problems, 1);
	assert_non_null(strstr(scene.texture_problem, "material 'Gold': texture 'missing_gold.png' is missing"));
}

/* Shares of the vertices (or pixels) that are blue, green and near white. */
typedef struct hues {
	double blue, green, white;
} hues;

static void count_hue(hues *h, const uint8_t *c, double share)
{
	h->blue += share * (c[2] > c[0] + 40 && c[2] > c[1]);
	h->green += share * (c[1] > c[0] + 30 && c[1] > c[2]);
	h->white += share * (c[0] > 170 && c[1] > 170 && c[2] > 170);
}

/* Twins a seam of the texture keeps apart sit at one place with one
 * normal; returns how many there are. */
static int check_seams(void)
{
	int twins = 0;
	for (int v = 0; v < m.vert_count; v++) {
		int lead = scene.seam_lead[v];
		assert_true(lead >= 0 && lead <= v);
		if (lead == v)
			continue;
		twins++;
		assert_memory_equal(&m.pos[v], &m.pos[lead], sizeof m.pos[v]);
		assert_true(m.uv[v][0] != m.uv[lead][0] || m.uv[v][1] != m.uv[lead][1]);
		assert_true(vec3_dot(m.normal[v], m.normal[lead]) > 0.9999f);
	}
	return twins;
}

static void test_texture_kept_for_the_gpu(void **state)
{
	(void)state;
	import("tests/data/rigs/CesiumMan.glb");
	assert_int_equal(m.coloured, 1);
	assert_int_equal(m.textured, 1);
	assert_int_equal(scene.textured, 1);
	assert_int_equal(scene.texture_problems, 0);
	assert_non_null(scene.texture_rgba);
	assert_int_equal(scene.texture_w, 1024);
	assert_int_equal(scene.texture_h, 1024);
	for (int v = 0; v < m.vert_count; v++) {
		assert_int_equal(m.sampled[v], 1);
		assert_true(m.uv[v][0] >= 0.0f && m.uv[v][0] <= 1.0f && m.uv[v][1] >= 0.0f && m.uv[v][1] <= 1.0f);
		/* the suit's material is white: its colour comes from the texture alone */
		assert_true(m.colour[v][0] == 255 && m.colour[v][1] == 255 && m.colour[v][2] == 255);
	}
	int twins = check_seams();
	print_message("CesiumMan: %d vertices, %d of them seam twins\n", m.vert_count, twins);
	assert_int_equal(twins, scene.seams);
	assert_true(twins > 100);
	/* the texture at the vertices, as the importer baked it before */
	rig_colour_bake(scene.texture_rgba, scene.texture_w, scene.texture_h, (const float (*)[2])m.uv, m.sampled,
			m.colour, m.vert_count);
	hues h = { 0, 0, 0 };
	for (int v = 0; v < m.vert_count; v++) {
		assert_int_equal(m.sampled[v], 0);
		count_hue(&h, m.colour[v], 1.0 / m.vert_count);
	}
	print_message("CesiumMan's vertices: %.1f%% blue, %.1f%% green, %.1f%% white\n", 100 * h.blue, 100 * h.green,
		      100 * h.white);
	assert_true(h.blue > 0.02 && h.green > 0.02 && h.white > 0.3);
}

/* The importer's power-of-two sides: the nearer by ratio, within the
 * board's. */
static void test_texture_sides(void **state)
{
	(void)state;
	assert_int_equal(rig_texture_side(1), 1);
	assert_int_equal(rig_texture_side(211), 256);
	assert_int_equal(rig_texture_side(600), 512);
	assert_int_equal(rig_texture_side(768), 1024 < SKP_MAX_TEXTURE_SIDE ? 1024 : SKP_MAX_TEXTURE_SIDE);
	assert_int_equal(rig_texture_side(1000), SKP_MAX_TEXTURE_SIDE < 1024 ? SKP_MAX_TEXTURE_SIDE : 1024);
	assert_int_equal(rig_texture_side(8192), SKP_MAX_TEXTURE_SIDE);
}

/* A 3x4 texture, red over blue, scaled to 4x4: rows flipped to GL's
 * order (the bottom first), each column the colour under it. (A block's
 * halves are 4x2 or 2x4: one colour each, as ETC1 keeps them.) */
static void test_texture_scaled_and_flipped(void **state)
{
	(void)state;
	static uint8_t rgba[4][3][4];
	for (int y = 0; y < 4; y++)
		for (int x = 0; x < 3; x++) {
			rgba[y][x][0] = y < 2 ? 200 : 0;
			rgba[y][x][2] = y < 2 ? 0 : 200;
			rgba[y][x][3] = 255;
		}
	static tex_image t;
	skp_error err;
	assert_int_equal(rig_texture_make(&rgba[0][0][0], 3, 4, &t, NULL, &err), SKP_OK);
	assert_int_equal(t.width, 4);
	assert_int_equal(t.height, 4);
	assert_int_equal(t.chain.levels, 3);
	uint8_t rgb[4 * 4 * 3];
	tex_etc1_decode_block(t.etc1, rgb);
	for (int y = 0; y < 4; y++)
		for (int x = 0; x < 4; x++) {
			const uint8_t *p = rgb + 3 * (4 * y + x);
			if (y < 2 ? !(p[2] > 180 && p[0] < 20) : !(p[0] > 180 && p[2] < 20))
				fail_msg("pixel %d,%d from the bottom: %d %d %d, wanted %s", x, y, p[0], p[1], p[2],
					 y < 2 ? "blue" : "red");
		}
}

/* The frame's pixels that are not the background's or the floor's: the
 * share of each hue among those whose colour is saturated or bright. */
static hues frame_hues(const char *png)
{
	static uint8_t px[480 * 540 * 4];
	int w, h;
	skp_error err;
	if (png_read_rgba(png, px, sizeof px, &w, &h, &err) != 0)
		fail_msg("%s: %s", png, err.msg);
	hues s = { 0, 0, 0 };
	for (long i = 0; i < (long)w * h; i++)
		count_hue(&s, px + 4 * i, 1.0 / ((double)w * h));
	return s;
}

static void test_played_in_colour(void **state)
{
	(void)state;
	if (test_emulator())
		skip();   /* no aarch64 Mesa under qemu-user (tests/cross_run.sh) */
	const char *img = test_scratch("cesium.skn"), *out = test_scratch("frames");
	assert_int_equal(test_run("%s pack -q assets/cmu/02.asf assets/cmu/02_01.amc --mesh tests/data/rigs/CesiumMan.glb "
				  "--weights mesh -o '%s' >/dev/null 2>&1", test_tool_path("skintool"), img), 0);
	const char *info = test_scratch("cesium_info.txt");
	assert_int_equal(test_run("%s info '%s' > '%s' 2>&1", test_tool_path("skintool"), img, info), 0);
	size_t n;
	char *said = test_read_file(info, &n);
	assert_non_null(said);
	if (!strstr(said, "texture: 1024x1024 ETC1, 11 mip levels, 699064 bytes; 2612 of 2612 vertices sample it"))
		fail_msg("skintool info said:\n%s", said);
	free(said);
	assert_int_equal(test_run("%s --image '%s' --platform surfaceless --size 480x540 --hud off --frames 1 --out '%s' "
				  ">/dev/null 2>&1", test_tool_path("skinplay"), img, out), 0);
	char png[600];
	snprintf(png, sizeof png, "%s/frame_000001.png", out);
	hues h = frame_hues(png);
	print_message("CesiumMan played: %.2f%% of the frame blue, %.2f%% green, %.2f%% white\n", 100 * h.blue,
		      100 * h.green, 100 * h.white);
	/* the body covers some 8% of the frame; the floor and sky are grey-blue,
	 * not saturated: green and white come from the suit alone */
	assert_true(h.green > 0.002 && h.white > 0.01);
}

/* Computed weights too: the seam's twins get one set, or the seam would
 * open as the body moves. */
static void test_seams_share_computed_weights(void **state)
{
	(void)state;
	const char *csv = test_scratch("cesium_weights.csv");
	assert_int_equal(test_run("%s bind -q assets/cmu/02.asf tests/data/rigs/CesiumMan.glb -o '%s' >/dev/null 2>&1",
				  test_tool_path("skintool"), csv), 0);
	import("tests/data/rigs/CesiumMan.glb");
	size_t n;
	char *text = test_read_file(csv, &n);
	assert_non_null(text);
	/* lines "vertex,bone,weight": each vertex's influences hashed in order */
	static uint64_t hash[SKP_MAX_VERTS];
	memset(hash, 0, sizeof hash);
	int lines = 0;
	for (char *at = strchr(text, '\n'); at && at[1]; at = strchr(at + 1, '\n')) {
		char *end;
		long v = strtol(at + 1, &end, 10);
		assert_true(*end == ',' && v >= 0 && v < m.vert_count);
		for (; *end && *end != '\n'; end++)
			hash[v] = hash[v] * 1099511628211u + (uint8_t)*end;
		lines++;
	}
	assert_true(lines >= m.vert_count);
	int twins = 0;
	for (int v = 0; v < m.vert_count; v++) {
		int lead = scene.seam_lead[v];
		if (lead == v)
			continue;
		twins++;
		if (hash[v] != hash[lead])
			fail_msg("vertex %d's weights are not its twin %d's", v, lead);
	}
	assert_true(twins > 100);
	free(text);
}

static void test_no_materials_keep_the_skin_colour(void **state)
{
	(void)state;
	const char *glb = test_data_path("mesh/orange_juice_male_base/male_base_mesh.glb");
	if (!glb)
		skip();
	import(glb);
	assert_int_equal(m.coloured, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_materials_and_vertex_colours),
		cmocka_unit_test(test_texture_kept_for_the_gpu),
		cmocka_unit_test(test_texture_sides),
		cmocka_unit_test(test_texture_scaled_and_flipped),
		cmocka_unit_test(test_seams_share_computed_weights),
		cmocka_unit_test(test_played_in_colour),
		cmocka_unit_test(test_no_materials_keep_the_skin_colour),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
