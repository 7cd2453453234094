/* The sampler: a window of two neighbouring captured frames over a
 * play_source, and the pose between them at any fractional frame index.
 * Moving forward reads frames in order (those the display skips are
 * decoded and dropped: a text stream has no other way, and it keeps the
 * memory fixed); going back, or far ahead on a source that seeks fast,
 * seeks. */
#ifndef PLAY_CURSOR_H
#define PLAY_CURSOR_H

#include "fk.h"
#include "play_source.h"

typedef struct play_cursor {
	const skel *s;
	play_source src;
	long next;               /* index the source's next() returns */
	long ia;                 /* index of frame a; -1: nothing read */
	int have_b;              /* frame ia + 1 is in b */
	long number_a, number_b; /* the frames' numbers (as in the file) */
	long last;               /* index of the last frame (the source's count,
	                          * lowered when the source ends early) */
	skel_local a, b;
	amc_frame frame;         /* read buffer */
} play_cursor;

/* Opens the cursor on src (frames >= 1, rate > 0) and reads frame 0.
 * SKP_OK, or the source's error. */
skp_status play_cursor_open(play_cursor *c, const skel *s, const play_source *src, skp_error *err);

/* The local pose at captured index x (clamped to [0, last]) into out;
 * *number: the number of the frame at or before x. SKP_OK, or the
 * source's error (out then holds the last pose the window had). */
skp_status play_cursor_sample(play_cursor *c, double x, skel_local *out, long *number, skp_error *err);

#endif
