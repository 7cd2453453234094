/* The skin layer's geometry: an indexed triangle mesh in fixed arrays, in
 * the skeleton's space and units. */
#ifndef MESH_H
#define MESH_H

#include <stdint.h>

#include "board_limits.h"
#include "vec3.h"

typedef struct mesh {
	int vert_count;
	int tri_count;
	vec3 pos[SKP_MAX_VERTS];
	vec3 normal[SKP_MAX_VERTS];    /* unit per-vertex normals */
	uint32_t tri[SKP_MAX_TRIS][3]; /* counter-clockwise seen from outside */
} mesh;

#endif
