/* Skin weights: for each mesh vertex up to SKP_MAX_INFLUENCES (bone, weight)
 * pairs summing to 1. A plain array-of-structs layout for the tools; the
 * runtime may re-lay it out for SIMD. */
#ifndef SKIN_WEIGHTS_H
#define SKIN_WEIGHTS_H

#include <stdint.h>

#include "board_limits.h"

typedef struct skin_weights {
	int vert_count;
	uint8_t count[SKP_MAX_VERTS];                     /* influences used, 1..4 */
	uint16_t bone[SKP_MAX_VERTS][SKP_MAX_INFLUENCES]; /* skeleton bone index */
	float weight[SKP_MAX_VERTS][SKP_MAX_INFLUENCES];  /* largest first when bound */
} skin_weights;

/* What a set of weights looks like, for `skintool bind --report`. */
typedef struct skin_weights_stats {
	int bone_verts[SKP_MAX_BONES]; /* vertices each bone influences (weight > 0) */
	int max_influences;            /* most influences on one vertex */
	long edge_count;               /* triangle edges measured (shared ones twice) */
	/* Mean over triangle edges (a,b) of 0.5 * sum_bones |w_a - w_b|: 0 when
	 * both ends move alike, 1 when they share no bone. */
	double edge_diff_mean;
} skin_weights_stats;

/* Index of the bone with the largest weight on vertex v. */
int skin_weights_dominant(const skin_weights *w, int v);

/* Weight of bone b on vertex v (0 when b does not influence it). */
float skin_weights_of(const skin_weights *w, int v, int b);

/* Sets vertex v's influences to the SKP_MAX_INFLUENCES largest positive
 * weights among count candidates (bone[i], weight[i]), largest first (on
 * equal weights the earlier candidate first), normalised to sum 1.
 * Returns their sum before normalising; 0 (no positive weight) leaves v
 * untouched. */
float skin_weights_set_largest(skin_weights *w, int v, const uint16_t *bone, const float *weight,
			       int count);

/* tri may be NULL (tri_count 0): then the edge figures stay 0. */
void skin_weights_stats_compute(const skin_weights *w, int bone_count,
				const uint32_t (*tri)[3], int tri_count,
				skin_weights_stats *out);

#endif
