/* The compressed clip codec (app/codec, app/encode) on a few real clips
 * (../shared/data) and on made-up and broken input (every shared clip:
 * tests/integration/test_codec_corpus.c):
 * - a segment decoded on its own (a seek) gives the frames decoding from
 *   the clip's start gives;
 * - still and single-frame clips, every cut of a segment and bit flips:
 *   an error or values on the tracks' grids, never a read past the bytes. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "codec_decode.h"
#include "codec_format.h"
#include "test_codec_clip.h"
#include "test_paths.h"

typedef codec_test_clip clip;

static clip clip_of;
static codec_decoder dec;
static float values[SKP_MAX_DOF];

/* Segment by segment from the start, and each segment on its own after
 * another one was decoded: the same values, bit for bit. */
static void test_seek_lands_on_the_same_frame(void **state)
{
	(void)state;
	clip *c = &clip_of;
	if (codec_test_load("mocap/cmu/kick.asf", "mocap/cmu/kick.amc", c))
		skip();
	/* under the sanitizers or an emulator (the encoder's search: 22 s
	 * under qemu for four segments' worth) three segments of 32 frames,
	 * the last half full: the same seeks; the native run takes the clip */
	const int seg = test_slow() ? CODEC_SEGMENT_FRAMES / 8 : 0;
	if (seg && c->n > 2 * seg + seg / 2)
		c->n = 2 * seg + seg / 2;
	encode_result r;
	skp_error err;
	codec_test_encode_segments(c, seg, &r);
	assert_true(r.segments >= 3);
	float *all = malloc(sizeof(float) * (size_t)c->n * (size_t)c->s.dof_count);
	codec_test_decode_all(c, &r, all);
	for (uint32_t k = 0; k < r.segments; k++) {
		uint32_t s = (k * 7 + 2) % r.segments, n;
		const uint8_t *b = codec_test_segment(&r, s, &n);
		assert_int_equal(codec_begin(&dec, &r.clip, s, b, n, &err), SKP_OK);
		for (long i = (long)s * r.clip.segment_frames; codec_next(&dec, values, &err) == 1; i++)
			assert_memory_equal(values, all + (size_t)i * (size_t)c->s.dof_count,
					    sizeof(float) * (size_t)c->s.dof_count);
	}
	free(all);
	encode_result_free(&r);
	free(c->frames);
}

/* A clip that never moves is its tracks' bases: no segment data beyond
 * the headers; one frame alone encodes too. */
static void test_still_and_single_frame(void **state)
{
	(void)state;
	clip *c = &clip_of;
	if (codec_test_load("mocap/cmu/02.asf", "mocap/cmu/02_01.amc", c))
		skip();
	/* under the sanitizers or an emulator 10 frames (100: 4 s under qemu) */
	const long still = test_slow() ? 10 : 100;
	for (long f = 1; f < still; f++)
		memcpy(c->frames + (size_t)f * (size_t)c->s.dof_count, c->frames, sizeof(float) * (size_t)c->s.dof_count);
	c->n = still;
	encode_result r;
	codec_test_encode(c, &r);
	for (int t = 0; t < r.clip.tracks; t++)
		assert_int_equal(r.clip.track[t].bits, 0);
	assert_true(r.nbytes <= 1);
	assert_true(codec_test_decode_all(c, &r, NULL) <= CODEC_TEST_BUDGET_CM);
	encode_result_free(&r);
	c->n = 1;
	codec_test_encode(c, &r);
	assert_int_equal(r.segments, 1);
	assert_true(codec_test_decode_all(c, &r, NULL) <= CODEC_TEST_BUDGET_CM);
	encode_result_free(&r);
	free(c->frames);
}

/* Every value decoded is on its track's grid (a q in [0, 2^bits)). */
static void assert_on_grid(const codec_clip *cc, const float *v)
{
	for (int t = 0; t < cc->tracks; t++) {
		const codec_track *tr = &cc->track[t];
		int32_t q = codec_last_q(&dec, t);
		assert_true(q >= 0 && (tr->bits ? q < (1 << tr->bits) : q == 0));
		assert_true(v[t] == codec_value(tr, q));
	}
}

/* Runs a (damaged) segment to its end or its first error. */
static int run_segment(const codec_clip *cc, uint32_t s, const uint8_t *b, uint32_t n)
{
	skp_error err;
	if (codec_begin(&dec, cc, s, b, n, &err) != SKP_OK)
		return -1;
	int rc;
	while ((rc = codec_next(&dec, values, &err)) == 1)
		assert_on_grid(cc, values);
	return rc;
}

static void test_damaged_segments(void **state)
{
	(void)state;
	clip *c = &clip_of;
	if (codec_test_load("mocap/cmu/09.asf", "mocap/cmu/09_06.amc", c))
		skip();
	/* segment 0 is the one damaged: the clip's first (under the sanitizers
	 * or an emulator 32 frames of it and a quarter of the bit flips: the
	 * encoder's search and the cuts took 6 s under qemu) */
	const int slow = test_slow();
	const long frames = slow ? CODEC_SEGMENT_FRAMES / 8 : CODEC_SEGMENT_FRAMES;
	if (c->n > frames)
		c->n = frames;
	encode_result r;
	codec_test_encode(c, &r);
	uint32_t n;
	const uint8_t *b = codec_test_segment(&r, 0, &n);
	uint8_t *copy = malloc(n);
	int errors = 0;
	for (uint32_t cut = 0; cut < n; cut++) {
		memcpy(copy, b, cut); /* a fresh buffer of exactly cut bytes: ASan sees any read past it */
		uint8_t *exact = malloc(cut ? cut : 1);
		memcpy(exact, copy, cut);
		errors += run_segment(&r.clip, 0, exact, cut) < 0; /* else it read zeros: still on the grid */
		free(exact);
	}
	print_message("segment 0 (%lu bytes) cut at every length: %d refused\n", (unsigned long)n, errors);
	assert_true(errors > (int)n / 2);
	unsigned seed = 12345;
	for (int i = 0; i < (slow ? 500 : 2000); i++) {
		memcpy(copy, b, n);
		for (int k = 0; k < 3; k++) {
			seed = seed * 1103515245u + 12345u;
			copy[(seed >> 8) % n] ^= (uint8_t)(1u << ((seed >> 4) & 7));
		}
		run_segment(&r.clip, 0, copy, n);
	}
	free(copy);
	encode_result_free(&r);
	free(c->frames);
}

static void test_header_check(void **state)
{
	(void)state;
	static codec_clip cc;
	skp_error err;
	memset(&cc, 0, sizeof cc);
	cc.frames = 10;
	cc.tracks = 2;
	cc.segment_frames = 4;
	cc.track[0] = (codec_track){ 1.0f, 0.5f, 8 };
	assert_int_equal(codec_clip_check(&cc, &err), SKP_OK);
	cc.track[1] = (codec_track){ NAN, 0.5f, 8 };
	assert_int_equal(codec_clip_check(&cc, &err), SKP_ERR_CORRUPT);
	cc.track[1] = (codec_track){ 1.0f, 0.5f, CODEC_MAX_BITS + 1 };
	assert_int_equal(codec_clip_check(&cc, &err), SKP_ERR_CORRUPT);
	cc.track[1] = (codec_track){ 3e38f, 1e38f, 8 };
	assert_int_equal(codec_clip_check(&cc, &err), SKP_ERR_CORRUPT);
	cc.track[1] = (codec_track){ 1.0f, 0.5f, 8 };
	cc.segment_frames = 0;
	assert_int_equal(codec_clip_check(&cc, &err), SKP_ERR_CORRUPT);
	cc.segment_frames = 4;
	uint8_t none[1] = { 0 };
	assert_int_equal(codec_begin(&dec, &cc, 3, none, 0, &err), SKP_ERR_RANGE);
	assert_int_equal(codec_begin(&dec, &cc, 2, none, 0, &err), SKP_ERR_CORRUPT);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_header_check),
		cmocka_unit_test(test_still_and_single_frame),
		cmocka_unit_test(test_seek_lands_on_the_same_frame),
		cmocka_unit_test(test_damaged_segments),
	};
	return cmocka_run_group_tests_name("codec", tests, NULL, NULL);
}
