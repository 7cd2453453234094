/* Blending local poses (fk.h's skel_local): each bone's rotation slerped on
 * the shortest arc, translations and `l` channels linear. Between two
 * captured frames, and between two clips in a crossfade. */
#ifndef PLAY_BLEND_H
#define PLAY_BLEND_H

#include "fk.h"

/* out = a at w = 0, b at w = 1 (out may be a or b). */
void play_blend(const skel *s, const skel_local *a, const skel_local *b, float w, skel_local *out);

/* The crossfade's weight at fraction x of its length: 0 before, 1 after,
 * with zero slope at both ends, so a fade starts and ends without a kink
 * in the motion, and a nearly constant slope between, so the pose moves
 * from the old clip to the new as evenly as it can. */
float play_fade_weight(double x);

#endif
