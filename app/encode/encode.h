/* The motion clip encoder (host only: it holds the whole clip and may
 * allocate): a clip's frames into the compressed format of
 * app/codec/codec_format.h, as small as it can make them while the error
 * stays within a budget measured the way ACL measures it: points a shell
 * distance from every joint, along its three axes, moved by the joint's
 * whole transform, compared with where the source puts them, on every
 * frame (encode_error.h).
 *
 * How (encode.c): each track's grid step starts from what the joint's
 * reach allows (the distance its rotation moves the points it carries),
 * scaled together until the clip's worst error is within the budget, then
 * grown one track at a time while it stays so. A joint with three
 * rotational dofs takes up its ancestors' rounding (encode_compensate.c): its
 * angles are chosen against the decoded parent, not the source's, so
 * errors do not pile up down a limb. The grid values are then coded in
 * segments (encode_segment.h): per track the predictor (constant, last
 * value, a straight line through the last two, or the last plus half the
 * last step) and the Rice parameter
 * that make it shortest, 120 Hz motion leaving small residuals. */
#ifndef ENCODE_H
#define ENCODE_H

#include <stddef.h>

#include "codec_format.h"
#include "skel.h"
#include "skp_error.h"

typedef struct encode_opts {
	double tolerance;   /* worst shell error allowed, skeleton units */
	double shell;       /* the shell's distance from each joint, skeleton units */
	int segment_frames; /* 0: CODEC_SEGMENT_FRAMES */
	/* told of progress (0..1) while the steps are searched; may be NULL */
	void (*progress)(void *ctx, double done);
	void *progress_ctx;
} encode_opts;

typedef struct encode_result {
	codec_clip clip;
	uint8_t *bytes;         /* the segments, one after another */
	size_t nbytes;
	uint32_t *offsets;      /* segment s is bytes [offsets[s], offsets[s + 1]) */
	uint32_t segments;
	double worst, p99;      /* shell error over every frame, skeleton units */
} encode_result;

/* Encodes n frames (n x s->dof_count values, as amc_frame.value) of
 * skeleton s. Fails on a limit (a segment larger than
 * SKP_CODEC_SEGMENT_BYTES, a track needing more than CODEC_MAX_BITS) or
 * out of memory. */
skp_status encode_clip(const skel *s, const float *frames, long n, const encode_opts *o, encode_result *r,
		       skp_error *err);

void encode_result_free(encode_result *r);

#endif
