/* Where the playback engine's captured frames come from: a small callback
 * interface (littlefs-style), so the same engine plays an AMC or BVH text
 * stream on the host, an image clip from flash on a device, or a table in a
 * test. Frames are indexed from 0; the engine asks for them in order and
 * seeks only to go back (a loop, a restart) or, where the source says it
 * seeks cheaply, to jump far ahead. */
#ifndef PLAY_SOURCE_H
#define PLAY_SOURCE_H

#include "amc.h"
#include "skp_error.h"

typedef struct play_source {
	void *ctx;
	/* The next frame into *f: 1, 0 after the last, or a negative
	 * skp_status with err filled. */
	int (*next)(void *ctx, amc_frame *f, skp_error *err);
	/* Makes frame index the next one read (0: the first). SKP_OK or an
	 * error. A source that cannot seek rewinds and reads forward. */
	skp_status (*seek)(void *ctx, long index, skp_error *err);
	long frames;          /* captured frames, >= 1 */
	double rate;          /* captured frames a second, > 0 */
	int seeks_fast;       /* 1: seek costs no more than a read (an image: by block) */
} play_source;

#endif
