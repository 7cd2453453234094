/* A shared mocap clip through the codec, for the codec's tests: loaded
 * whole, encoded within the budget, decoded segment by segment and checked
 * against the source on every frame. */
#ifndef TEST_CODEC_CLIP_H
#define TEST_CODEC_CLIP_H

#include <stdint.h>

#include "encode.h"
#include "skel.h"

#define CODEC_TEST_BUDGET_CM 0.01 /* ACL's default error budget */
#define CODEC_TEST_SHELL_CM 3.0   /* on ACL's shell: points 3 cm off each joint */

typedef struct codec_test_clip {
	skel s;
	float *frames; /* n frames of s.dof_count values */
	long n;
	double cm; /* cm a skeleton unit */
} codec_test_clip;

/* -1 (and nothing loaded) when the shared data is not there. */
int codec_test_load(const char *asf, const char *amc, codec_test_clip *c);
void codec_test_encode(const codec_test_clip *c, encode_result *r);
/* The same in segments of segment_frames (0: CODEC_SEGMENT_FRAMES). */
void codec_test_encode_segments(const codec_test_clip *c, int segment_frames, encode_result *r);
const uint8_t *codec_test_segment(const encode_result *r, uint32_t s, uint32_t *n);
/* Decodes every frame, checking each against the source (keeping the
 * values in keep, when given); the worst error in cm. */
double codec_test_decode_all(const codec_test_clip *c, const encode_result *r, float *keep);

#endif
