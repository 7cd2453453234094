/* An image clip (app/image/image_stream.h) as a play_source. A frame whose
 * block is lost beyond repair is not decoded: the last good frame is held
 * in its place (the rest pose when the clip starts in a bad block), and
 * the caller is told through on_lost, so a dying flash costs smoothness,
 * never the show. Seeks go by block (a compressed clip's by segment). */
#ifndef PLAY_IMAGE_SOURCE_H
#define PLAY_IMAGE_SOURCE_H

#include "image_stream.h"
#include "play_source.h"

typedef struct play_image_source {
	skp_clip_stream stream;
	amc_frame last;          /* the last good frame */
	int have_last;
	unsigned long lost_frames; /* frames held in place of a lost one, ever */
	unsigned long pass_lost;   /* ... since the clip was last at its start */
	/* Told of each frame held: the image block, why, the frame held. */
	void (*on_lost)(void *ctx, long block, const char *why, long held_number);
	/* Told when the clip goes back to its start (a loop or a restart). */
	void (*on_rewind)(void *ctx);
	void *ctx;
} play_image_source;

/* Opens clip of im (its quantisation read). The callbacks stay as set. */
skp_status play_image_source_open(play_image_source *s, skp_image *im, int clip, skp_error *err);

/* The source the engine reads (frames and rate from the clip's entry). */
play_source play_image_source_get(play_image_source *s);

#endif
