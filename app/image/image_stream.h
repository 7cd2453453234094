/* Plays one clip of a flash image frame by frame from a fixed ring of
 * SKP_IMAGE_RING_BLOCKS blocks prefetched ahead of the play head: memory
 * does not depend on the clip's length. Frames are decoded straight from
 * the ring into an amc_frame, so the pipeline after it is the one that
 * plays AMC text.
 *
 * A frame in a block that fails its check (CRC, I/O error, short read, a
 * block of another image) is not decoded: skp_clip_stream_next returns
 * SKP_CLIP_LOST with the block in err, and the caller keeps showing its
 * last good frame; playback goes on at the next good block.
 *
 * A block rebuilt from parity is kept (SKP_IMAGE_CACHE_BLOCKS of them, for
 * the clip): on the clip's next passes the block itself is read, as any
 * block is, and while it is still bad the kept copy serves, so a short
 * looping clip does not read its whole parity group again every pass (a
 * slow card at a second a read would starve the watchdog).
 *
 * A compressed clip (version 5, app/codec) is read a segment at a time:
 * its bytes gathered from the ring's blocks into seg_bytes (the blocks of
 * the next segment prefetched meanwhile, one a frame), then decoded a
 * frame at a time; a seek lands in a segment and decodes from its start.
 * A segment touching a block that cannot be read or rebuilt, or that the
 * decoder refuses, is lost (SKP_CLIP_LOST for each of its frames) and
 * playback goes on at the next segment. */
#ifndef IMAGE_STREAM_H
#define IMAGE_STREAM_H

#include "amc.h"
#include "image_read.h"

#define SKP_CLIP_LOST 2

typedef struct skp_clip_slot {
	uint32_t block;          /* frame block (0-based within the clip), UINT32_MAX empty */
	uint8_t state;           /* skp_block_state */
} skp_clip_slot;

typedef struct skp_clip_stream {
	skp_image *im;
	int clip;
	skp_image_clip c;
	uint32_t next;           /* index of the next frame */
	uint32_t fetch;          /* next frame block to prefetch */
	float qmin[SKP_MAX_DOF], qstep[SKP_MAX_DOF];
	skp_clip_slot slot[SKP_IMAGE_RING_BLOCKS];
	uint8_t ring[SKP_IMAGE_RING_BLOCKS][SKP_IMAGE_BLOCK_SIZE];
	uint32_t kept[SKP_IMAGE_CACHE_BLOCKS];  /* image blocks rebuilt, UINT32_MAX none */
	uint8_t keep[SKP_IMAGE_CACHE_BLOCKS][SKP_IMAGE_BLOCK_SIZE];
	int keep_next;           /* the slot the next rebuilt block takes */
	unsigned long kept_uses; /* reads of a bad block served from a kept copy */
	unsigned long reads;     /* blocks read, for the figures */
	/* a compressed clip */
	codec_clip cc;
	codec_decoder dec;
	uint32_t seg;            /* the segment in seg_bytes, UINT32_MAX none */
	uint32_t seg_last;       /* its last block (clip-relative) */
	uint8_t seg_state;       /* skp_block_state of its blocks */
	uint8_t seg_refused;     /* the decoder refused it */
	uint32_t seg_block;      /* the image block that failed */
	float value[SKP_MAX_DOF];/* the frame being decoded */
	uint8_t seg_bytes[SKP_CODEC_SEGMENT_BYTES];
} skp_clip_stream;

/* Opens clip (an index into im->clip) at its first frame; loads its
 * quantisation or its compressed header (a bad block there is an error:
 * the clip cannot play). */
skp_status skp_clip_stream_open(skp_clip_stream *p, skp_image *im, int clip, skp_error *err);

/* Moves the play head to frame index (0 = the clip's first frame); the
 * blocks in the ring stay (a short clip looping is read once). */
void skp_clip_stream_seek(skp_clip_stream *p, uint32_t index);

/* Returns 1 with the next frame in *f (number = first number + index,
 * values in the clip's dof order), 0 after the last frame, or
 * SKP_CLIP_LOST when the frame's block is bad: *f is untouched,
 * err->block is the image block and err->msg why; the head still advances. */
int skp_clip_stream_next(skp_clip_stream *p, amc_frame *f, skp_error *err);

#endif
