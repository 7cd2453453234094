/* The skin layer's geometry: an indexed triangle mesh in fixed arrays, in
 * the skeleton's space and units. */
#ifndef MESH_H
#define MESH_H

#include <stdint.h>

#include "board_limits.h"
#include "vec3.h"

/* The skin colour a body, or a vertex, without a base colour of its own
 * is drawn in (0..1 a channel, as colour's bytes over 255): the
 * renderer's, and the importer's for vertices beside coloured ones. */
#define MESH_SKIN_RGB { 0.86f, 0.67f, 0.56f }

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
	/* 1: the body has a base colour texture (app/texture/tex_image.h), its
	 * colour multiplied into colour's at the vertices whose sampled is 1,
	 * at uv (GL's: (0, 0) the texture's bottom left, repeating); the other
	 * vertices keep their colour alone (a second texture is baked into
	 * it); 0: no texture */
	int textured;
	float uv[SKP_MAX_VERTS][2];
	uint8_t sampled[SKP_MAX_VERTS];
} mesh;

#endif
