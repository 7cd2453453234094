/* A compressed clip made from integers alone, the same on every board
 * (the floats are exact or IEEE-rounded quotients of small integers, the
 * grid values a seeded random walk): what the cross-board decode checks
 * encode on the host and decode on each board (tests/unit/test_image_codec.c
 * under qemu-user for the Pi, tests/embedded/emb_skin.c on the Cortex-M4),
 * the decoded values' bits hashed by codec_synth_hash. */
#ifndef CODEC_SYNTH_H
#define CODEC_SYNTH_H

#include <stdint.h>

#include "codec_format.h"

#define CODEC_SYNTH_TRACKS 40
#define CODEC_SYNTH_FRAMES 600
#define CODEC_SYNTH_SEGMENT 128

/* The clip's tracks: every fifth constant, the others 16 bits wide over
 * ranges from 0.3 to 660 around bases from -180 to 103. */
static inline void codec_synth_clip(codec_clip *c)
{
	c->frames = CODEC_SYNTH_FRAMES;
	c->tracks = CODEC_SYNTH_TRACKS;
	c->segment_frames = CODEC_SYNTH_SEGMENT;
	for (int t = 0; t < CODEC_SYNTH_TRACKS; t++) {
		c->track[t].base = -180.0f + 7.25f * (float)t;
		c->track[t].step = (float)(1 + t * t) / (float)(97 + 13 * t) / 100.0f;
		c->track[t].bits = t % 5 == 4 ? 0 : 16;
	}
}

/* Grid values q[frame * tracks + track]: walks of -20..20 a frame, some
 * jumping, within 0..65535; 0 on constant tracks. */
static inline void codec_synth_q(int32_t *q)
{
	uint32_t r = 2463534242u;
	int32_t v[CODEC_SYNTH_TRACKS];
	for (int t = 0; t < CODEC_SYNTH_TRACKS; t++)
		v[t] = 20000 + 700 * t;
	for (int f = 0; f < CODEC_SYNTH_FRAMES; f++)
		for (int t = 0; t < CODEC_SYNTH_TRACKS; t++) {
			r ^= r << 13;
			r ^= r >> 17;
			r ^= r << 5;
			int32_t d = (int32_t)(r % 41u) - 20;
			if (t % 7 == 3 && r % 97u == 0)
				d *= 300; /* a jump: the Rice escape */
			v[t] += d;
			v[t] = v[t] < 0 ? 0 : v[t] > 65535 ? 65535 : v[t];
			q[f * CODEC_SYNTH_TRACKS + t] = t % 5 == 4 ? 0 : v[t];
		}
}

/* FNV-1a over the bits of n decoded values. */
static inline uint32_t codec_synth_hash(uint32_t h, const float *v, int n)
{
	for (int i = 0; i < n; i++) {
		union { float f; uint32_t u; } b = { v[i] };
		for (int k = 0; k < 4; k++)
			h = (h ^ ((b.u >> (8 * k)) & 0xffu)) * 16777619u;
	}
	return h;
}

#endif
