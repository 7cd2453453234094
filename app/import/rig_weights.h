/* The artist's weights (`--weights mesh`) moved onto the skeleton: each
 * joint's weight goes to the bone it moves with (rig_map.h: its own, else
 * its nearest mapped ancestor's, else the root), weights landing on the
 * same bone add up, and each vertex keeps its 4 largest, normalised. */
#ifndef RIG_WEIGHTS_H
#define RIG_WEIGHTS_H

#include "rig_map.h"
#include "skin_weights.h"

typedef struct rig_weights_info {
	int trimmed;            /* vertices that had more than 4 bones */
	int unweighted;         /* vertices without any weight: given to the root */
} rig_weights_info;

/* orphan (may be NULL) gets 1 for each vertex whose weight all went to
 * the root for want of a mapped joint (or that had none), else 0. */
void rig_weights_to_skel(const rig_scene *r, const rig_map *m, skin_weights *out, rig_weights_info *info,
			 uint8_t *orphan);

#endif
