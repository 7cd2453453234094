/* An image packed in memory for the image tests (test_image,
 * test_image_recovery): the box body (test_box.h) bound to its skeleton,
 * with two clips, tiny.amc's frames and 200 made-up ones (several
 * 512-byte blocks), with or without parity, then opened from the same
 * bytes. Everything lives in the caller's storage, named by a
 * test_imgpack. */
#ifndef TEST_IMGPACK_H
#define TEST_IMGPACK_H

#include <stddef.h>
#include <stdint.h>

#include "image_stream.h"
#include "image_write.h"

#define TEST_IMGPACK_BS 512
#define TEST_IMGPACK_SYNTH 200 /* the made-up clip's frames */

typedef struct test_imgpack {
	const skel *s;             /* the skeleton the body and clips are for */
	const mesh *m;
	const skin_weights *w;
	const amc_frame *frames;   /* tiny.amc's, *frame_count of them */
	const int *frame_count;
	amc_frame *synth;          /* room for TEST_IMGPACK_SYNTH: made by the pack */
	skp_image_writer *wr;
	skp_clip_range *range;
	uint8_t *img;              /* cap bytes of storage, the image its first *size */
	size_t cap;
	size_t *size;
	skp_image *im;             /* the image opened, through *rb and *rdev */
	skp_mem_blockdev *rb;
	skp_blockdev *rdev;
} test_imgpack;

/* The storage a test program packs into and opens from (static: megabytes),
 * and the test_imgpack `pk` naming it. */
#define TEST_IMGPACK_CAP (1 << 20)
#define TEST_IMGPACK_STORAGE                                                                                      \
	static skel s, s2;                                                                                        \
	static mesh m, m2;                                                                                        \
	static skin_weights w, w2;                                                                                \
	static uint8_t img[TEST_IMGPACK_CAP];                                                                     \
	static size_t img_size;                                                                                   \
	static skp_image im;                                                                                      \
	static skp_clip_stream pl;                                                                                \
	static skp_image_writer wr;                                                                               \
	static skp_clip_range range;                                                                              \
	static amc_frame frames[64];                                                                              \
	static int frame_count;                                                                                   \
	static amc_frame synth[TEST_IMGPACK_SYNTH];                                                               \
	static skp_mem_blockdev rb;                                                                               \
	static skp_blockdev rdev;                                                                                 \
	static const test_imgpack pk = { &s, &m, &w, frames, &frame_count, synth, &wr, &range,                    \
					 img, TEST_IMGPACK_CAP, &img_size, &im, &rb, &rdev }

/* A made-up id per pack (pack draws it at random): each call another. */
void test_imgpack_next_id(uint8_t id[SKP_IMAGE_ID_BYTES]);

/* n made-up frames for skeleton s, numbered from 10. */
void test_imgpack_synth(const skel *s, amc_frame *f, int n);

/* Packs the body (bind_values as its bind frame 7, NULL for the rest
 * pose) and the clips "tiny" and "synth" into p->img, the storage zeroed
 * first; parity: data blocks per group, 0 the default, -1 none. Fails the
 * test if a step fails. */
void test_imgpack_pack(const test_imgpack *p, uint64_t sequence, const float *bind_values, int parity);

/* What the next packs carry besides: a texture (written with a textured
 * mesh; NULL none, the default) and a format version (0: the writer's
 * own). */
void test_imgpack_texture(const tex_image *t);
void test_imgpack_version(int version);

/* Opens the image from the first size bytes of p->img. */
skp_status test_imgpack_open(const test_imgpack *p, size_t size, skp_error *err);

/* Opening the first *p->size bytes fails with code, its message
 * containing needle. */
void test_imgpack_refused(const test_imgpack *p, const char *needle, skp_status code);

#endif
