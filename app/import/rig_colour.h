/* A rigged mesh's colours as its file has them: each vertex's base colour
 * from its material's base (or diffuse) colour, times its base colour
 * texture sampled at the vertex's first UV (PNG, embedded in the file or
 * beside it), times its vertex colour, stored sRGB per vertex
 * (mesh.colour). Per vertex, not per texel: a palette texture (Soldier's)
 * or flat materials (Paladin's 700) come out whole; a photographic one
 * (CesiumMan's suit) as its colours at the vertices. */
#ifndef RIG_COLOUR_H
#define RIG_COLOUR_H

#include <stdint.h>

#include <assimp/scene.h>

#define RIG_TEXTURE_MAX_SIDE 8192 /* a texture wider or taller is not read */

typedef struct rig_colour_work {
	const char *model_path;   /* external textures are found beside it */
	int textured;             /* meshes that had a texture sampled */
	int coloured;             /* meshes that carried any colour of their own */
	int problems;             /* textures that could not be read */
	char problem[320];        /* the first, a sentence naming texture and material */
	/* the last texture decoded, kept for the next mesh that uses it */
	char cached[512];
	uint8_t *rgba;
	int w, h;
} rig_colour_work;

/* Writes the base colour of each of am's vertices to out (am->mNumVertices
 * rows); returns 1 when the mesh's material, texture or vertex colours say
 * anything (0: the library's default material and nothing else). A
 * texture that cannot be read is noted in w (problems, problem) and the
 * material's colour used. */
int rig_colour_mesh(rig_colour_work *w, const struct aiScene *sc, const struct aiMesh *am, uint8_t (*out)[3]);

/* Frees the cached texture. */
void rig_colour_done(rig_colour_work *w);

#endif
