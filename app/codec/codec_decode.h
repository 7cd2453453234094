/* Decoding a compressed clip's segments (codec_format.h) frame by frame,
 * with fixed memory: the segment's bytes are the caller's (an image
 * player's buffer), the state a cursor and two values per track. Every
 * read is checked: a damaged segment is an error, never a read past its
 * bytes or a value off its track's grid. */
#ifndef CODEC_DECODE_H
#define CODEC_DECODE_H

#include "codec_format.h"
#include "skp_error.h"

typedef struct codec_track_state {
	int32_t q1, q2;      /* the last two q */
	uint8_t order, k;
} codec_track_state;

typedef struct codec_decoder {
	const codec_clip *clip;
	const uint8_t *bytes;
	uint32_t nbytes;
	uint64_t pos;        /* bit cursor */
	uint32_t segment, frame, length;  /* frame: next frame in the segment */
	codec_track_state t[SKP_MAX_DOF];
} codec_decoder;

/* Checks a clip header read from storage: counts within the board's
 * limits, finite base and step, bits at most CODEC_MAX_BITS. */
skp_status codec_clip_check(const codec_clip *c, skp_error *err);

/* Starts segment s of c over its n bytes (which must stay valid while
 * frames are read); reads the per-track header. */
skp_status codec_begin(codec_decoder *d, const codec_clip *c, uint32_t s, const uint8_t *bytes, uint32_t n,
		       skp_error *err);

/* The segment's next frame into values[c->tracks]: 1, 0 after its last
 * frame, or -SKP_ERR_CORRUPT (err says where). */
int codec_next(codec_decoder *d, float *values, skp_error *err);

/* The q of the frame codec_next last gave, per track (for tests). */
static inline int32_t codec_last_q(const codec_decoder *d, int track)
{
	return d->t[track].q1;
}

#endif
