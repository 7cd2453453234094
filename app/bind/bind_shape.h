/* Whether a mesh without a rig is shaped like a standing biped, before a
 * human skeleton is bound to it (Y up, as bind_fit.h assumes):
 *   - it stands on two feet: the vertices in the lowest 8% of its height
 *     span at most 70% of its height one way (feet apart: the CMU
 *     skeleton's generated body stands 55% wide) and 35% the other (a
 *     foot's length); a quadruped's paws span its body's length, a box or
 *     a figure lying down is all footprint;
 *   - it has some width: its wider side at least 12% of its height (a
 *     pole, a sword, a lamp post has none).
 * A figure in a long robe may fail the first; --force binds it anyway. */
#ifndef BIND_SHAPE_H
#define BIND_SHAPE_H

#include "vec3.h"

typedef struct bind_shape {
	float height;           /* Y extent */
	float width, depth;     /* the wider and the narrower horizontal extent */
	float foot_x, foot_z;   /* the footprint's extents */
	int biped;
} bind_shape;

#define BIND_SHAPE_FOOT 0.08f   /* the footprint: this share of the height from the bottom */
#define BIND_SHAPE_SPAN 0.7f    /* at most this share of the height one way */
#define BIND_SHAPE_FEET 0.35f   /* and this much the other */
#define BIND_SHAPE_WIDE 0.12f   /* the wider side at least this share of the height */

void bind_shape_measure(const vec3 *pos, int n, bind_shape *out);

#endif
