/* Computed weights made to vary smoothly over the surface: the paper's
 * rule picks each vertex's bones alone, so two neighbours can fall to
 * unrelated bones (a finger's vertex to the thigh beside it in an A-pose,
 * the crotch's to either leg) and the edge between them tears when those
 * bones part. Each pass moves every vertex's weights halfway to its
 * neighbours' mean (along the mesh's edges: never across a gap between
 * fingers or legs), keeping a vertex's BIND_SMOOTH_KEEP largest; at the
 * end the 4 largest are kept and normalised. */
#ifndef BIND_SMOOTH_H
#define BIND_SMOOTH_H

#include <stdint.h>

#include "board_limits.h"
#include "mesh.h"
#include "skin_weights.h"

#define BIND_SMOOTH_KEEP 8       /* influences a vertex carries between passes */
/* How far the weights spread, as a share of the mesh's largest extent: n
 * passes spread them about sqrt(n / 2) edges, so a mesh gets as many as
 * reach this far by its mean edge (MakeHuman's body, edges 0.6% of its
 * height: 16 passes; its longest edge stretch on CMU's walk 6.4% of its
 * height before, 1.2% after, app/bind/README.md), at least 1, at most
 * BIND_SMOOTH_MAX_PASSES. */
#define BIND_SMOOTH_REACH 0.017f
#define BIND_SMOOTH_MAX_PASSES 32

typedef struct bind_smooth_work {
	uint32_t start[SKP_MAX_VERTS + 1];     /* each vertex's neighbours in next[] */
	uint32_t fill[SKP_MAX_VERTS];
	uint32_t next[6 * SKP_MAX_TRIS];       /* both ends of every triangle edge */
	uint8_t bone[2][SKP_MAX_VERTS][BIND_SMOOTH_KEEP];
	float weight[2][SKP_MAX_VERTS][BIND_SMOOTH_KEEP];
	float acc[SKP_MAX_BONES];              /* one vertex's sum per bone */
	uint8_t touched[SKP_MAX_BONES];
} bind_smooth_work;

/* The passes a mesh gets (BIND_SMOOTH_REACH). */
int bind_smooth_passes(const mesh *m);

/* Smooths w (computed for m's vertices) over m's edges; returns the
 * passes made. */
int bind_smooth(bind_smooth_work *work, const mesh *m, skin_weights *w);

#endif
