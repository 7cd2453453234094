/* Per-vertex normals of an indexed triangle mesh. */
#ifndef MESH_NORMALS_H
#define MESH_NORMALS_H

#include "mesh.h"

/* Area-weighted vertex normals: the normalised sum of the (un-normalised)
 * cross products of the triangles around each vertex, so large faces count
 * more and slivers hardly at all. A vertex in no triangle of non-zero area
 * gets +Y, so every normal stays a unit vector. */
void mesh_compute_normals(mesh *m);

#endif
