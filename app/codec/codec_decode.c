#include "codec_decode.h"

#include <math.h>

float codec_value(const codec_track *t, int32_t q)
{
	float scaled = (float)q * t->step;
	return t->base + scaled;
}

/* Up to 57 bits from the cursor, bytes past the end read as 0 (the caller
 * checks the cursor against the end after consuming). */
static uint64_t window(const codec_decoder *d)
{
	uint64_t w = 0;
	uint64_t at = d->pos >> 3;
	if (at + 8 <= d->nbytes) {
		const uint8_t *p = d->bytes + at;
		w = (uint64_t)p[0] | (uint64_t)p[1] << 8 | (uint64_t)p[2] << 16 | (uint64_t)p[3] << 24 |
		    (uint64_t)p[4] << 32 | (uint64_t)p[5] << 40 | (uint64_t)p[6] << 48 | (uint64_t)p[7] << 56;
	} else {
		for (int i = 7; i >= 0; i--)
			w = w << 8 | (at + (uint64_t)i < d->nbytes ? d->bytes[at + (uint64_t)i] : 0u);
	}
	return w >> (d->pos & 7);
}

static int overrun(const codec_decoder *d)
{
	return d->pos > (uint64_t)d->nbytes * 8u;
}

/* n bits, 0 <= n <= 32 */
static uint32_t take(codec_decoder *d, int n)
{
	uint32_t v = n ? (uint32_t)(window(d) & (((uint64_t)1 << n) - 1)) : 0;
	d->pos += (unsigned)n;
	return v;
}

static skp_status bad(const codec_decoder *d, skp_error *err, const char *what)
{
	return skp_fail(err, SKP_ERR_CORRUPT, 0, "compressed segment %lu, frame %lu: %s", (unsigned long)d->segment,
			(unsigned long)d->frame, what);
}

/* A Rice-coded residual, zigzag undone; 0 on success. */
static int rice(codec_decoder *d, int k, int32_t *r)
{
	uint64_t w = window(d);
	if (w == 0)
		return -1;
	int quotient = __builtin_ctzll(w);
	if (quotient > CODEC_RICE_ESCAPE)
		return -1;
	d->pos += (unsigned)quotient + 1u;
	uint32_t z = quotient == CODEC_RICE_ESCAPE ? take(d, CODEC_ESCAPE_BITS) : ((uint32_t)quotient << k) | take(d, k);
	*r = (int32_t)(z >> 1) ^ -(int32_t)(z & 1);
	return overrun(d) ? -1 : 0;
}

skp_status codec_clip_check(const codec_clip *c, skp_error *err)
{
	if (c->tracks > SKP_MAX_DOF || c->segment_frames == 0 || c->segment_frames > CODEC_MAX_SEGMENT_FRAMES)
		return skp_fail(err, SKP_ERR_CORRUPT, 0, "compressed clip: %u tracks (board limit %d), %u frames a segment",
				(unsigned)c->tracks, SKP_MAX_DOF, (unsigned)c->segment_frames);
	for (int i = 0; i < c->tracks; i++) {
		const codec_track *t = &c->track[i];
		/* the width first: the top's shift needs it below 32 */
		float top = t->bits <= CODEC_MAX_BITS ? codec_value(t, (int32_t)((1u << t->bits) - 1u)) : 0.0f;
		if (t->bits > CODEC_MAX_BITS || !isfinite(t->base) || !isfinite(t->step) || !(t->step >= 0) ||
		    !isfinite(top))
			return skp_fail(err, SKP_ERR_CORRUPT, 0, "compressed clip: track %d: bits %u, base %g, step %g", i + 1,
					(unsigned)t->bits, (double)t->base, (double)t->step);
	}
	return SKP_OK;
}

skp_status codec_begin(codec_decoder *d, const codec_clip *c, uint32_t s, const uint8_t *bytes, uint32_t n,
		       skp_error *err)
{
	d->clip = c;
	d->bytes = bytes;
	d->nbytes = n;
	d->pos = 0;
	d->segment = s;
	d->frame = 0;
	d->length = 0;
	if (s >= codec_segments(c))
		return skp_fail(err, SKP_ERR_RANGE, 0, "compressed clip: segment %lu of %lu", (unsigned long)s,
				(unsigned long)codec_segments(c));
	d->length = s + 1 < codec_segments(c) ? c->segment_frames : c->frames - s * c->segment_frames;
	for (int i = 0; i < c->tracks; i++) {
		codec_track_state *t = &d->t[i];
		t->q1 = t->q2 = 0;
		t->order = t->k = 0;
		if (!c->track[i].bits)
			continue;
		t->order = (uint8_t)take(d, 2);
		t->k = (uint8_t)(t->order ? take(d, 5) : 0);
		if (t->k > CODEC_MAX_K || overrun(d))
			return bad(d, err, "track header out of range");
	}
	return SKP_OK;
}

/* Track i's q in the segment's current frame. */
static int track_q(codec_decoder *d, int i, int32_t *q)
{
	codec_track_state *t = &d->t[i];
	const int bits = d->clip->track[i].bits;
	uint32_t f = d->frame;
	if (t->order == 0 && f > 0) {
		*q = t->q1;
		return 0;
	}
	if (f < (t->order > 1 ? 2u : 1u)) {
		*q = (int32_t)take(d, bits);
		return overrun(d) ? -1 : 0;
	}
	int32_t r;
	if (rice(d, t->k, &r))
		return -1;
	int64_t q1 = t->q1, q2 = t->q2;
	int64_t pred = t->order == 1 ? q1 : t->order == 2 ? 2 * q1 - q2 : q1 + ((q1 - q2) >> 1);
	int64_t v = pred + r;
	if (v < 0 || v >= ((int64_t)1 << bits))
		return -1;
	*q = (int32_t)v;
	return 0;
}

int codec_next(codec_decoder *d, float *values, skp_error *err)
{
	const codec_clip *c = d->clip;
	if (d->frame >= d->length)
		return 0;
	for (int i = 0; i < c->tracks; i++) {
		const codec_track *tr = &c->track[i];
		int32_t q = 0;
		if (tr->bits && track_q(d, i, &q))
			return -(int)bad(d, err, "track data out of range or past the segment's end");
		d->t[i].q2 = d->t[i].q1;
		d->t[i].q1 = q;
		values[i] = codec_value(tr, q);
	}
	d->frame++;
	return 1;
}
