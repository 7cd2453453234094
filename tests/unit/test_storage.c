/* Storage backends: a file as block storage (pread/pwrite, partial last
 * block, sequential reader for raw text) and the fault-injecting wrapper,
 * one test per fault, each checked on raw reads and through the image
 * clip stream (bad blocks reported with their number, playback going on). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "clock.h"
#include "image_stream.h"
#include "image_write.h"
#include "storage_faulty.h"
#include "show_source.h"
#include "storage_file.h"
#include "test_parse.h"
#include "test_paths.h"

#define BS 512

static char path[] = "/tmp/skp_storage_XXXXXX";
static storage_file sf;
static storage_faulty fy;
static skel s;
static mesh m;
static skin_weights w;
static skp_image_writer wr;
static skp_clip_range range;
static skp_image im;
static skp_clip_stream pl;
static amc_frame synth[300];

static int write_file(int parity);

/* A one-triangle body on the tiny arm and a 300-frame clip: 24 frame
 * blocks of 512 bytes, written through storage_file. */
static int setup(void **state)
{
	(void)state;
	skp_error err;
	int fd = mkstemp(path);
	if (fd < 0 || test_parse_asf_file("tests/data/tiny.asf", &s, &err) != SKP_OK)
		return -1;
	close(fd);
	m.vert_count = w.vert_count = 3;
	m.tri_count = 1;
	for (int v = 0; v < 3; v++) {
		m.pos[v] = vec3_make((float)v, (float)(v == 1), 0);
		m.normal[v] = vec3_make(0, 0, 1);
		m.tri[0][v] = (uint32_t)v;
		w.count[v] = 1;
		w.bone[v][0] = (uint16_t)v;
		w.weight[v][0] = 1;
	}
	skp_clip_range_init(&range, &s);
	for (int i = 0; i < 300; i++) {
		synth[i].number = i + 1;
		for (int d = 0; d < s.dof_count; d++)
			synth[i].value[d] = (float)((i * 7 + d * 13) % 100) * 0.01f;
		if (skp_clip_range_add(&range, &synth[i], &err) != SKP_OK)
			return -1;
	}
	return write_file(-1);
}

/* The image file, with parity (group size, 0 the default) or without (-1):
 * the fault tests want to see each fault, the parity test wants it gone. */
static int write_file(int parity)
{
	static const uint8_t id[SKP_IMAGE_ID_BYTES] = "storage-test-id";
	skp_error err;
	if (storage_file_create(&sf, path, BS) < 0)
		return -1;
	skp_status rc = skp_image_write_begin(&wr, &sf.bd, 42, id, &s, &err);
	wr.parity_group = parity;
	if (!rc) rc = skp_image_write_bind(&wr, &m, &w, NULL, 0, &err);
	if (!rc) rc = skp_image_clip_begin(&wr, "synth", 120, &range, &err);
	for (int i = 0; i < 300 && !rc; i++)
		rc = skp_image_clip_frame(&wr, &synth[i], &err);
	if (!rc) rc = skp_image_write_end(&wr, &err);
	storage_file_close(&sf);
	return rc == SKP_OK ? 0 : -1;
}

static int teardown(void **state)
{
	(void)state;
	return unlink(path);
}

/* Opens the file under the faulty wrapper (no faults yet). */
static void open_faulty(void)
{
	assert_int_equal(show_storage_open(&sf, path), 0);
	assert_int_equal(sf.bd.block_size, BS);
	storage_faulty_init(&fy, &sf.bd);
}

/* Plays the clip; returns frames lost, recording the first bad block and
 * its reason. */
static int play_all(long *bad_block, char *why)
{
	skp_error err;
	static amc_frame f;
	int lost = 0, r, i = 0;
	*bad_block = -1;
	assert_int_equal(skp_image_open(&im, &fy.bd, &err), SKP_OK);
	assert_int_equal(skp_clip_stream_open(&pl, &im, 0, &err), SKP_OK);
	while ((r = skp_clip_stream_next(&pl, &f, &err)) != 0) {
		if (r == SKP_CLIP_LOST) {
			if (*bad_block < 0) {
				*bad_block = err.block;
				strcpy(why, err.msg);
			}
			lost++;
		} else {
			assert_int_equal(r, 1);
			assert_int_equal(f.number, i + 1);
		}
		i++;
	}
	assert_int_equal(i, 300);
	return lost;
}

static void test_file_blocks_and_reader(void **state)
{
	(void)state;
	static uint8_t a[BS], b[1024];
	open_faulty();
	assert_int_equal(sf.bd.block_count, wr.hdr.block_count);
	assert_int_equal(sf.bd.read(sf.bd.ctx, 3, a), BS);
	assert_int_equal(sf.bd.read(sf.bd.ctx, sf.bd.block_count, a), SKP_BD_ERANGE);
	/* the sequential reader sees the same bytes */
	skp_reader rd = storage_file_reader(&sf);
	long got = 0;
	while (got < 4 * BS) {
		long n = rd.read(rd.ctx, b, sizeof b);
		assert_true(n > 0);
		got += n;
	}
	assert_memory_equal(b + sizeof b - BS, a, BS);
	/* a block size that does not divide the file: the last block reads short */
	storage_file_set_block_size(&sf, 3 * BS);
	uint32_t last = sf.bd.block_count - 1;
	int n = sf.bd.read(sf.bd.ctx, last, b);
	assert_true(n > 0 && n <= 3 * BS);
	assert_int_equal((uint64_t)last * 3 * BS + (uint64_t)n, sf.size);
	storage_file_close(&sf);
}

static void test_no_fault_plays_everything(void **state)
{
	(void)state;
	long bad;
	char why[200];
	open_faulty();
	assert_int_equal(play_all(&bad, why), 0);
	assert_int_equal(bad, -1);
	/* the ring reads each frame block once */
	assert_int_equal(pl.reads, wr.dir[0].frame_blocks);
	storage_file_close(&sf);
}

static void test_fault_bit_flip(void **state)
{
	(void)state;
	static uint8_t a[BS], b[BS];
	long bad;
	char why[200];
	open_faulty();
	uint32_t target = wr.dir[0].frames_first + 5;
	assert_int_equal(sf.bd.read(sf.bd.ctx, target, a), BS);
	assert_int_equal(storage_faulty_flip(&fy, target, 8 * 100 + 3), 0);
	assert_int_equal(fy.bd.read(fy.bd.ctx, target, b), BS);
	int diff = 0;
	for (int i = 0; i < BS; i++)
		diff += __builtin_popcount(a[i] ^ b[i]);
	assert_int_equal(diff, 1);
	assert_int_equal(b[100] ^ a[100], 1 << 3);
	assert_int_equal(play_all(&bad, why), wr.dir[0].frames_per_block);
	assert_int_equal(bad, target);
	assert_string_equal(why, "CRC mismatch");
	storage_file_close(&sf);
}

static void test_fault_random_rate(void **state)
{
	(void)state;
	static uint8_t a[BS], b[BS];
	open_faulty();
	storage_faulty_flip_rate(&fy, 0.25, 7);
	unsigned long flips = 0;
	uint32_t block = wr.dir[0].frames_first;
	assert_int_equal(sf.bd.read(sf.bd.ctx, block, a), BS);
	for (int i = 0; i < 4000; i++) {
		unsigned long before = fy.flips;
		assert_int_equal(fy.bd.read(fy.bd.ctx, block, b), BS);
		assert_int_equal(memcmp(a, b, BS) != 0, fy.flips != before);
	}
	flips = fy.flips;
	assert_true(flips > 800 && flips < 1200); /* 1000 expected */
	/* the same seed gives the same faults */
	storage_faulty_flip_rate(&fy, 0.25, 7);
	fy.flips = 0;
	for (int i = 0; i < 4000; i++)
		fy.bd.read(fy.bd.ctx, block, b);
	assert_int_equal(fy.flips, flips);
	/* played at that rate, every lost frame is named and the rest decode */
	storage_faulty_flip_rate(&fy, 0.25, 99);
	fy.flips = 0;
	skp_error err;
	/* the header and directory may be hit too: retry opening as a device would */
	int opened = 0;
	for (int t = 0; t < 20 && !opened; t++)
		opened = skp_image_open(&im, &fy.bd, &err) == SKP_OK && skp_clip_stream_open(&pl, &im, 0, &err) == SKP_OK;
	assert_true(opened);
	int lost = 0, r;
	static amc_frame f;
	while ((r = skp_clip_stream_next(&pl, &f, &err)) != 0) {
		if (r == SKP_CLIP_LOST) {
			assert_true(err.block >= (long)wr.dir[0].frames_first);
			assert_true(err.block < (long)(wr.dir[0].frames_first + wr.dir[0].frame_blocks));
			lost++;
		} else {
			assert_int_equal(r, 1);
		}
	}
	assert_true(lost > 0 && lost < 300);
	storage_file_close(&sf);
}

static void test_fault_short_read(void **state)
{
	(void)state;
	static uint8_t b[BS];
	long bad;
	char why[200];
	open_faulty();
	uint32_t target = wr.dir[0].frames_first + 1;
	assert_int_equal(storage_faulty_short(&fy, target, 100), 0);
	assert_int_equal(fy.bd.read(fy.bd.ctx, target, b), 100);
	assert_int_equal(play_all(&bad, why), wr.dir[0].frames_per_block);
	assert_int_equal(bad, target);
	assert_string_equal(why, "short read");
	/* a short read of the header: the copy at the end stands in; both
	 * short, the image is refused naming block 0 */
	skp_error err;
	assert_int_equal(storage_faulty_short(&fy, 0, BS - 1), 0);
	assert_int_equal(skp_image_open(&im, &fy.bd, &err), SKP_OK);
	assert_true(im.header_from_copy);
	assert_int_equal(storage_faulty_short(&fy, wr.hdr.copy_block, BS - 1), 0);
	assert_int_equal(skp_image_open(&im, &fy.bd, &err), SKP_ERR_CORRUPT);
	assert_int_equal(err.block, 0);
	assert_non_null(strstr(err.msg, "short read"));
	storage_file_close(&sf);
}

static void test_fault_io_error(void **state)
{
	(void)state;
	static uint8_t b[BS];
	long bad;
	char why[200];
	open_faulty();
	uint32_t last = wr.dir[0].frames_first + wr.dir[0].frame_blocks - 1;
	assert_int_equal(storage_faulty_eio(&fy, last), 0);
	assert_int_equal(fy.bd.read(fy.bd.ctx, last, b), SKP_BD_EIO);
	assert_int_equal(fy.eios, 1);
	/* the last block holds the clip's tail: 300 - 23 * 13 frames */
	uint32_t fpb = wr.dir[0].frames_per_block;
	assert_int_equal(play_all(&bad, why), (int)(300 - (wr.dir[0].frame_blocks - 1) * fpb));
	assert_int_equal(bad, last);
	assert_string_equal(why, "I/O error");
	/* an I/O error in the skeleton section refuses loading it, naming the block */
	static skel loaded;
	skp_error err;
	assert_int_equal(storage_faulty_eio(&fy, 1), 0);
	assert_int_equal(skp_image_open(&im, &fy.bd, &err), SKP_OK);
	assert_int_equal(skp_image_load_skel(&im, &loaded, &err), SKP_ERR_IO);
	assert_int_equal(err.block, 1);
	storage_file_close(&sf);
}

static void test_fault_slow_reads(void **state)
{
	(void)state;
	long bad;
	char why[200];
	open_faulty();
	storage_faulty_delay(&fy, 2000);
	uint64_t t0 = clock_now_ns();
	assert_int_equal(play_all(&bad, why), 0);
	uint64_t ns = clock_now_ns() - t0;
	/* every read paid the delay, and slow storage loses nothing */
	assert_true(ns >= (uint64_t)fy.reads * 2000000u);
	assert_true(fy.reads >= wr.dir[0].frame_blocks);
	storage_file_close(&sf);
}

/* With parity the same faults lose nothing: each block is rebuilt. */
static void test_faults_rebuilt_with_parity(void **state)
{
	(void)state;
	long bad;
	char why[200];
	assert_int_equal(write_file(4), 0); /* 19 data blocks: 5 groups */
	open_faulty();
	uint32_t first = wr.dir[0].frames_first;
	assert_int_equal(storage_faulty_flip(&fy, first + 5, 8 * 100 + 3), 0);
	assert_int_equal(storage_faulty_short(&fy, first + 6, 100), 0); /* consecutive: other groups */
	assert_int_equal(storage_faulty_eio(&fy, first + 7), 0);
	assert_int_equal(play_all(&bad, why), 0);
	assert_int_equal(im.rebuilt, 3);
	/* the header too, through the copy */
	skp_error err;
	assert_int_equal(storage_faulty_eio(&fy, 0), 0);
	assert_int_equal(skp_image_open(&im, &fy.bd, &err), SKP_OK);
	assert_true(im.header_from_copy);
	storage_file_close(&sf);
	assert_int_equal(write_file(-1), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_file_blocks_and_reader),
		cmocka_unit_test(test_no_fault_plays_everything),
		cmocka_unit_test(test_fault_bit_flip),
		cmocka_unit_test(test_fault_random_rate),
		cmocka_unit_test(test_fault_short_read),
		cmocka_unit_test(test_fault_io_error),
		cmocka_unit_test(test_fault_slow_reads),
		cmocka_unit_test(test_faults_rebuilt_with_parity),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
