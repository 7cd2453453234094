/* Which of a mesh's parts make up the body whose volume is measured. A
 * character is often several closed surfaces: a Mixamo robot's shells and
 * the balls at its joints, a head with eyes and teeth inside it. The
 * signed volume of them all counts the inner ones as flesh too, and how
 * much of them pokes out of the shells changes with the pose, so the
 * volume measures (measure.h) keep only the outer closed parts: a part
 * (triangles connected through shared vertices) counts when each of its
 * edges is met by two of its triangles, it encloses a volume, and its
 * vertices' centroid lies inside no larger counted part (winding number
 * over that part's triangles above one half). */
#ifndef PARTS_H
#define PARTS_H

#include <stdint.h>

#include "mesh.h"

typedef struct parts_summary {
	int parts;          /* connected parts */
	int counted;        /* the outer closed parts the volume is measured on */
	int inner;          /* closed parts inside a larger one: left out */
	int open;           /* parts with an edge met by one triangle: left out */
	int open_edges;     /* those edges, over all parts */
	int counted_tris;   /* triangles of the counted parts */
} parts_summary;

/* Writes the triangles of the counted parts to tri_out (room for
 * m->tri_count) and the counts to *out. Returns 0, or -1 out of memory. */
int parts_for_volume(const mesh *m, uint32_t (*tri_out)[3], parts_summary *out);

#endif
