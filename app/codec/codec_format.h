/* A compressed motion clip (the image's clip frames from format version
 * 5, app/image/image_format.h): every dof of every frame as an integer q
 * on its track's grid, value = base + q * step (float, as
 * codec_value computes it: the same bits on every board), the q coded in
 * segments of frames that decode on their own (random access by segment).
 *
 * TRACKS. A track (one dof) has base and step (f32) and bits, the width of
 * its largest q (0: the track is constant, every value base, and has no
 * data at all). pack chooses each track's step as the largest that keeps
 * the clip's error within its budget (app/encode).
 *
 * SEGMENTS. Frames [s * segment_frames, ...) of segment s, the last one
 * shorter. A segment is a bit stream, least significant bit first, bytes
 * in order:
 *
 *   per coded track (bits > 0), in dof order: 2 bits its predictor P in
 *   this segment (0: every q is the first one), then, for P 1 to 3, 5 bits
 *   k, the Rice parameter of its residuals (one k a segment: the
 *   encoder's best; a k adapting to the residuals as they came, LOCO-I's
 *   rule, took 1-3% more on the CMU clips);
 *   then frame by frame, per coded track in dof order: the first frame
 *   (the first two for P 2 and 3) of the segment give q itself (bits wide;
 *   a P 0 track gives it once, in frame 0, and nothing after); every later
 *   frame gives the residual r = q - prediction, zigzag-coded (z = 2r for
 *   r >= 0, -2r - 1 else) as a Rice code with the track's k: z >> k zero bits, a one
 *   bit, then the low k bits of z; or, when z >> k would reach
 *   CODEC_RICE_ESCAPE, that many zero bits, a one bit and z in
 *   CODEC_ESCAPE_BITS bits. Predictions: P 1 the last q, P 2 twice the
 *   last less the one before, P 3 the last plus half (floor) the last
 *   step. A longer run of zero bits, a q outside [0, 2^bits), or a stream
 *   that runs past its bytes is corrupt.
 *
 * Frame-major order lets a player decode a frame at a time with one
 * cursor and a little state per track; seeking inside a segment decodes
 * from its start. */
#ifndef CODEC_FORMAT_H
#define CODEC_FORMAT_H

#include <stdint.h>

#include "board_limits.h"

#define CODEC_MAX_BITS 24             /* a track's q below 2^24: exact in a float */
#define CODEC_MAX_K 24
#define CODEC_RICE_ESCAPE 24          /* this many zero bits: z follows raw */
#define CODEC_ESCAPE_BITS 27          /* z < 6 * 2^24 for every predictor */
#define CODEC_SEGMENT_FRAMES 256      /* what pack writes (halved while a segment is too big) */
#define CODEC_MAX_SEGMENT_FRAMES 1024 /* what a reader takes */

/* The largest segment a board reads (its buffer): pack refuses a clip whose
 * segment would be larger. */
#ifndef SKP_CODEC_SEGMENT_BYTES
#define SKP_CODEC_SEGMENT_BYTES 16384
#endif

typedef struct codec_track {
	float base, step;
	uint8_t bits;
} codec_track;

typedef struct codec_clip {
	uint32_t frames;
	uint16_t tracks, segment_frames;
	codec_track track[SKP_MAX_DOF];
} codec_clip;

static inline uint32_t codec_segments(const codec_clip *c)
{
	return c->segment_frames ? (c->frames + c->segment_frames - 1u) / c->segment_frames : 0;
}

/* A track's value for q: base + q * step with two roundings, product then
 * sum, so that every board and every caller gets the same bits. Defined
 * in codec_decode.c, a core file built in ISO C mode (no multiply-add
 * contracted): inline here, the encoder and tests (GNU C mode) got a fused
 * multiply-add on aarch64, one rounding, other values than the player's. */
float codec_value(const codec_track *t, int32_t q);

#endif
