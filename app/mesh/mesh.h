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
	/* 1: colour holds each vertex's base colour (sRGB, from the file's
	 * materials); 0: drawn in the renderer's skin colour */
	int coloured;
	uint8_t colour[SKP_MAX_VERTS][3];
} mesh;

#endif
