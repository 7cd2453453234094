/* One segment of a compressed clip as codec_format.h lays it out: per
 * coded track the predictor and Rice parameter that make it shortest,
 * then the frames. */
#ifndef ENCODE_SEGMENT_H
#define ENCODE_SEGMENT_H

#include <stddef.h>
#include <stdint.h>

#include "codec_format.h"

/* A growing bit stream, least significant bit first. */
typedef struct enc_bits {
	uint8_t *buf;
	size_t len, cap;     /* bytes */
	uint64_t acc;
	int nacc;
	int failed;          /* out of memory */
} enc_bits;

/* Frames [first, first + len) of the grid values q (frame-major, dofs a
 * frame) of clip c, byte-aligned at the end. */
void enc_segment(const codec_clip *c, const int32_t *q, int dofs, long first, int len, enc_bits *out);

void enc_bits_free(enc_bits *b);

#endif
