/* Per-vertex normals of an indexed triangle mesh. */
#ifndef MESH_NORMALS_H
#define MESH_NORMALS_H

#include "mesh.h"

/* Area-weighted vertex normals: the normalised sum of the (un-normalised)
 * cross products of the triangles around each vertex, so large faces count
 * more and slivers hardly at all. A vertex in no triangle of non-zero area
 * (or whose sum overflows) gets +Y, so every normal stays a unit vector. */
void mesh_compute_normals(mesh *m);

/* The unit vector along n without underflow or overflow on the way (tiny
 * cross products, huge file normals); the zero vector for a zero or
 * non-finite n. */
vec3 mesh_unit(vec3 n);

#endif
