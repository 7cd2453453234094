/* app/image/FORMAT.md is a specification a reader can be written from: this
 * is such a reader, written from FORMAT.md alone (no app/image code, its own
 * CRC-32 from the parameters the spec gives; SHA-256 from app/base), run on
 * the default show pack makes. It checks every block's frame and CRC, the
 * header and its copy, the directory and its copy, the parity and the
 * digest; parses the skeleton, bind and directory to their exact ends; and
 * decodes a clip's first frame, whose root must be where `skintool fk` puts
 * it. A change of the format that FORMAT.md does not follow fails here. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sha256.h"
#include "test_paths.h"
#include "test_run.h"

/* "CRC-32: reflected polynomial 0xEDB88320, initial value and final XOR
 * 0xFFFFFFFF", bit by bit. */
static uint32_t spec_crc(const uint8_t *p, size_t n)
{
	uint32_t c = 0xffffffffu;
	while (n--) {
		c ^= *p++;
		for (int k = 0; k < 8; k++)
			c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
	}
	return ~c;
}

static uint32_t le16(const uint8_t *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8;
}

static uint32_t le32(const uint8_t *p)
{
	return le16(p) | le16(p + 2) << 16;
}

static float lef(const uint8_t *p)
{
	uint32_t u = le32(p);
	float f;
	memcpy(&f, &u, 4);
	return f;
}

typedef struct image {
	const uint8_t *data;
	size_t size;
	uint32_t bs, count, dofs, verts, tris, clips, bones, d, p, dir_copy, copy;
	uint32_t sec[4][3];     /* skeleton, bind, directory, clips: first, count, bytes */
	uint8_t id[16];
} image;

static const uint8_t *block(const image *im, uint32_t i)
{
	assert_true(i < im->count);
	return im->data + (size_t)i * im->bs;
}

/* A framed block: CRC, id, index, kind, item. */
static const uint8_t *framed(const image *im, uint32_t i, int kind, unsigned item)
{
	const uint8_t *b = block(im, i);
	assert_int_equal(spec_crc(b, im->bs - 4), le32(b + im->bs - 4));
	assert_memory_equal(b, im->id, 16);
	assert_int_equal(le32(b + 16), i);
	assert_int_equal(b[20], kind);
	assert_int_equal(b[21], 0);
	assert_int_equal(le16(b + 22), item);
	return b;
}

/* A section: the payloads of its blocks joined, cut to its bytes. */
typedef struct stream {
	uint8_t *buf;
	uint32_t len, at;
} stream;

static void stream_open(stream *s, const image *im, uint32_t first, uint32_t n, uint32_t bytes, int kind, unsigned item)
{
	uint32_t payload = im->bs - 28;
	assert_true((uint64_t)n * payload >= bytes);
	s->buf = malloc((size_t)n * payload + 1);
	assert_non_null(s->buf);
	for (uint32_t i = 0; i < n; i++)
		memcpy(s->buf + (size_t)i * payload, framed(im, first + i, kind, item) + 24, payload);
	s->len = bytes;
	s->at = 0;
}

static const uint8_t *take(stream *s, uint32_t n)
{
	assert_true(s->at + n <= s->len);
	s->at += n;
	return s->buf + s->at - n;
}

static void skip_str(stream *s)
{
	take(s, *take(s, 1));
}

static void read_header(image *im)
{
	assert_true(im->size >= 512);
	const uint8_t *h = im->data + 24;
	assert_memory_equal(h, "SKPIMAGE", 8);
	assert_int_equal(le16(h + 8), 8);
	assert_int_equal(le16(h + 10), 168);
	assert_int_equal(spec_crc(h, 164), le32(h + 164));
	im->bs = le32(h + 12);
	im->count = le32(h + 16);
	memcpy(im->id, h + 28, 16);
	im->bones = le32(h + 44);
	im->dofs = le32(h + 48);
	im->verts = le32(h + 52);
	im->tris = le32(h + 56);
	assert_int_equal(le32(h + 60), 4);
	im->clips = le32(h + 64);
	for (int i = 0; i < 4; i++)
		for (int k = 0; k < 3; k++)
			im->sec[i][k] = le32(h + 68 + 12 * i + 4 * k);
	im->d = le32(h + 116);
	im->p = le32(h + 120);
	im->dir_copy = le32(h + 124);
	im->copy = le32(h + 128);
	assert_true(im->bs >= 512 && im->bs % 16 == 0);
	assert_int_equal((uint64_t)im->count * im->bs, im->size);
	assert_int_equal(im->d + im->p + im->sec[2][1] + 1, im->count);
	assert_int_equal(im->dir_copy, im->d + im->p);
	assert_int_equal(im->copy, im->count - 1);
	assert_int_equal(im->sec[3][2], 0);
	framed(im, 0, 1, 0);
	/* the copy: the header at bytes B-172..B-5 of the last block */
	assert_memory_equal(framed(im, im->copy, 1, 1) + im->bs - 172, h, 168);
}

static void leaf_of(const uint8_t *b, uint32_t n, uint8_t leaf[16])
{
	sha256_ctx ctx;
	uint8_t sum[32];
	sha256_init(&ctx);
	sha256_update(&ctx, b, n);
	sha256_final(&ctx, sum);
	memcpy(leaf, sum, 16);
}

/* Version 7: the digest blocks (kind 7) after the directory end the data
 * blocks; a leaf for every block before them (block 0's zeros), then the
 * root over the digest blocks' own leaves in the header's digest field. */
static void check_block_digests(const image *im)
{
	uint32_t h = im->sec[2][0] + im->sec[2][1], per = (im->bs - 28) / 16;
	uint8_t leaf[16], zero[16] = { 0 };
	assert_int_equal(im->d - h, (h + per - 1) / per);
	for (uint32_t b = 0; b < h; b++) {
		const uint8_t *at = framed(im, h + b / per, 7, 0) + 24 + (b % per) * 16;
		if (b == 0) {
			assert_memory_equal(at, zero, 16);
			continue;
		}
		leaf_of(block(im, b), im->bs, leaf);
		assert_memory_equal(at, leaf, 16);
	}
	sha256_ctx ctx;
	uint8_t root[32];
	sha256_init(&ctx);
	for (uint32_t b = h; b < im->d; b++) {
		leaf_of(block(im, b), im->bs, leaf);
		sha256_update(&ctx, leaf, 16);
	}
	sha256_final(&ctx, root);
	assert_memory_equal(root, im->data + 24 + 132, 32);
}

static void check_parity_and_digest(const image *im)
{
	uint8_t *acc = malloc(im->bs);
	assert_non_null(acc);
	for (uint32_t g = 0; g < im->p; g++) {
		memset(acc, 0, im->bs);
		for (uint32_t b = g; b < im->d; b += im->p)
			for (uint32_t k = 0; k < im->bs; k++)
				acc[k] ^= block(im, b)[k];
		assert_memory_equal(acc, block(im, im->d + g), im->bs);
	}
	free(acc);
	check_block_digests(im);
	for (uint32_t i = 0; i < im->sec[2][1]; i++)
		assert_memory_equal(framed(im, im->sec[2][0] + i, 4, 0) + 24, framed(im, im->dir_copy + i, 4, 1) + 24,
				    im->bs - 28);
}

static void read_skeleton(const image *im)
{
	stream s;
	stream_open(&s, im, im->sec[0][0], im->sec[0][1], im->sec[0][2], 2, 0);
	skip_str(&s);
	skip_str(&s);
	take(&s, 4 + 4 + 1 + 12);
	uint32_t n = le16(take(&s, 2)), dofs = le16(take(&s, 2)), sum = 0;
	assert_int_equal(n, im->bones);
	assert_int_equal(dofs, im->dofs);
	assert_int_equal(take(&s, n)[0], 0); /* eval_order: the root first */
	for (uint32_t i = 0; i < n; i++) {
		skip_str(&s);
		take(&s, 4);
		int16_t parent = (int16_t)le16(take(&s, 2));
		assert_true(i == 0 ? parent == -1 : parent >= 0 && (uint32_t)parent < n);
		take(&s, 12 + 4 + 12 + 3);
		uint32_t channels = *take(&s, 1);
		assert_true(channels <= 7);
		take(&s, channels + 1 + 8 * channels);
		assert_int_equal(le16(take(&s, 2)), sum);
		sum += channels;
		take(&s, 16 + 12);
	}
	assert_int_equal(sum, dofs);
	assert_int_equal(s.at, s.len);
	free(s.buf);
}

/* Version 8's texture: its chain's bytes are every level's blocks, each
 * level half the one above down to 1 x 1. */
static void read_texture(stream *s, uint32_t v)
{
	uint8_t textured = *take(s, 1);
	assert_true(textured <= 1);
	if (!textured)
		return;
	take(s, 16 + 4 * v);
	for (uint32_t i = 0; i < v; i++)
		assert_true(*take(s, 1) <= 1);
	uint32_t w = le16(take(s, 2)), h = le16(take(s, 2)), format = *take(s, 1), bytes = le32(take(s, 4));
	assert_int_equal(format, 1);
	assert_true(w >= 1 && w <= 4096 && (w & (w - 1)) == 0 && h >= 1 && h <= 4096 && (h & (h - 1)) == 0);
	uint32_t chain = 0;
	for (;;) {
		chain += (w + 3) / 4 * ((h + 3) / 4) * 8;
		if (w == 1 && h == 1)
			break;
		w = w > 1 ? w / 2 : 1;
		h = h > 1 ? h / 2 : 1;
	}
	assert_int_equal(bytes, chain);
	take(s, bytes);
}

static void read_bind(const image *im)
{
	stream s;
	stream_open(&s, im, im->sec[1][0], im->sec[1][1], im->sec[1][2], 3, 0);
	uint32_t v = le32(take(&s, 4)), t = le32(take(&s, 4)), posed = *take(&s, 1);
	assert_int_equal(v, im->verts);
	assert_int_equal(t, im->tris);
	assert_true(posed <= 1);
	take(&s, 4 + (posed ? 4 * im->dofs : 0) + 24 + 6 * v + 4 * v);
	for (uint32_t i = 0; i < 3 * t; i++)
		assert_true(le32(take(&s, 4)) < v);
	for (uint32_t i = 0; i < v; i++) {
		const uint8_t *r = take(&s, 13);
		uint32_t sum = 0;
		assert_true(r[0] >= 1 && r[0] <= 4);
		for (int k = 0; k < r[0]; k++) {
			assert_true(r[1 + k] < im->bones);
			sum += le16(r + 5 + 2 * k);
		}
		assert_int_equal(sum, 65535);
	}
	uint8_t coloured = *take(&s, 1);
	assert_true(coloured <= 1);
	if (coloured)
		take(&s, 3 * v);
	read_texture(&s, v);
	assert_int_equal(s.at, s.len);
	free(s.buf);
}

/* Bits of a segment, least significant bit of each byte first. */
static uint32_t bits_take(const uint8_t *seg, uint32_t len, uint64_t *at, int n)
{
	uint32_t v = 0;
	for (int i = 0; i < n; i++, ++*at) {
		assert_true(*at / 8 < len);
		v |= (uint32_t)((seg[*at / 8] >> (*at % 8)) & 1u) << i;
	}
	return v;
}

/* A quantised clip's frame blocks and the root of its first frame. */
static void quantised_clip(const image *im, const uint8_t *e, unsigned c, float root[3])
{
	uint32_t frames = le32(e + 4), dofs = le16(e + 12), fpb = le16(e + 14);
	uint32_t qf = le32(e + 16), qn = le32(e + 20), ff = le32(e + 24), fn = le32(e + 28);
	assert_int_equal(fpb, (im->bs - 30) / (2 * dofs));
	assert_int_equal(fn, (frames + fpb - 1) / fpb);
	for (uint32_t b = 0; b < fn; b++) {
		uint32_t holds = frames - b * fpb < fpb ? frames - b * fpb : fpb;
		assert_int_equal(le16(framed(im, ff + b, 6, c) + 24), holds);
	}
	stream q;
	stream_open(&q, im, qf, qn, 8 * dofs, 5, c);
	for (int k = 0; k < 3; k++) {
		const uint8_t *mq = take(&q, 8);
		root[k] = lef(mq) + (float)le16(block(im, ff) + 26 + 2 * k) * lef(mq + 4);
	}
	free(q.buf);
}

/* A compressed clip: its header, its stream blocks' counts, and the root
 * of its first frame (frame 0 of segment 0 gives each track's q itself). */
static void compressed_clip(const image *im, const uint8_t *e, const uint8_t *v5, unsigned c, float root[3])
{
	uint32_t frames = le32(e + 4), dofs = le16(e + 12), fpb = le16(e + 14);
	uint32_t qf = le32(e + 16), qn = le32(e + 20), ff = le32(e + 24), fn = le32(e + 28);
	uint32_t bytes = le32(v5 + 1), segs = le32(v5 + 5), room = im->bs - 30;
	assert_int_equal(fpb, 0);
	assert_int_equal(fn, (bytes + room - 1) / room);
	uint8_t *stream_bytes = malloc(bytes + 1);
	assert_non_null(stream_bytes);
	for (uint32_t b = 0; b < fn; b++) {
		uint32_t holds = bytes - b * room < room ? bytes - b * room : room;
		const uint8_t *blk = framed(im, ff + b, 6, c);
		assert_int_equal(le16(blk + 24), holds);
		memcpy(stream_bytes + (size_t)b * room, blk + 26, holds);
	}
	stream q;
	stream_open(&q, im, qf, qn, 4 + 9 * dofs + 4 * (segs + 1), 5, c);
	assert_int_equal(le16(take(&q, 2)), dofs);
	uint32_t seg_frames = le16(take(&q, 2));
	assert_int_equal(segs, (frames + seg_frames - 1) / seg_frames);
	float base[3], step[3];
	uint8_t width[512];
	assert_true(dofs <= sizeof width);
	for (uint32_t t = 0; t < dofs; t++) {
		const uint8_t *tr = take(&q, 9);
		if (t < 3) {
			base[t] = lef(tr);
			step[t] = lef(tr + 4);
		}
		width[t] = tr[8];
	}
	uint32_t off0 = le32(take(&q, 4)), off1 = le32(take(&q, 4));
	assert_int_equal(off0, 0);
	assert_true(off1 <= bytes && off1 <= 16384);
	/* the predictors' header, then frame 0: q of each coded track */
	uint64_t at = 0;
	for (uint32_t t = 0; t < dofs; t++)
		if (width[t] && bits_take(stream_bytes, off1, &at, 2))
			bits_take(stream_bytes, off1, &at, 5);
	for (uint32_t t = 0; t < dofs; t++) {
		uint32_t qv = width[t] ? bits_take(stream_bytes, off1, &at, width[t]) : 0;
		if (t < 3) {
			volatile float scaled = (float)qv * step[t];
			root[t] = base[t] + scaled;
		}
	}
	free(q.buf);
	free(stream_bytes);
}

/* The directory; the first clip's first frame decoded into root[3]. */
static void read_clips(const image *im, float root[3])
{
	stream s;
	stream_open(&s, im, im->sec[2][0], im->sec[2][1], im->sec[2][2], 4, 0);
	uint32_t n = le16(take(&s, 2));
	assert_int_equal(n, im->clips);
	for (uint32_t c = 0; c < n; c++) {
		skip_str(&s);
		const uint8_t *e = take(&s, 4 + 4 + 4 + 2 + 2 + 16 + 8);
		const uint8_t *v5 = take(&s, 1 + 4 + 4 + 4 + 4);
		float mine[3];
		assert_true(lef(e) > 0.0f);
		assert_int_equal(le16(e + 12), im->dofs);
		assert_true(v5[0] <= 1);
		if (v5[0])
			compressed_clip(im, e, v5, c, mine);
		else
			quantised_clip(im, e, c, mine);
		if (c == 0)
			memcpy(root, mine, sizeof mine);
	}
	assert_int_equal(s.at, s.len);
	free(s.buf);
}

static void test_a_reader_from_the_spec(void **state)
{
	(void)state;
	const char *skn = test_tool_path("assets/demo.skn");
	if (access(skn, R_OK) != 0 || access(test_tool_path("skintool"), X_OK) != 0) {
		print_message("%s: not built here (a cross build): skipped\n", skn);
		skip();
	}
	image im = { 0 };
	uint8_t check[9];
	memcpy(check, "123456789", 9);
	assert_int_equal(spec_crc(check, 9), 0xcbf43926u);
	im.data = (const uint8_t *)test_read_file(skn, &im.size);
	assert_non_null(im.data);
	read_header(&im);
	check_parity_and_digest(&im);
	read_skeleton(&im);
	read_bind(&im);
	float root[3] = { 0, 0, 0 };
	read_clips(&im, root);
	/* the default show's first clip is 02_01 (assets/README.md) */
	const char *out = test_scratch("fk.csv");
	assert_int_equal(test_run("%s fk assets/cmu/02.asf assets/cmu/02_01.amc --frame=1 > %s", test_tool_path("skintool"), out),
			 0);
	char *csv = test_read_file(out, NULL);
	assert_non_null(csv);
	float x, y, z;
	const char *row = strstr(csv, "\n1,root,");
	assert_non_null(row);
	assert_int_equal(sscanf(row, "\n1,root,%f,%f,%f", &x, &y, &z), 3);
	free(csv);
	print_message("%s: %u blocks of %u, %u data, %u parity, %u clips; root of 02_01's first frame %.4f %.4f %.4f, "
		      "fk %.4f %.4f %.4f\n", skn, im.count, im.bs, im.d, im.p, im.clips, (double)root[0], (double)root[1],
		      (double)root[2], (double)x, (double)y, (double)z);
	/* within the shell error (0.01 cm: 0.004 units) of the source */
	assert_true(fabsf(root[0] - x) < 4e-3f && fabsf(root[1] - y) < 4e-3f && fabsf(root[2] - z) < 4e-3f);
	free((void *)im.data);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_a_reader_from_the_spec),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
