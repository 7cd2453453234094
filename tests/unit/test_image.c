/* Flash image core: CRC-32, pack/read round trip in memory (skeleton and
 * bind data exact, frames within the stated quantisation), every block's
 * damage named and playback holding over bad blocks (images packed without
 * parity), parity rebuilding any one bad block bit-identical, the copies
 * (header, directory) wherever the storage ends, and the refusals: wrong
 * magic, older versions by name, header CRC, truncation, board limits,
 * another image's blocks. Raw ASF/AMC streamed from block storage. */
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
#include "test_parse.h"
#include "test_paths.h"

#define BS 512
#define CAP (1 << 20)

static skel s, s2;
static mesh m, m2;
static skin_weights w, w2;
static uint8_t img[CAP];
static size_t img_size;
static skp_image im;
static skp_clip_stream pl;
static skp_image_writer wr;
static skp_clip_range range;
static amc_frame frames[64];
static int frame_count;

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

/* Two clips: tiny.amc and a made-up longer one (40 frames of 5 dofs, in
 * several 512-byte blocks). */
static void load_inputs(void)
{
	frame_count = test_tiny_inputs(&s, frames, 64, &m, &w);
}

static skp_status write_clip(const char *name, const amc_frame *f, int n, skp_error *err)
{
	skp_clip_range_init(&range, &s);
	for (int i = 0; i < n; i++)
		if (skp_clip_range_add(&range, &f[i], err) != SKP_OK)
			return err->code;
	skp_status rc = skp_image_clip_begin(&wr, name, 120.0f, &range, err);
	for (int i = 0; i < n && rc == SKP_OK; i++)
		rc = skp_image_clip_frame(&wr, &f[i], err);
	return rc;
}

static amc_frame synth[200];

static void make_synth(int n)
{
	for (int i = 0; i < n; i++) {
		memset(&synth[i], 0, sizeof synth[i]);
		synth[i].number = 10 + i;
		for (int d = 0; d < s.dof_count; d++)
			synth[i].value[d] = (float)(sin(0.1 * i + d) * (d < 3 ? 40.0 : 3.0));
	}
}

/* A made-up id per pack (pack draws it at random): each call another. */
static void next_id(uint8_t id[SKP_IMAGE_ID_BYTES])
{
	static uint64_t n = 0x9e3779b97f4a7c15ull;
	for (int i = 0; i < SKP_IMAGE_ID_BYTES; i++) {
		n = n * 6364136223846793005ull + 1442695040888963407ull;
		id[i] = (uint8_t)(n >> 56);
	}
}

/* parity: data blocks per group, 0 the default, -1 none */
static void pack_with(uint64_t sequence, const float *bind_values, int parity)
{
	static skp_mem_blockdev mb;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	skp_error err;
	skp_blockdev dev = skp_mem_blockdev_init(&mb, img, CAP, BS);
	memset(img, 0, CAP);
	next_id(id);
	assert_int_equal(skp_image_write_begin(&wr, &dev, sequence, id, &s, &err), SKP_OK);
	wr.parity_group = parity;
	assert_int_equal(skp_image_write_bind(&wr, &m, &w, bind_values, 7, &err), SKP_OK);
	assert_int_equal(write_clip("tiny", frames, frame_count, &err), SKP_OK);
	make_synth(200);
	assert_int_equal(write_clip("synth", synth, 200, &err), SKP_OK);
	assert_int_equal(skp_image_write_end(&wr, &err), SKP_OK);
	img_size = mb.size;
	assert_int_equal(img_size, (size_t)wr.hdr.block_count * BS);
}

/* Without parity: every damaged block is seen as it is. */
static void pack(uint64_t sequence, const float *bind_values)
{
	pack_with(sequence, bind_values, -1);
}

static skp_mem_blockdev rb;
static skp_blockdev rdev;

static skp_status open_image(size_t size, skp_error *err)
{
	rdev = skp_mem_blockdev_ro(&rb, img, size, BS);
	return skp_image_open(&im, &rdev, err);
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

/* Loads everything and checks every block as the storage holds it;
 * returns the first bad block or -1 when all is well. */
static long first_bad(void)
{
	static uint8_t buf[BS];
	static float bind2[SKP_MAX_DOF];
	skp_error err;
	long number;
	if (open_image(img_size, &err) != SKP_OK)
		return err.block;
	if (im.header_from_copy)
		return 0;
	if (skp_image_load_skel(&im, &s2, &err) != SKP_OK ||
	    skp_image_load_bind(&im, &s2, &m2, &w2, bind2, &number, &err) != SKP_OK)
		return err.block;
	for (uint32_t b = 0; b < im.hdr.block_count; b++)
		if ((b < im.hdr.data_blocks || b >= im.hdr.dir_copy) && skp_image_check_block(&im, b, 0, 0, buf) != SKP_BLOCK_OK)
			return (long)b;
	return -1;
}

static void test_any_byte_names_its_block(void **state)
{
	(void)state;
	load_inputs();
	pack(99, NULL);
	assert_int_equal(first_bad(), -1);
	uint32_t blocks = (uint32_t)(img_size / BS);
	assert_true(blocks >= 6);
	uint64_t rnd = 12345;
	for (uint32_t b = 0; b < blocks; b++) {
		for (int k = 0; k < 3; k++) {
			rnd = rnd * 6364136223846793005ull + 1442695040888963407ull;
			size_t at = (size_t)b * BS + (size_t)((rnd >> 33) % BS);
			uint8_t bit = (uint8_t)(1u << ((rnd >> 20) % 8));
			img[at] ^= bit;
			long bad = first_bad();
			img[at] ^= bit;
			if (bad != (long)b)
				fail_msg("byte %zu flipped: block %ld named, expected %lu", at, bad, (unsigned long)b);
		}
	}
}

static void test_bad_frame_block_holds(void **state)
{
	(void)state;
	skp_error err;
	static amc_frame f;
	load_inputs();
	pack(5, NULL);
	uint32_t fpb = wr.dir[1].frames_per_block, bad = wr.dir[1].frames_first + 2;
	img[(size_t)bad * BS + 40] ^= 0x10;
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(skp_clip_stream_open(&pl, &im, 1, &err), SKP_OK);
	int lost = 0, good = 0, r;
	long last_good = -1;
	for (int i = 0; (r = skp_clip_stream_next(&pl, &f, &err)) != 0; i++) {
		int in_bad = (uint32_t)i / fpb == 2;
		if (in_bad) {
			assert_int_equal(r, SKP_CLIP_LOST);
			assert_int_equal(err.block, bad);
			assert_string_equal(err.msg, "CRC mismatch");
			assert_int_equal(f.number, last_good); /* untouched: the caller holds it */
			lost++;
		} else {
			assert_int_equal(r, 1);
			assert_int_equal(f.number, 10 + i);
			last_good = f.number;
			good++;
		}
	}
	assert_int_equal(lost, (int)fpb);
	assert_int_equal(good + lost, 200);
	/* the ring never holds more than its blocks, and seeking restarts it */
	skp_clip_stream_seek(&pl, 199);
	assert_int_equal(skp_clip_stream_next(&pl, &f, &err), 1);
	assert_int_equal(f.number, 209);
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

static void set_version_6(uint8_t *p) { le_put16(p + 8, 6); }
static void set_sequence(uint8_t *p) { le_put64(p + 20, 777); }
static void set_many_bones(uint8_t *p) { le_put32(p + 44, SKP_MAX_BONES + 1); }
static void set_magic(uint8_t *p) { p[0] = 'X'; }

static void expect_refusal(const char *needle, skp_status code)
{
	skp_error err;
	assert_int_not_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(err.code, code);
	if (!strstr(err.msg, needle))
		fail_msg("expected '%s' in '%s'", needle, err.msg);
}

static void test_refusals(void **state)
{
	(void)state;
	load_inputs();
	pack(5, NULL);
	patch_header(set_version_6, 1);
	expect_refusal("version 6, this build reads versions 4 to 5", SKP_ERR_CORRUPT);
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

/* A block of another image left in place (same position, good CRC) is
 * refused, even when both images have the same sequence (two packs in one
 * second): the ids differ. Rebuilt from parity, it reads as it was. */
static void test_foreign_block(void **state)
{
	(void)state;
	static uint8_t old[CAP], buf[BS], want[BS];
	skp_error err;
	load_inputs();
	pack_with(1, NULL, 0);
	memcpy(old, img, img_size);
	pack_with(1, NULL, 0);
	assert_memory_not_equal(old, img, SKP_IMAGE_ID_BYTES);
	uint32_t b = wr.dir[1].frames_first;
	memcpy(want, img + (size_t)b * BS, BS);
	memcpy(img + (size_t)b * BS, old + (size_t)b * BS, BS);
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(skp_image_check_block(&im, b, SKP_KIND_FRAMES, 1, buf), SKP_BLOCK_FOREIGN);
	assert_int_equal(skp_image_read_block(&im, b, SKP_KIND_FRAMES, 1, buf), SKP_BLOCK_OK);
	assert_memory_equal(buf, want, BS);
	assert_int_equal(im.rebuilt, 1);
	assert_int_equal(skp_image_read_block(&im, b + 1, SKP_KIND_FRAMES, 1, buf), SKP_BLOCK_OK);
	/* a good block asked for at another position */
	assert_int_equal(skp_image_check_block(&im, b + 1, SKP_KIND_FRAMES, 0, buf), SKP_BLOCK_MISPLACED);
	/* another image's block 0 (good CRC, its own header): block 1 says
	 * whose the image is, and the header comes from the copy */
	memcpy(img, old, BS);
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_true(im.header_from_copy);
	assert_memory_equal(im.hdr.id, img + BS, SKP_IMAGE_ID_BYTES);
}

/* FNV-1a over everything playback gets from the image: skeleton, body,
 * every frame of every clip. */
static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
	const uint8_t *b = p;
	for (size_t i = 0; i < n; i++)
		h = (h ^ b[i]) * 1099511628211ull;
	return h;
}

static uint64_t decoded_hash(void)
{
	static float bind2[SKP_MAX_DOF];
	static amc_frame f;
	skp_error err;
	long number;
	uint64_t h = 1469598103934665603ull;
	if (open_image(img_size, &err) != SKP_OK || skp_image_load_skel(&im, &s2, &err) != SKP_OK ||
	    skp_image_load_bind(&im, &s2, &m2, &w2, bind2, &number, &err) != SKP_OK)
		return 0;
	h = fnv(h, m2.pos, sizeof(vec3) * (size_t)m2.vert_count);
	h = fnv(h, w2.weight, sizeof w2.weight[0] * (size_t)m2.vert_count);
	h = fnv(h, bind2, sizeof(float) * (size_t)s2.dof_count);
	for (int c = 0; c < im.clip_count; c++) {
		if (skp_clip_stream_open(&pl, &im, c, &err) != SKP_OK)
			return 0;
		int r;
		while ((r = skp_clip_stream_next(&pl, &f, &err)) == 1)
			h = fnv(h, f.value, sizeof(float) * (size_t)s2.dof_count);
		if (r != 0)
			return 0;
	}
	return h;
}

static void test_parity_layout(void **state)
{
	(void)state;
	skp_error err;
	load_inputs();
	pack_with(3, NULL, 0);
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	const skp_image_header *h = &im.hdr;
	assert_int_equal(h->version, 5);
	assert_int_equal(h->parity_blocks, skp_parity_blocks(h->data_blocks, 0));
	assert_int_equal(h->block_count, h->copy_block + 1);
	assert_int_equal(h->dir_copy, h->data_blocks + h->parity_blocks);
	assert_int_equal(h->copy_block, h->dir_copy + h->sec[SKP_SEC_DIRECTORY].count);
	/* the default keeps parity and the header copy within 15% where it can */
	assert_true((h->parity_blocks + 1) * 100 <= h->data_blocks * 15 || h->parity_blocks == 1);
	print_message("%lu data blocks, %lu parity, 1 copy: %.1f%% more\n", (unsigned long)h->data_blocks,
		      (unsigned long)h->parity_blocks, 100.0 * (h->parity_blocks + 1) / h->data_blocks);
	assert_int_equal(skp_parity_blocks(217, 0), 28);  /* groups of 8 */
	assert_int_equal(skp_parity_blocks(20, 0), 2);    /* groups of 10: 3/20 = 15% */
	assert_int_equal(skp_parity_blocks(217, 4), 55);
	/* the block size is found from the end when block 0 is gone */
	skp_image_header copy;
	assert_true(skp_image_copy_at(img + img_size - SKP_IMAGE_TAIL, img_size - SKP_IMAGE_TAIL, &copy));
	assert_int_equal(copy.block_size, BS);
}

/* Any one data block flipped, or zeroed, is rebuilt bit-identical: what the
 * playback gets is the same as from the undamaged image. */
static void test_parity_rebuilds_any_one_block(void **state)
{
	(void)state;
	static uint8_t keep[BS];
	load_inputs();
	pack_with(4, NULL, 4);
	uint64_t ref = decoded_hash();
	assert_true(ref != 0);
	uint32_t data = wr.hdr.data_blocks;
	for (uint32_t b = 0; b < wr.hdr.block_count; b++) {
		uint8_t *blk = img + (size_t)b * BS;
		memcpy(keep, blk, BS);
		blk[(b * 37u) % BS] ^= 0x5a;
		if (decoded_hash() != ref)
			fail_msg("block %lu with a byte flipped: decoded differently", (unsigned long)b);
		if (b < data && im.rebuilt == 0 && b != 0)
			fail_msg("block %lu flipped: nothing rebuilt", (unsigned long)b);
		memset(blk, 0, BS);
		if (decoded_hash() != ref)
			fail_msg("block %lu zeroed: decoded differently", (unsigned long)b);
		memcpy(blk, keep, BS);
	}
	print_message("%lu blocks, each flipped and zeroed in turn: decoded identical\n",
		      (unsigned long)wr.hdr.block_count);
}

/* Reads through a counter, for the rebuild cache. */
static unsigned long reads_done;
static int counting_read(void *ctx, uint32_t block, void *buf)
{
	reads_done++;
	return rdev.read(ctx, block, buf);
}

/* A clip looping over a block rebuilt from parity: the first pass reads
 * the group to rebuild it, the next ones read the block itself only (the
 * clip is longer than the ring) and take the kept copy (the same frames),
 * not the group again; a clip within the ring is read once. */
static void test_rebuilt_block_kept_for_next_passes(void **state)
{
	(void)state;
	static amc_frame f, first[200];
	skp_error err;
	load_inputs();
	pack_with(11, NULL, 4);
	uint32_t bad = wr.dir[1].frames_first + 1;
	img[(size_t)bad * BS + 60] ^= 0x20;
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	skp_blockdev counted = rdev;
	counted.read = counting_read;
	im.dev = &counted;
	assert_int_equal(skp_clip_stream_open(&pl, &im, 1, &err), SKP_OK);
	unsigned long per_pass[3];
	for (int pass = 0; pass < 3; pass++) {
		reads_done = 0;
		skp_clip_stream_seek(&pl, 0);
		for (int i = 0; skp_clip_stream_next(&pl, &f, &err) == 1; i++) {
			if (pass == 0)
				first[i] = f;
			else
				assert_memory_equal(f.value, first[i].value, sizeof(float) * (size_t)s.dof_count);
		}
		per_pass[pass] = reads_done;
	}
	assert_int_equal(im.rebuilt, 1);
	print_message("reads a pass: %lu, %lu, %lu; kept copy used %lu times\n", per_pass[0], per_pass[1], per_pass[2],
		      pl.kept_uses);
	assert_int_equal(pl.kept_uses, 2);
	assert_int_equal(per_pass[1], per_pass[2]);
	assert_int_equal(per_pass[1], (unsigned long)wr.dir[1].frame_blocks);
	assert_true(per_pass[0] > per_pass[1]);
	/* a clip within the ring (tiny: one block) is read once, whatever
	 * its passes */
	assert_int_equal(skp_clip_stream_open(&pl, &im, 0, &err), SKP_OK);
	for (int pass = 0; pass < 3; pass++) {
		reads_done = 0;
		skp_clip_stream_seek(&pl, 0);
		while (skp_clip_stream_next(&pl, &f, &err) == 1)
			;
		per_pass[pass] = reads_done;
	}
	assert_int_equal(per_pass[0], 1);
	assert_int_equal(per_pass[1] + per_pass[2], 0);
	im.dev = &rdev;
}

/* Two bad blocks of one group are beyond XOR: the read says so. */
static void test_two_bad_blocks_in_a_group(void **state)
{
	(void)state;
	static uint8_t buf[BS];
	skp_error err;
	load_inputs();
	pack_with(6, NULL, 4);
	uint32_t p = wr.hdr.parity_blocks, b = wr.dir[1].frames_first;
	img[(size_t)b * BS + 30] ^= 1;
	img[(size_t)(b + p) * BS + 30] ^= 1;
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_int_equal(skp_image_read_block(&im, b, SKP_KIND_FRAMES, 1, buf), SKP_BLOCK_CRC);
	assert_int_equal(skp_image_rebuild(&im, b, SKP_KIND_FRAMES, 1, buf), SKP_BLOCK_CRC);
	/* one block of another group is still rebuilt */
	img[(size_t)(b + 1) * BS + 30] ^= 1;
	assert_int_equal(skp_image_read_block(&im, b + 1, SKP_KIND_FRAMES, 1, buf), SKP_BLOCK_OK);
	assert_int_equal(im.rebuilt, 1);
}

/* Block 0 gone: the header comes from the copy at the end. */
static void test_header_copy(void **state)
{
	(void)state;
	skp_error err;
	load_inputs();
	pack_with(7, NULL, 0);
	uint64_t ref = decoded_hash();
	memset(img, 0xff, BS);
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_true(im.header_from_copy);
	assert_int_equal(decoded_hash(), ref);
	/* both gone: refused, block 0 named */
	memset(img + img_size - BS, 0, BS);
	assert_int_equal(open_image(img_size, &err), SKP_ERR_CORRUPT);
	assert_int_equal(err.block, 0);
}

/* Storage longer than the image (a slot on a raw partition, a padded
 * download): the copy is where the header says, and searched for when
 * block 0 is lost; storage shorter by the copies or parity: a warning
 * (im.missing), the same playback. */
static void test_copy_wherever_the_storage_ends(void **state)
{
	(void)state;
	static const size_t extra[] = { 1, 7, BS, 3 * BS + 5 };
	load_inputs();
	pack_with(8, NULL, 0);
	uint64_t ref = decoded_hash();
	size_t full = img_size;
	for (size_t i = 0; i < sizeof extra / sizeof extra[0]; i++) {
		memset(img + full, 0xa5, extra[i]);
		img_size = full + extra[i];
		assert_int_equal(decoded_hash(), ref);
		assert_false(im.header_from_copy);
		memset(img, 0, BS);      /* block 0 lost too: the copy is searched for */
		assert_int_equal(decoded_hash(), ref);
		assert_true(im.header_from_copy);
		skp_block_seal(img, BS); /* still another image's block (zero id) */
		assert_int_equal(decoded_hash(), ref);
		pack_with(8, NULL, 0);
		ref = decoded_hash();
	}
	/* the header copy, then the directory copy and parity missing */
	for (uint32_t lost = 1; lost <= 1 + wr.hdr.sec[SKP_SEC_DIRECTORY].count + 1; lost++) {
		img_size = full - (size_t)lost * BS;
		assert_int_equal(decoded_hash(), ref);
		assert_int_equal(im.missing, lost);
	}
	/* into the data: refused (a partial directory block is short) */
	img_size = (size_t)wr.hdr.data_blocks * BS - 1;
	expect_refusal("clip directory section: short read", SKP_ERR_CORRUPT);
	img_size = (size_t)(wr.hdr.data_blocks - 1) * BS;
	expect_refusal("image truncated", SKP_ERR_CORRUPT);
}

/* The directory and block 0 come back from their copies when their parity
 * group cannot rebuild them (another block of the group lost too), and a
 * lost copy from what it copies. */
static void test_directory_and_header_copies(void **state)
{
	(void)state;
	static uint8_t buf[BS];
	skp_error err;
	load_inputs();
	pack_with(9, NULL, 4);
	uint64_t ref = decoded_hash();
	const skp_image_header *h = &wr.hdr;
	uint32_t dir = h->sec[SKP_SEC_DIRECTORY].first, p = h->parity_blocks;
	assert_true(dir >= p);
	memset(img + (size_t)dir * BS, 0, BS);
	memset(img + (size_t)(dir - p) * BS, 0, BS);   /* the same group */
	memset(img, 0, BS);
	memset(img + (size_t)p * BS, 0, BS);           /* group 0 */
	assert_int_equal(open_image(img_size, &err), SKP_OK);
	assert_true(im.header_from_copy);
	assert_int_equal(skp_image_read_block(&im, dir, SKP_KIND_DIRECTORY, 0, buf), SKP_BLOCK_OK);
	assert_string_equal(im.rebuilt_from, "the directory copy");
	assert_int_equal(skp_image_read_block(&im, 0, SKP_KIND_HEADER, 0, buf), SKP_BLOCK_OK);
	assert_string_equal(im.rebuilt_from, "the header");
	pack_with(9, NULL, 4);
	memset(img + (size_t)h->dir_copy * BS, 0, BS);
	memset(img + (size_t)h->copy_block * BS, 0, BS);
	assert_int_equal(decoded_hash(), ref);
	assert_int_equal(skp_image_read_block(&im, h->dir_copy, SKP_KIND_DIRECTORY, 1, buf), SKP_BLOCK_OK);
	assert_int_equal(skp_image_read_block(&im, h->copy_block, SKP_KIND_HEADER, 1, buf), SKP_BLOCK_OK);
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
	next_id(id);
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
	make_synth(3);
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
		cmocka_unit_test(test_any_byte_names_its_block),
		cmocka_unit_test(test_bad_frame_block_holds),
		cmocka_unit_test(test_refusals),
		cmocka_unit_test(test_foreign_block),
		cmocka_unit_test(test_parity_layout),
		cmocka_unit_test(test_parity_rebuilds_any_one_block),
		cmocka_unit_test(test_two_bad_blocks_in_a_group),
		cmocka_unit_test(test_rebuilt_block_kept_for_next_passes),
		cmocka_unit_test(test_header_copy),
		cmocka_unit_test(test_copy_wherever_the_storage_ends),
		cmocka_unit_test(test_directory_and_header_copies),
		cmocka_unit_test(test_older_versions_refused),
		cmocka_unit_test(test_writer_errors),
		cmocka_unit_test(test_blockdev_reader_streams_text),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
