/* Flash image damage and recovery, on images packed in memory: every
 * block's damage named and playback holding over bad blocks (images packed
 * without parity), another image's blocks refused, parity rebuilding any
 * one bad block bit-identical (and the rebuilt block kept for the next
 * passes of a loop), two bad blocks in a group beyond it, and the copies
 * (header, directory) wherever the storage ends. The format itself:
 * test_image.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "image_parity.h"
#include "image_stream.h"
#include "image_write.h"
#include "test_box.h"
#include "test_imgpack.h"

#define BS TEST_IMGPACK_BS
#define CAP TEST_IMGPACK_CAP

TEST_IMGPACK_STORAGE;

/* tiny.asf, tiny.amc's frames and the box body: what pack packs, with
 * 200 made-up frames (test_imgpack.h). */
static void load_inputs(void)
{
	frame_count = test_tiny_inputs(&s, frames, 64, &m, &w);
}

/* parity: data blocks per group, 0 the default, -1 none */
static void pack_with(uint64_t sequence, const float *bind_values, int parity)
{
	test_imgpack_pack(&pk, sequence, bind_values, parity);
}

/* Without parity: every damaged block is seen as it is. */
static void pack(uint64_t sequence, const float *bind_values)
{
	pack_with(sequence, bind_values, -1);
}

static skp_status open_image(size_t size, skp_error *err)
{
	return test_imgpack_open(&pk, size, err);
}

static void expect_refusal(const char *needle, skp_status code)
{
	test_imgpack_refused(&pk, needle, code);
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
	assert_int_equal(h->version, SKP_IMAGE_VERSION);
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

/* Block 0 lost: the header from its copy; the copy lost too: block 0
 * rebuilt from parity; one more block of group 0, or no parity: refused. */
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
	/* both gone (issue 45): block 0 rebuilt from parity group 0, whose
	 * layout the blocks' own frames give */
	memset(img + img_size - BS, 0, BS);
	assert_int_equal(decoded_hash(), ref);
	assert_true(im.header_from_parity);
	/* block 0 whole but for one bit of its block size, which its header's
	 * CRC refuses: the same (the damaged size was read blocks by) */
	pack_with(7, NULL, 0);
	img[SKP_IMAGE_BLOCK_HDR + 14] ^= 0x04;
	memset(img + img_size - BS, 0, BS);
	assert_int_equal(decoded_hash(), ref);
	assert_true(im.header_from_parity);
	/* ... and another block of group 0 too: refused, block 0 named */
	memset(img + img_size - BS, 0, BS);
	memset(img + (size_t)wr.hdr.parity_blocks * BS, 0, BS);
	assert_int_equal(open_image(img_size, &err), SKP_ERR_CORRUPT);
	assert_int_equal(err.block, 0);
	/* without parity: both gone is refused likewise */
	pack_with(7, NULL, -1);
	memset(img, 0xff, BS);
	memset(img + img_size - BS, 0, BS);
	assert_int_equal(open_image(img_size, &err), SKP_ERR_CORRUPT);
	assert_int_equal(err.block, 0);
}

/* Damage that looks worse than it is (issue 45): block 0 lost with another
 * block of its parity group (the header from its copy, block 0 made again
 * from it, the other rebuilt from parity); blocks 0 and 1 from another pack
 * of the same show (an in-place write cut after two blocks: the blocks after
 * them say whose the image is, the header comes from the copy, block 1 from
 * parity). Both play every frame as packed. */
static void test_damage_that_can_be_undone(void **state)
{
	(void)state;
	static uint8_t old[CAP];
	load_inputs();
	pack_with(3, NULL, 4);
	memcpy(old, img, img_size);
	pack_with(3, NULL, 4);
	uint64_t ref = decoded_hash();
	assert_true(ref != 0);
	uint32_t p = wr.hdr.parity_blocks;
	assert_true(p >= 2 && wr.hdr.data_blocks > p);
	memset(img, 0, BS);
	memset(img + (size_t)p * BS + 40, 0x5a, 8);  /* block p: parity group 0, as block 0 */
	assert_int_equal(decoded_hash(), ref);
	assert_true(im.header_from_copy);
	pack_with(3, NULL, 4);
	assert_int_equal(wr.hdr.parity_blocks, p);
	memcpy(img, old, 2 * BS);
	assert_int_equal(decoded_hash(), ref);
	assert_true(im.header_from_copy);
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
	/* into the data: refused (a partial last data block, a digest block, is short) */
	img_size = (size_t)wr.hdr.data_blocks * BS - 1;
	expect_refusal("block digests section: short read (image truncated)", SKP_ERR_CORRUPT);
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

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_any_byte_names_its_block),
		cmocka_unit_test(test_bad_frame_block_holds),
		cmocka_unit_test(test_foreign_block),
		cmocka_unit_test(test_parity_layout),
		cmocka_unit_test(test_parity_rebuilds_any_one_block),
		cmocka_unit_test(test_two_bad_blocks_in_a_group),
		cmocka_unit_test(test_rebuilt_block_kept_for_next_passes),
		cmocka_unit_test(test_header_copy),
		cmocka_unit_test(test_damage_that_can_be_undone),
		cmocka_unit_test(test_copy_wherever_the_storage_ends),
		cmocka_unit_test(test_directory_and_header_copies),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
