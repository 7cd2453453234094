/* Compressed clips in a flash image (format version 5, app/codec through
 * app/image): the image's clip stream gives, bit for bit, what the codec
 * decodes from the encoder's bytes; a seek lands on the frame decoding
 * from the start gives; a damaged frames block is rebuilt from parity, or
 * loses only the segments touching it (the rest plays, nothing crashes),
 * a forged one (CRC recomputed) is refused or stays on the grid; version 4
 * images (quantised clips) still read; a clip made from integers alone
 * (tests/support/codec_synth.h) decodes to the same bits as on the host
 * where this runs (the Pi's build under qemu-user; the Cortex-M4's is
 * tests/embedded/emb_skin.c). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "codec_decode.h"
#include "codec_synth.h"
#include "encode.h"
#include "encode_segment.h"
#include "image_stream.h"
#include "image_survey.h"
#include "image_write.h"
#include "test_box.h"

#define BS 512
#define CAP (1 << 20)
#define FRAMES 700
#define FIRST 5

static skel s;
static mesh m;
static skin_weights w;
static amc_frame tiny[64];
static float src[FRAMES * SKP_MAX_DOF];
static float want[FRAMES][SKP_MAX_DOF];
static uint8_t img[CAP];
static size_t img_size;
static skp_image im;
static skp_clip_stream st;
static skp_image_writer wr;
static encode_result enc;

/* A smooth made-up motion with a little noise: every dof moves. */
static void make_motion(void)
{
	uint32_t n = 12345;
	for (int f = 0; f < FRAMES; f++)
		for (int d = 0; d < s.dof_count; d++) {
			n = n * 1103515245u + 12345u;
			double noise = ((n >> 16) & 1023) / 1023.0 - 0.5;
			src[f * s.dof_count + d] = (float)(sin(0.02 * f + d) * (d < 3 ? 20.0 : 30.0) + 0.05 * noise);
		}
}

/* What the codec decodes from the encoder's bytes: the reference. */
static void decode_reference(void)
{
	static codec_decoder d;
	skp_error err;
	int f = 0;
	for (uint32_t sg = 0; sg < enc.segments; sg++) {
		assert_int_equal(codec_begin(&d, &enc.clip, sg, enc.bytes + enc.offsets[sg],
					     enc.offsets[sg + 1] - enc.offsets[sg], &err), SKP_OK);
		while (codec_next(&d, want[f], &err) == 1)
			f++;
	}
	assert_int_equal(f, FRAMES);
}

static int setup(void **state)
{
	(void)state;
	test_tiny_inputs(&s, tiny, 64, &m, &w);
	make_motion();
	encode_opts o = { 0.01, 3.0, 128, NULL, NULL };
	skp_error err;
	if (encode_clip(&s, src, FRAMES, &o, &enc, &err) != SKP_OK)
		return -1;
	decode_reference();
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	encode_result_free(&enc);
	return 0;
}

static void next_id(uint8_t id[SKP_IMAGE_ID_BYTES])
{
	for (int i = 0; i < SKP_IMAGE_ID_BYTES; i++)
		id[i] = (uint8_t)(0x5a ^ (i * 37));
}

/* The image: the tiny arm's body and the compressed clip; parity: data
 * blocks a group, -1 none. */
static void pack_version(int parity, int version)
{
	static skp_mem_blockdev mb;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	skp_error err;
	skp_blockdev dev = skp_mem_blockdev_init(&mb, img, CAP, BS);
	memset(img, 0, CAP);
	next_id(id);
	assert_int_equal(skp_image_write_begin(&wr, &dev, 1, id, &s, &err), SKP_OK);
	wr.parity_group = parity;
	wr.hdr.version = (uint16_t)version;
	assert_int_equal(skp_image_write_bind(&wr, &m, &w, NULL, 0, &err), SKP_OK);
	skp_coded_clip k = { &enc.clip, enc.bytes, (uint32_t)enc.nbytes, enc.offsets, enc.segments, FIRST,
			     0.01f, 0.1f, 0.01f, 1.0f };
	assert_int_equal(skp_image_clip_coded(&wr, "coded", 120.0f, &k, &err), SKP_OK);
	assert_int_equal(skp_image_write_end(&wr, &err), SKP_OK);
	img_size = mb.size;
}

static void pack(int parity)
{
	pack_version(parity, SKP_IMAGE_VERSION);
}

static void open_clip(void)
{
	static skp_mem_blockdev rb;
	static skp_blockdev rdev;
	skp_error err;
	rdev = skp_mem_blockdev_ro(&rb, img, img_size, BS);
	assert_int_equal(skp_image_open(&im, &rdev, &err), SKP_OK);
	assert_int_equal(skp_clip_stream_open(&st, &im, 0, &err), SKP_OK);
}

static void assert_frame(const amc_frame *f, int index)
{
	assert_int_equal(f->number, FIRST + index);
	if (memcmp(f->value, want[index], sizeof(float) * (size_t)s.dof_count))
		fail_msg("frame %d differs from the codec's decode", index);
}

static void test_stream_is_the_codec_bit_for_bit(void **state)
{
	(void)state;
	static amc_frame f;
	skp_error err;
	pack(0);
	open_clip();
	const skp_image_clip *c = &im.clip[0];
	assert_int_equal(im.hdr.version, SKP_IMAGE_VERSION);
	assert_int_equal(c->coded, 1);
	assert_int_equal(c->frame_count, FRAMES);
	assert_int_equal(c->segments, enc.segments);
	assert_int_equal(c->stream_bytes, enc.nbytes);
	assert_true(enc.segments >= 5);          /* 128 frames a segment */
	assert_true(c->frame_blocks >= 2 * enc.segments / 3); /* segments span blocks */
	uint64_t h = 1469598103934665603ull;
	for (int i = 0; i < FRAMES; i++) {
		assert_int_equal(skp_clip_stream_next(&st, &f, &err), 1);
		assert_frame(&f, i);
		for (size_t b = 0; b < sizeof(float) * (size_t)s.dof_count; b++)
			h = (h ^ ((const uint8_t *)f.value)[b]) * 1099511628211ull;
	}
	assert_int_equal(skp_clip_stream_next(&st, &f, &err), 0);
	printf("%d frames, %lu stream bytes (%.1f a frame) in %lu blocks of %d, %lu segments; checksum %016llx\n", FRAMES,
	       (unsigned long)c->stream_bytes, c->stream_bytes / (double)FRAMES, (unsigned long)c->frame_blocks, BS,
	       (unsigned long)c->segments, (unsigned long long)h);
	/* the acceptance's view of its range: within every value */
	static float qmin[SKP_MAX_DOF], qstep[SKP_MAX_DOF];
	assert_int_equal(skp_image_load_quant(&im, 0, qmin, qstep, &err), SKP_OK);
	for (int d = 0; d < s.dof_count; d++)
		for (int i = 0; i < FRAMES; i++)
			assert_true(want[i][d] >= qmin[d] && want[i][d] <= qmin[d] + 65535.0f * qstep[d] * 1.0001f + 1e-6f);
	assert_int_equal(skp_image_check_frames(&im, 0, &err), SKP_OK);
}

static void test_seek_lands_on_the_same_frame(void **state)
{
	(void)state;
	static amc_frame f;
	skp_error err;
	pack(0);
	open_clip();
	const int at[] = { 0, 1, 127, 128, 129, 699, 300, 5, 256, 255, 640, 641, 0, 383 };
	for (size_t i = 0; i < sizeof at / sizeof at[0]; i++) {
		skp_clip_stream_seek(&st, (uint32_t)at[i]);
		for (int k = 0; k < 3 && at[i] + k < FRAMES; k++) {
			assert_int_equal(skp_clip_stream_next(&st, &f, &err), 1);
			assert_frame(&f, at[i] + k);
		}
	}
}

/* Plays the clip; returns the frames lost, checking every good one. */
static int play_all(int *first_lost, int *last_lost)
{
	static amc_frame f;
	skp_error err;
	int lost = 0;
	*first_lost = *last_lost = -1;
	for (int i = 0; i < FRAMES; i++) {
		int r = skp_clip_stream_next(&st, &f, &err);
		if (r == SKP_CLIP_LOST) {
			assert_true(err.block >= (long)im.clip[0].quant_first);
			if (*first_lost < 0)
				*first_lost = i;
			*last_lost = i;
			lost++;
			continue;
		}
		assert_int_equal(r, 1);
		assert_frame(&f, i);
	}
	assert_int_equal(skp_clip_stream_next(&st, &f, &err), 0);
	return lost;
}

static void test_damaged_block_rebuilt_or_its_segments_lost(void **state)
{
	(void)state;
	int a, b;
	/* with parity: rebuilt, every frame as packed */
	pack(0);
	open_clip();
	uint32_t block = im.clip[0].frames_first + im.clip[0].frame_blocks / 2;
	img[(size_t)block * BS + 100] ^= 0x20;
	open_clip();
	assert_int_equal(play_all(&a, &b), 0);
	assert_true(im.rebuilt >= 1);
	/* without: the segments touching the block are lost, the rest plays */
	pack(-1);
	open_clip();
	block = im.clip[0].frames_first + im.clip[0].frame_blocks / 2;
	img[(size_t)block * BS + 100] ^= 0x20;
	open_clip();
	int lost = play_all(&a, &b);
	uint32_t room = BS - SKP_IMAGE_BLOCK_EXTRA - SKP_IMAGE_FRAMES_COUNT;
	uint32_t lo = (block - im.clip[0].frames_first) * room, hi = lo + room;
	int expect = 0;
	for (uint32_t sg = 0; sg < enc.segments; sg++)
		if (enc.offsets[sg] < hi && enc.offsets[sg + 1] > lo)
			expect += sg + 1 < enc.segments ? 128 : FRAMES - 128 * (int)sg;
	assert_int_equal(lost, expect);
	assert_int_equal(a % 128, 0);
	printf("a frames block beyond repair: frames %d..%d lost (%d), the other %d as packed\n", a, b, lost, FRAMES - lost);
	/* played again: the same (the ring and the kept copies do not hide it) */
	skp_clip_stream_seek(&st, 0);
	assert_int_equal(play_all(&a, &b), lost);
}

/* A forger's change (CRC made good again) in the stream or in the offsets:
 * refused, or values still on the grid; never a crash or a read past. */
static void test_forged_stream_refused_or_on_grid(void **state)
{
	(void)state;
	static amc_frame f;
	skp_error err;
	pack(-1);
	uint32_t first = 0, blocks = 0, quant = 0;
	open_clip();
	first = im.clip[0].frames_first;
	blocks = im.clip[0].frame_blocks;
	quant = im.clip[0].quant_first;
	int refused = 0;
	for (uint32_t b = 0; b < blocks + 1; b++) {
		uint32_t at = b < blocks ? first + b : quant;
		for (int k = 0; k < 8; k++) {
			pack(-1);
			size_t off = (size_t)at * BS + SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_FRAMES_COUNT + (size_t)(k * 61 % 480);
			img[off] ^= (uint8_t)(1u << (k % 8));
			skp_block_seal(img + (size_t)at * BS, BS);
			static skp_mem_blockdev rb;
			static skp_blockdev rdev;
			rdev = skp_mem_blockdev_ro(&rb, img, img_size, BS);
			if (skp_image_open(&im, &rdev, &err) != SKP_OK || skp_clip_stream_open(&st, &im, 0, &err) != SKP_OK) {
				refused++;
				continue;
			}
			for (int i = 0; i < FRAMES; i++) {
				int r = skp_clip_stream_next(&st, &f, &err);
				assert_true(r == 1 || r == SKP_CLIP_LOST);
				refused += r == SKP_CLIP_LOST;
				for (int d = 0; r == 1 && d < s.dof_count; d++)
					assert_true(isfinite(f.value[d]));
			}
		}
	}
	printf("forged bytes: %d frames or clips refused\n", refused);
	assert_true(refused > 0);
}

/* Version 4 images (quantised clips, no version 5 fields) still read; a
 * version 4 writer takes no compressed clip. */
static void test_version_4_still_reads(void **state)
{
	(void)state;
	static skp_mem_blockdev mb;
	static skp_clip_range range;
	static amc_frame f;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	skp_error err;
	skp_blockdev dev = skp_mem_blockdev_init(&mb, img, CAP, BS);
	next_id(id);
	assert_int_equal(skp_image_write_begin(&wr, &dev, 1, id, &s, &err), SKP_OK);
	wr.hdr.version = 4;
	assert_int_equal(skp_image_write_bind(&wr, &m, &w, NULL, 0, &err), SKP_OK);
	skp_coded_clip k = { &enc.clip, enc.bytes, (uint32_t)enc.nbytes, enc.offsets, enc.segments, 0, 0, 0, 0, 0 };
	assert_int_not_equal(skp_image_clip_coded(&wr, "coded", 120.0f, &k, &err), SKP_OK);
	assert_non_null(strstr(err.msg, "version 4 has no compressed clips"));
	skp_clip_range_init(&range, &s);
	for (int i = 0; i < 100; i++) {
		f.number = i + 1;
		memcpy(f.value, want[i], sizeof(float) * (size_t)s.dof_count);
		assert_int_equal(skp_clip_range_add(&range, &f, &err), SKP_OK);
	}
	assert_int_equal(skp_image_clip_begin(&wr, "old", 120.0f, &range, &err), SKP_OK);
	for (int i = 0; i < 100; i++) {
		f.number = i + 1;
		memcpy(f.value, want[i], sizeof(float) * (size_t)s.dof_count);
		assert_int_equal(skp_image_clip_frame(&wr, &f, &err), SKP_OK);
	}
	assert_int_equal(skp_image_write_end(&wr, &err), SKP_OK);
	img_size = mb.size;
	open_clip();
	assert_int_equal(im.hdr.version, 4);
	assert_int_equal(im.clip[0].coded, 0);
	for (int i = 0; i < 100; i++) {
		assert_int_equal(skp_clip_stream_next(&st, &f, &err), 1);
		for (int d = 0; d < s.dof_count; d++)
			assert_true(fabsf(f.value[d] - want[i][d]) <= st.qstep[d] * 0.5f * 1.001f + 1e-6f);
	}
}

/* Frames played as packed, until the first that is lost or differs. */
static int frames_as_packed(void)
{
	static amc_frame f;
	skp_error err;
	int i = 0;
	skp_clip_stream_seek(&st, 0);
	for (; i < FRAMES; i++)
		if (skp_clip_stream_next(&st, &f, &err) != 1 || memcmp(f.value, want[i], sizeof(float) * (size_t)s.dof_count))
			break;
	return i;
}

/* A frames block forged (a byte changed, its CRC made good) in an image
 * without parity: version 7 holds the frames it carried (the block fails
 * its digest: lost, never played wrong); version 6 (no block digests,
 * still read) plays the forgery, and only the whole-image digest says so. */
static void test_forged_block_held_not_played(void **state)
{
	(void)state;
	static uint8_t buf[BS];
	skp_image_verdict v;
	for (int version = 6; version <= SKP_IMAGE_VERSION; version++) {
		pack_version(-1, version);
		open_clip();
		assert_int_equal(im.hdr.version, version);
		assert_int_equal(im.digests, version >= 7);
		assert_int_equal(frames_as_packed(), FRAMES);
		skp_image_verify(&im, buf, NULL, NULL, &v);
		assert_true(v.bad == 0 && v.digest == 1);
		uint8_t *b = img + (size_t)im.clip[0].frames_first * BS;
		b[SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_FRAMES_COUNT + 40] ^= 0x10;
		skp_block_seal(b, BS);
		open_clip();
		int played = frames_as_packed();
		skp_image_verify(&im, buf, NULL, NULL, &v);
		printf("version %d, first frames block forged: %d of %d frames as packed; verify: %ld bad, digest %d\n",
		       version, played, FRAMES, v.bad, v.digest);
		assert_true(played < FRAMES);
		if (version >= 7) {
			static amc_frame f;
			skp_error err;
			skp_clip_stream_seek(&st, 0);
			assert_int_equal(skp_clip_stream_next(&st, &f, &err), SKP_CLIP_LOST);
			assert_true(v.bad == 1 && v.beyond == 1 && v.digest == -1);
		} else {
			assert_true(v.bad == 0 && v.digest == 0);
		}
	}
}

/* The checksum of the host's decode (x86-64, GCC 12): every board's must
 * equal it. */
#define CODEC_SYNTH_SUM 0x4c1d14a7u

static void test_decode_bits_are_the_host_s(void **state)
{
	(void)state;
	static codec_clip c;
	static int32_t q[CODEC_SYNTH_FRAMES * CODEC_SYNTH_TRACKS];
	static codec_decoder d;
	static float v[CODEC_SYNTH_TRACKS];
	skp_error err;
	codec_synth_clip(&c);
	codec_synth_q(q);
	assert_int_equal(codec_clip_check(&c, &err), SKP_OK);
	uint32_t h = 2166136261u;
	long frames = 0, bytes = 0;
	for (uint32_t sg = 0; sg < codec_segments(&c); sg++) {
		enc_bits b = { 0 };
		long first = (long)sg * CODEC_SYNTH_SEGMENT;
		int len = (int)(CODEC_SYNTH_FRAMES - first < CODEC_SYNTH_SEGMENT ? CODEC_SYNTH_FRAMES - first : CODEC_SYNTH_SEGMENT);
		enc_segment(&c, q, CODEC_SYNTH_TRACKS, first, len, &b);
		assert_false(b.failed);
		assert_int_equal(codec_begin(&d, &c, sg, b.buf, (uint32_t)b.len, &err), SKP_OK);
		while (codec_next(&d, v, &err) == 1) {
			for (int t = 0; t < CODEC_SYNTH_TRACKS; t++)
				assert_int_equal(codec_last_q(&d, t), q[frames * CODEC_SYNTH_TRACKS + t]);
			h = codec_synth_hash(h, v, CODEC_SYNTH_TRACKS);
			frames++;
		}
		bytes += (long)b.len;
		enc_bits_free(&b);
	}
	assert_int_equal(frames, CODEC_SYNTH_FRAMES);
	printf("integer clip: %ld frames of %d tracks, %ld bytes, decode checksum %08lx (host %08lx)\n", frames,
	       CODEC_SYNTH_TRACKS, bytes, (unsigned long)h, (unsigned long)CODEC_SYNTH_SUM);
	assert_int_equal(h, CODEC_SYNTH_SUM);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_stream_is_the_codec_bit_for_bit),
		cmocka_unit_test(test_seek_lands_on_the_same_frame),
		cmocka_unit_test(test_damaged_block_rebuilt_or_its_segments_lost),
		cmocka_unit_test(test_forged_stream_refused_or_on_grid),
		cmocka_unit_test(test_version_4_still_reads),
		cmocka_unit_test(test_forged_block_held_not_played),
		cmocka_unit_test(test_decode_bits_are_the_host_s),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
