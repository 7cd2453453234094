/* Flash image format: CRC-32 and SHA-256 against known vectors, the
 * pack/read round trip in memory (skeleton and bind data exact, frames
 * within the stated quantisation), the refusals (wrong magic, older
 * versions by name, header CRC, truncation, board limits), the writer's
 * errors, and raw ASF/AMC streamed from block storage. Damage, parity and
 * the copies: test_image_recovery.c. */
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
#include "image_parity.h"
#include "image_stream.h"
#include "image_write.h"
#include "sha256.h"
#include "test_box.h"
#include "test_imgpack.h"
#include "test_parse.h"
#include "test_paths.h"

#define BS TEST_IMGPACK_BS
#define CAP TEST_IMGPACK_CAP

TEST_IMGPACK_STORAGE;

static void test_crc32_vectors(void **state)
{
	(void)state;
	assert_int_equal(crc32_compute("123456789", 9), 0xCBF43926u);
	assert_int_equal(crc32_compute("", 0), 0);
	assert_int_equal(crc32_update(crc32_update(0, "1234", 4), "56789", 5), 0xCBF43926u);
	assert_int_equal(crc32_compute("The quick brown fox jumps over the lazy dog", 43), 0x414FA339u);
}

/* FIPS 180-4's examples, and a message fed in uneven pieces across the
 * 64-byte blocks and the padding's boundary (55/56 bytes). */
static void assert_sha256(const char *msg, size_t piece, const char *hex)
{
	sha256_ctx c;
	uint8_t out[SHA256_BYTES];
	char got[2 * SHA256_BYTES + 1];
	size_t n = strlen(msg);
	sha256_init(&c);
	for (size_t at = 0; at < n; at += piece)
		sha256_update(&c, msg + at, n - at < piece ? n - at : piece);
	sha256_final(&c, out);
	for (int i = 0; i < SHA256_BYTES; i++)
		snprintf(got + 2 * i, 3, "%02x", out[i]);
	assert_string_equal(got, hex);
}

static void test_sha256_vectors(void **state)
{
	(void)state;
	assert_sha256("", 1, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
	assert_sha256("abc", 1, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
	assert_sha256("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq", 7,
		      "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
	assert_sha256("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklmnopqklmnopqrlmnopqrsmnopqrstnopqrstu",
		      13, "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
	/* a million 'a' (FIPS 180-2's long vector) in pieces that make whole
	 * 64-byte blocks hashed where they lie and partial ones buffered */
	static char million[1000001];
	memset(million, 'a', 1000000);
	static const size_t pieces[] = { 64, 1000, 4096, 1000000 };
	for (size_t i = 0; i < sizeof pieces / sizeof pieces[0]; i++)
		assert_sha256(million, pieces[i], "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

/* Version 3 keeps positions to half a 16-bit step of the bounds on each
 * axis (the box is 3.6 x 0.6 x 0.6) and normals to 5e-5. */
static void assert_same_vertices(const mesh *a, const mesh *b)
{
	for (int v = 0; v < a->vert_count; v++) {
		assert_true(fabsf(a->pos[v].x - b->pos[v].x) <= 0.5f * 3.6f / 65535 + 1e-6f);
		assert_true(fabsf(a->pos[v].y - b->pos[v].y) <= 0.5f * 0.6f / 65535 + 1e-7f);
		assert_true(fabsf(a->pos[v].z - b->pos[v].z) <= 0.5f * 0.6f / 65535 + 1e-7f);
		assert_true(vec3_length(vec3_sub(a->normal[v], b->normal[v])) < 5e-5f);
	}
}

/* tiny.asf, tiny.amc's frames and the box body: what pack packs, with
 * 200 made-up frames (test_imgpack.h). */
static void load_inputs(void)
{
	frame_count = test_tiny_inputs(&s, frames, 64, &m, &w);
}

/* Without parity: every damaged block is seen as it is. */
static void pack(uint64_t sequence, const float *bind_values)
{
	test_imgpack_pack(&pk, sequence, bind_values, -1);
}

static skp_status open_image(size_t size, skp_error *err)
{
	return test_imgpack_open(&pk, size, err);
}

static void assert_same_skel(const skel *a, const skel *b)
{
	assert_string_equal(a->name, b->name);
	assert_string_equal(a->version, b->version);
	assert_int_equal(a->count, b->count);
	assert_int_equal(a->dof_count, b->dof_count);
	assert_memory_equal(a->eval_order, b->eval_order, (size_t)a->count);
	assert_true(a->angle_in_degrees == b->angle_in_degrees && a->length_scale == b->length_scale);
	assert_memory_equal(&a->root_position, &b->root_position, sizeof a->root_position);
	for (int i = 0; i < a->count; i++) {
		const skel_bone *x = &a->bone[i], *y = &b->bone[i];
		assert_string_equal(x->name, y->name);
		assert_true(x->id == y->id && x->parent == y->parent && x->length == y->length);
		assert_memory_equal(&x->direction, &y->direction, sizeof x->direction);
		assert_memory_equal(&x->axis_angle, &y->axis_angle, sizeof x->axis_angle);
		assert_memory_equal(&x->axis_rot, &y->axis_rot, sizeof x->axis_rot);
		assert_memory_equal(x->axis_order, y->axis_order, 3);
		assert_int_equal(x->channel_count, y->channel_count);
		assert_memory_equal(x->channel, y->channel, x->channel_count);
		assert_int_equal(x->has_limits, y->has_limits);
		assert_memory_equal(x->limit, y->limit, sizeof(float) * 2 * x->channel_count);
		assert_int_equal(x->dof_offset, y->dof_offset);
	}
}

/* Every frame of the clip decodes within step/2 of what was packed. */
static void check_clip(int clip, const amc_frame *f, int n)
{
	skp_error err;
	static amc_frame got;
	assert_int_equal(skp_clip_stream_open(&pl, &im, clip, &err), SKP_OK);
	for (int i = 0; i < n; i++) {
		assert_int_equal(skp_clip_stream_next(&pl, &got, &err), 1);
		assert_int_equal(got.number, f[i].number);
		for (int d = 0; d < s.dof_count; d++) {
			double tol = pl.qstep[d] * 0.5 * (1 + 1e-6) + 1e-6 * fabs(f[i].value[d]);
			assert_true(fabs((double)got.value[d] - f[i].value[d]) <= tol);
		}
	}
	assert_int_equal(skp_clip_stream_next(&pl, &got, &err), 0);
}

static void test_round_trip(void **state)
{
	(void)state;
	static float bind[SKP_MAX_DOF], bind2[SKP_MAX_DOF];
	skp_error err;
	long number;
	load_inputs();
	for (int d = 0; d < s.dof_count; d++)
		bind[d] = 0.25f * (float)d;
	pack(1234, bind);
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(im.hdr.sequence, 1234);
	assert_int_equal(im.clip_count, 2);
	assert_string_equal(im.clip[0].name, "tiny");
	assert_string_equal(im.clip[1].name, "synth");
	assert_int_equal(im.clip[1].first_number, 10);
	assert_int_equal(skp_image_load_skel(&im, &s2, &err), SKP_OK);
	assert_same_skel(&s, &s2);
	assert_int_equal(skp_image_load_bind(&im, &s2, &m2, &w2, bind2, &number, &err), SKP_OK);
	assert_int_equal(number, 7);
	assert_memory_equal(bind, bind2, sizeof(float) * (size_t)s.dof_count);
	assert_int_equal(m2.vert_count, 8);
	assert_int_equal(m2.tri_count, 12);
	assert_same_vertices(&m, &m2);
	assert_memory_equal(m.tri, m2.tri, sizeof(uint32_t) * 36);
	for (int v = 0; v < 8; v++) {
		assert_int_equal(w.count[v], w2.count[v]);
		for (int i = 0; i < w.count[v]; i++) {
			assert_int_equal(w.bone[v][i], w2.bone[v][i]);
			assert_true(fabsf(w.weight[v][i] - w2.weight[v][i]) <= 1.0f / 65535);
		}
	}
	check_clip(0, frames, frame_count);
	check_clip(1, synth, 200);
	/* the worst-case error stated per clip is the largest step / 2 */
	float worst = 0;
	for (int d = 0; d < 3; d++)
		worst = fmaxf(worst, pl.qstep[d] * 0.5f);
	assert_true(im.clip[1].max_trans_err == worst);
	assert_true(im.clip[1].max_rot_err > 0 && im.clip[1].max_rot_err < 1e-4f);
}

/* The body's colours (version 6) come back as written; a body without
 * any reads back without. */
static void test_colours_round_trip(void **state)
{
	(void)state;
	static float bind2[SKP_MAX_DOF];
	skp_error err;
	long number;
	load_inputs();
	m.coloured = 1;
	for (int v = 0; v < m.vert_count; v++)
		for (int c = 0; c < 3; c++)
			m.colour[v][c] = (uint8_t)(37 * v + 91 * c + 5);
	pack(1, NULL);
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(im.hdr.version, SKP_IMAGE_VERSION);
	assert_int_equal(skp_image_load_skel(&im, &s2, &err), SKP_OK);
	assert_int_equal(skp_image_load_bind(&im, &s2, &m2, &w2, bind2, &number, &err), SKP_OK);
	assert_int_equal(m2.coloured, 1);
	assert_memory_equal(m.colour, m2.colour, 3 * (size_t)m.vert_count);
	m.coloured = 0;
	pack(1, NULL);
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(skp_image_load_skel(&im, &s2, &err), SKP_OK);
	assert_int_equal(skp_image_load_bind(&im, &s2, &m2, &w2, bind2, &number, &err), SKP_OK);
	assert_int_equal(m2.coloured, 0);
}

static void test_rest_pose_bind(void **state)
{
	(void)state;
	static float bind2[SKP_MAX_DOF];
	skp_error err;
	long number;
	load_inputs();
	pack(1, NULL);
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(skp_image_load_skel(&im, &s2, &err), SKP_OK);
	assert_int_equal(skp_image_load_bind(&im, &s2, &m2, &w2, bind2, &number, &err), SKP_OK);
	assert_int_equal(number, -1);
	for (int d = 0; d < s.dof_count; d++)
		assert_true(bind2[d] == 0.0f);
}

/* Rewrites the header through fn, in block 0 and in the copy, and fixes the
 * CRCs as asked. */
static void patch_header(void (*fn)(uint8_t *p), int fix_header_crc)
{
	uint8_t *copy = img + img_size - BS;
	uint8_t *at[2] = { img + SKP_IMAGE_BLOCK_HDR, copy + BS - SKP_IMAGE_TAIL };
	for (int i = 0; i < 2; i++) {
		fn(at[i]);
		if (fix_header_crc)
			le_put32(at[i] + SKP_IMAGE_HEADER_SIZE - 4, crc32_compute(at[i], SKP_IMAGE_HEADER_SIZE - 4));
	}
	skp_block_seal(img, BS);
	skp_block_seal(copy, BS);
}

static void set_version_9(uint8_t *p) { le_put16(p + 8, 9); }
static void set_sequence(uint8_t *p) { le_put64(p + 20, 777); }
static void set_many_bones(uint8_t *p) { le_put32(p + 44, SKP_MAX_BONES + 1); }
static void set_magic(uint8_t *p) { p[0] = 'X'; }

static void expect_refusal(const char *needle, skp_status code)
{
	test_imgpack_refused(&pk, needle, code);
}

static void test_refusals(void **state)
{
	(void)state;
	load_inputs();
	pack(5, NULL);
	patch_header(set_version_9, 1);
	expect_refusal("version 9, this build reads versions 4 to 8", SKP_ERR_CORRUPT);
	pack(5, NULL);
	patch_header(set_sequence, 0);
	expect_refusal("header CRC mismatch", SKP_ERR_CORRUPT);
	pack(5, NULL);
	patch_header(set_many_bones, 1);
	expect_refusal("board limit SKP_MAX_BONES", SKP_ERR_LIMIT);
	pack(5, NULL);
	patch_header(set_magic, 1);
	expect_refusal("not a skinplay image", SKP_ERR_CORRUPT);
	pack(5, NULL);
	size_t full = img_size;
	img_size = full - 3 * BS;
	expect_refusal("truncated", SKP_ERR_CORRUPT);
	img_size = full - 100; /* a partial last block: the header copy reads short */
	skp_error err;
	static uint8_t buf[BS];
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(skp_image_check_block(&im, im.hdr.copy_block, SKP_KIND_HEADER, 1, buf), SKP_BLOCK_SHORT);
	img_size = 0;
	expect_refusal("short read", SKP_ERR_CORRUPT);
}

/* Images of versions 1 to 3 (no image id) are refused by name: the
 * version 1 and 2 writers' own files from tests/data, and a version 3
 * header. */
static void test_older_versions_refused(void **state)
{
	(void)state;
	static const char *const files[] = { "tests/data/v1_tiny.skn", "tests/data/v2_tiny.skn" };
	skp_error err;
	size_t n;
	for (int i = 0; i < 2; i++) {
		char *old = test_read_file(files[i], &n);
		assert_true(old && n <= CAP);
		memcpy(img, old, n);
		free(old);
		rdev = skp_mem_blockdev_ro(&rb, img, n, BS);
		assert_int_equal(skp_image_open(&im, &rdev, &err), SKP_ERR_CORRUPT);
		char want[64];
		snprintf(want, sizeof want, "image format version %d (skintool 0.16 or older", i + 1);
		if (!strstr(err.msg, want) || !strstr(err.msg, "pack the show again"))
			fail_msg("%s: %s", files[i], err.msg);
	}
	/* a version 3 header: after a 12-byte frame, 116 bytes, its CRC at 112 */
	load_inputs();
	pack(5, NULL);
	uint8_t *p = img + 12;
	memcpy(p, SKP_IMAGE_MAGIC, 8);
	le_put16(p + 8, 3);
	le_put16(p + 10, 116);
	le_put32(p + 112, crc32_compute(p, 112));
	skp_block_seal(img, BS);
	expect_refusal("image format version 3 (skintool 0.16 or older, without an image id)", SKP_ERR_CORRUPT);
}

static void test_writer_errors(void **state)
{
	(void)state;
	static skp_mem_blockdev mb;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	skp_error err;
	load_inputs();
	test_imgpack_next_id(id);
	skp_blockdev dev = skp_mem_blockdev_init(&mb, img, 2 * BS, BS);
	assert_int_equal(skp_image_write_begin(&wr, &dev, 1, id, &s, &err), SKP_OK);
	/* header and skeleton fill the storage: no room for the body */
	assert_int_equal(skp_image_write_bind(&wr, &m, &w, NULL, 0, &err), SKP_ERR_IO);
	assert_int_equal(err.block, 2);
	/* callers print "block 2: " before the message: it must not say it again */
	assert_string_equal(err.msg, "cannot write it");
	dev = skp_mem_blockdev_init(&mb, img, CAP, 100);
	assert_int_equal(skp_image_write_begin(&wr, &dev, 1, id, &s, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "block size 100"));
	/* frames must be numbered consecutively */
	skp_clip_range_init(&range, &s);
	test_imgpack_synth(&s, synth, 3);
	synth[2].number = 40;
	synth[2].line = 17;
	assert_int_equal(skp_clip_range_add(&range, &synth[0], &err), SKP_OK);
	assert_int_equal(skp_clip_range_add(&range, &synth[1], &err), SKP_OK);
	assert_int_equal(skp_clip_range_add(&range, &synth[2], &err), SKP_ERR_SYNTAX);
	assert_int_equal(err.line, 17);
}

/* Raw ASF and AMC text kept on block storage stream through the same
 * skp_reader interface as a file, one block at a time. */
static void test_blockdev_reader_streams_text(void **state)
{
	(void)state;
	static skp_mem_blockdev mb;
	static skp_blockdev_stream st;
	static uint8_t buf[BS];
	static text_lines tl;
	static amc_stream as;
	static amc_frame f;
	skp_error err;
	size_t na, nm;
	char *asf = test_read_file("tests/data/tiny.asf", &na);
	char *amc = test_read_file("tests/data/tiny.amc", &nm);
	assert_true(asf && amc && na + nm + 1000 < CAP);
	load_inputs();
	memset(img, 0xAA, CAP);
	memcpy(img + 700, asf, na);               /* not block aligned */
	memcpy(img + 700 + na + 33, amc, nm);
	skp_blockdev dev = skp_mem_blockdev_ro(&mb, img, 700 + na + 33 + nm, BS);
	text_lines_init(&tl, skp_blockdev_reader(&st, &dev, buf, 700, na));
	assert_int_equal(asf_parse(&s2, &tl, &err), SKP_OK);
	assert_same_skel(&s, &s2);
	text_lines_init(&tl, skp_blockdev_reader(&st, &dev, buf, 700 + na + 33, nm));
	amc_open(&as, &s2, &tl);
	int n = 0;
	while (amc_next(&as, &f, &err) > 0) {
		assert_memory_equal(f.value, frames[n].value, sizeof(float) * (size_t)s.dof_count);
		n++;
	}
	assert_int_equal(n, frame_count);
	free(asf);
	free(amc);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_crc32_vectors),
		cmocka_unit_test(test_sha256_vectors),
		cmocka_unit_test(test_round_trip),
		cmocka_unit_test(test_rest_pose_bind),
		cmocka_unit_test(test_colours_round_trip),
		cmocka_unit_test(test_refusals),
		cmocka_unit_test(test_older_versions_refused),
		cmocka_unit_test(test_writer_errors),
		cmocka_unit_test(test_blockdev_reader_streams_text),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
