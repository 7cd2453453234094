/* CRC-valid nonsense: images whose every block checks but whose content
 * cannot play (a body of 0 vertices, all-degenerate triangles, a flat
 * body, a bone 3e38 long, a root 1e30 away, by its position or by a
 * clip's translation, a rotation of 1e30 degrees, a non-unit axis quaternion, a frame count one past
 * the data, a rate of 1e-9 frames a second), written here with the core
 * writer as a forger would. The same acceptance judges them in skinplay
 * (refused, or the clip skipped; of two slots the older good one plays),
 * in skintool info (exit 2, saying why) and in skintool pack (which
 * refuses to write such an image and leaves the output as it was). Names
 * with control characters are printed escaped. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crc32.h"
#include "image_copies.h"
#include "image_digests.h"
#include "image_write.h"
#include "sha256.h"
#include "storage_file.h"
#include "test_box.h"
#include "test_paths.h"
#include "test_run.h"

#define BS 512

static skel s;
static mesh m;
static skin_weights w;
static amc_frame frames[8];
static int frame_count;
static float fps;

/* The good inputs: the tiny arm, the box, tiny.amc at 120 Hz. */
static void inputs(void)
{
	frame_count = test_tiny_inputs(&s, frames, 8, &m, &w);
	fps = 120.0f;
}

/* Writes the inputs as they are now into path, as pack would but without
 * its acceptance: every block framed and sealed. */
static const char *clip_name = "tiny";

static void write_image(const char *path, uint64_t sequence)
{
	static storage_file sf;
	static skp_image_writer wr;
	static skp_clip_range range;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	skp_error err;
	for (int i = 0; i < SKP_IMAGE_ID_BYTES; i++)
		id[i] = (uint8_t)(sequence * 31 + (uint64_t)i);
	assert_int_equal(storage_file_create(&sf, path, BS), 0);
	skp_status rc = skp_image_write_begin(&wr, &sf.bd, sequence, id, &s, &err);
	if (!rc) rc = skp_image_write_bind(&wr, &m, &w, NULL, 0, &err);
	skp_clip_range_init(&range, &s);
	for (int i = 0; i < frame_count && !rc; i++)
		rc = skp_clip_range_add(&range, &frames[i], &err);
	if (!rc) rc = skp_image_clip_begin(&wr, clip_name, fps, &range, &err);
	for (int i = 0; i < frame_count && !rc; i++)
		rc = skp_image_clip_frame(&wr, &frames[i], &err);
	if (!rc) rc = skp_image_write_end(&wr, &err);
	if (rc)
		fail_msg("%s: %s", path, err.msg);
	storage_file_close(&sf);
}

/* A forger who knows version 7 makes block b's digest good again too: its
 * leaf in the digest block, the root in both headers. */
static void redigest(uint8_t *d, skp_image_header *h, uint32_t b)
{
	uint32_t first = skp_digest_first(h), per = skp_digest_per_block(BS);
	uint8_t *db = d + (size_t)(first + b / per) * BS, leaf[SKP_IMAGE_LEAF_BYTES];
	skp_block_leaf(d + (size_t)b * BS, BS, db + SKP_IMAGE_BLOCK_HDR + (b % per) * SKP_IMAGE_LEAF_BYTES);
	skp_block_seal(db, BS);
	sha256_ctx c;
	sha256_init(&c);
	for (uint32_t k = first; k < h->data_blocks; k++) {
		skp_block_leaf(d + (size_t)k * BS, BS, leaf);
		sha256_update(&c, leaf, sizeof leaf);
	}
	sha256_final(&c, h->digest);
	skp_header_block_frame(d, h);
	skp_header_copy_frame(d + (size_t)h->copy_block * BS, h);
}

/* The directory entry's frame count, one more, in the directory and its
 * copy, both resealed, the digests made good: a forger's edit. */
static void one_frame_more(const char *path)
{
	size_t n;
	uint8_t *d = (uint8_t *)test_read_file(path, &n);
	assert_non_null(d);
	skp_image_header h;
	assert_true(skp_image_header_get(d + SKP_IMAGE_BLOCK_HDR, SKP_IMAGE_HEADER_SIZE, &h));
	const uint32_t blocks[2] = { h.sec[SKP_SEC_DIRECTORY].first, h.dir_copy };
	for (int i = 0; i < 2; i++) {
		uint8_t *b = d + (size_t)blocks[i] * BS, *count = b + SKP_IMAGE_BLOCK_HDR + 2 + 1 + 4 + 4;
		assert_memory_equal(b + SKP_IMAGE_BLOCK_HDR + 3, "tiny", 4);
		le_put32(count, le_get32(count) + 1);
		le_put32(b + BS - 4, crc32_compute(b, BS - 4));
	}
	redigest(d, &h, blocks[0]);
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(d, 1, n, f), n);
	fclose(f);
	free(d);
}

static void no_vertices(void) { m.vert_count = w.vert_count = 0; m.tri_count = 0; }
static void degenerate(void) { for (int t = 0; t < m.tri_count; t++) m.tri[t][2] = m.tri[t][1]; }
static void flat(void) { for (int v = 0; v < m.vert_count; v++) m.pos[v].z = 0.3f; }
static void long_bone(void) { s.bone[1].length = 3e38f; }
static void far_root(void) { s.root_position.x = 1e30f; }
static void far_travel(void) { frames[0].value[0] = 1e30f; }
static void far_angle(void) { frames[0].value[4] = 1e30f; }
static void non_unit_axis(void) { s.bone[2].axis_rot.w = 2.0f; }
static void slow(void) { fps = 1e-9f; }

typedef struct nonsense {
	const char *name;
	void (*spoil)(void);
	int clip;              /* 1: the clip is refused (the body plays) */
	const char *why;       /* in info's output */
} nonsense;

static const nonsense cases[] = {
	{ "no_vertices", no_vertices, 0, "body: 0 vertices and 0 triangles" },
	{ "degenerate", degenerate, 0, "12 of 12 triangles have no area" },
	{ "flat", flat, 0, "flat, not a body" },
	{ "long_bone", long_bone, 0, "skeleton: reaches 3.00000e38 units" },
	{ "far_root", far_root, 0, "skeleton: reaches 1.00000e30 units" },
	{ "far_travel", far_travel, 1, "a translation of up to 1.00000e30 units" },
	{ "far_angle", far_angle, 1, "a rotation of up to 1.00000e30" },
	{ "non_unit_axis", non_unit_axis, 0, "not a unit quaternion" },
	{ "one_frame_more", NULL, 1, "the clip's last block holds 2 frames, the directory says 3" },
	{ "slow", slow, 1, "a rate of 1.00000e-9 frames a second" },
};

static const char *image_of(const nonsense *c)
{
	static char path[512];
	snprintf(path, sizeof path, "%s.skn", test_scratch(c->name));
	inputs();
	if (c->spoil)
		c->spoil();
	write_image(path, 9);
	if (!c->spoil)
		one_frame_more(path);
	return path;
}

static void test_info_says_why(void **state)
{
	(void)state;
	const char *out = test_scratch("info.txt");
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		const char *img = image_of(&cases[i]);
		int st = test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), img, out);
		if (st != 2 || !test_file_contains(out, cases[i].why) ||
		    !test_file_contains(out, cases[i].clip ? "accept: clip 0 tiny cannot play" : "accept: refused")) {
			size_t n;
			char *text = test_read_file(out, &n);
			fail_msg("%s: info exited %d without '%s':\n%s", cases[i].name, st, cases[i].why, text ? text : "");
		}
	}
}

/* Whether skinplay plays case c: natively every case; under the
 * sanitizers or an emulator the first refused body and the first skipped
 * clip (skinplay's two ways out; info judges every case with the same
 * acceptance in test_info_says_why): two skinplay runs a case cost
 * about 1 s there. */
static int skinplay_meets(const nonsense *c)
{
	static int met[2];
	return !test_slow() || !met[c->clip]++;
}

/* One slot: refused (exit 1), or the body holds under a message (exit 2
 * headless); with an older good slot beside it, the good one plays. */
static void test_skinplay_refuses_and_falls_back(void **state)
{
	(void)state;
	const char *good = test_scratch("good.skn"), *log = test_scratch("play.txt");
	inputs();
	write_image(good, 1);
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		if (!skinplay_meets(&cases[i]))
			continue;
		const char *img = image_of(&cases[i]);
		int st = test_run("%s --image '%s' --platform surfaceless --size 64x36 --frames 3 >'%s' 2>&1",
				  test_tool_path("skinplay"), img, log);
		const char *said = cases[i].clip ? "image: clip tiny skipped" : "refused";
		if (st != (cases[i].clip ? 2 : 1) || !test_file_contains(log, said))
			fail_msg("%s alone: skinplay exited %d, expected %d and '%s'", cases[i].name, st,
				 cases[i].clip ? 2 : 1, said);
		st = test_run("%s --image '%s' --image '%s' --platform surfaceless --size 64x36 --frames 3 >'%s' 2>&1",
			      test_tool_path("skinplay"), img, good, log);
		if (st != 0 || !test_file_contains(log, "image: playing") || !test_file_contains(log, "good.skn (sequence 1"))
			fail_msg("%s with an older good slot: skinplay exited %d, not playing good.skn", cases[i].name, st);
	}
}

/* pack judges what it wrote with the same code: a flat mesh and a mesh
 * far from its skeleton are not written, and the output stays as it was. */
static void test_pack_refuses(void **state)
{
	(void)state;
	static const char *const meshes[2][2] = {
		{ "v -0.1 -0.3 0\nv 3.5 -0.3 0\nv -0.1 0.3 0\nv 3.5 0.3 0\nf 1 2 4 3\n", "flat, not a body" },
		{ "v 99 -1 -1\nv 103 -1 -1\nv 99 1 -1\nv 103 1 -1\nv 99 -1 1\nv 103 -1 1\nv 99 1 1\nv 103 1 1\n"
		  "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n",
		  "the skeleton does not fit this body" },
	};
	const char *obj = test_scratch("mesh.obj"), *out = test_scratch("out.skn"), *log = test_scratch("pack.txt");
	for (int i = 0; i < 2; i++) {
		test_write_text(obj, meshes[i][0]);
		test_write_text(out, "the user's old show");
		int st = test_run("%s pack tests/data/tiny.asf tests/data/tiny.amc --mesh '%s' --no-fit -o '%s' >'%s' 2>&1",
				  test_tool_path("skintool"), obj, out, log);
		assert_int_equal(st, 1);
		assert_true(test_file_contains(log, "not written: skinplay would refuse it"));
		assert_true(test_file_contains(log, meshes[i][1]));
		assert_true(test_file_contains(out, "the user's old show"));
	}
}

/* Names with control characters reach no terminal raw: a clip named so in
 * a forged image, and a clip file named so, packed. */
static void test_names_escaped(void **state)
{
	(void)state;
	const char *img = test_scratch("esc.skn"), *out = test_scratch("esc.txt");
	const char *amc = test_scratch("w\x1b[31m.amc");
	inputs();
	clip_name = "ti\x1b]0;pwned\x07ny";
	write_image(img, 3);
	clip_name = "tiny";
	assert_int_equal(test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), img, out), 0);
	assert_true(test_file_contains(out, "ti\\x1b]0;pwned\\x07ny: 2 frames"));
	assert_false(test_file_contains(out, "\x1b"));
	assert_int_equal(test_run("cp tests/data/tiny.amc '%s' && %s pack tests/data/tiny.asf '%s' -o '%s' >'%s' 2>&1", amc,
				  test_tool_path("skintool"), amc, img, out), 0);
	assert_true(test_file_contains(out, "clip w\\x1b[31m: 2 frames"));
	assert_false(test_file_contains(out, "\x1b"));
	assert_int_equal(test_run("%s --image '%s' --platform surfaceless --size 64x36 --frames 2 >'%s' 2>&1",
				  test_tool_path("skinplay"), img, out), 0);
	assert_false(test_file_contains(out, "\x1b"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_info_says_why),
		cmocka_unit_test(test_skinplay_refuses_and_falls_back),
		cmocka_unit_test(test_pack_refuses),
		cmocka_unit_test(test_names_escaped),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
