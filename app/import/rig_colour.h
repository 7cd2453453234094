/* A rigged mesh's colours as its file has them: each vertex's base colour
 * from its material's base (or diffuse) colour, times its vertex colour,
 * stored sRGB per vertex (mesh.colour), times its base colour texture (PNG
 * or JPEG, told by its bytes, embedded in the file or beside it; JPEG through
 * rig_jpeg.h) at the vertex's first UV.
 *   - One texture goes to the GPU, the one the most vertices use
 *     (rig_colour_tally, rig_colour_choose), when the board keeps textures
 *     (SKP_MAX_TEXTURE_SIDE): its vertices get their UV and sampled set, and
 *     its pixels are kept (gpu_rgba) for the image (rig_texture.h), drawn
 *     per texel (CesiumMan's suit whole, not its colours at the vertices).
 *   - Any other is baked: sampled at the vertex into its colour, which
 *     keeps a palette texture (Soldier's) or flat materials (Paladin's 700)
 *     whole. */
#ifndef RIG_COLOUR_H
#define RIG_COLOUR_H

#include <stdint.h>

#include <assimp/scene.h>

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
	/* the textures the meshes use, by how many vertices (rig_colour_tally) */
	int tally_count;
	struct rig_colour_tally {
		char path[512];
		long verts;
	} tally[16];
	/* the one the GPU draws (rig_colour_choose; "" none), and once a mesh
	 * using it is read, its pixels: RGBA8, top row first, owned here */
	char gpu_path[512];
	char gpu_material[64];
	uint8_t *gpu_rgba;
	int gpu_w, gpu_h;
} rig_colour_work;

/* Counts am's vertices under its material's base colour texture, before
 * the meshes are read. */
void rig_colour_tally(rig_colour_work *w, const struct aiScene *sc, const struct aiMesh *am);

/* The texture with the most vertices becomes the GPU's, when the board
 * keeps one. */
void rig_colour_choose(rig_colour_work *w);

/* Writes the base colour of each of am's vertices to out, and its UV and
 * whether it samples the GPU's texture to uv and sampled (am->mNumVertices
 * rows each); returns 1 when the mesh's material, texture or vertex
 * colours say anything (0: the library's default material and nothing
 * else). A texture that cannot be read is noted in w (problems, problem)
 * and the material's colour used. */
int rig_colour_mesh(rig_colour_work *w, const struct aiScene *sc, const struct aiMesh *am, uint8_t (*out)[3],
		    float (*uv)[2], uint8_t *sampled);

/* Multiplies the RGBA8 texture (w x h, top row first) at each vertex's uv
 * (GL's, bottom left (0, 0), repeating) into the colour of the n vertices
 * whose sampled is 1, and clears sampled: the GPU's texture baked, when
 * it cannot go to the GPU after all. */
void rig_colour_bake(const uint8_t *rgba, int w, int h, const float (*uv)[2], uint8_t *sampled, uint8_t (*colour)[3],
		     int n);

/* For readers of other files (an OBJ's .mtl: rig_obj_colour.h). The
 * texture file (PNG or JPEG by its bytes, within rig_limits_texture_fits)
 * decoded into w's cache (kept while the next call names the same file);
 * 0 with *why (a phrase: "is missing", "is truncated or damaged", ...)
 * when it cannot be read. */
int rig_colour_file(rig_colour_work *w, const char *file, const char **why);

/* The cached texture at GL's (u, v) (bottom left (0, 0), repeating),
 * bilinear, linear RGB. */
void rig_colour_texel(const rig_colour_work *w, float u, float v, float rgb[3]);

/* A linear channel (clamped to 0..1) as sRGB. */
uint8_t rig_colour_srgb(float linear);

/* Frees the cached texture (the GPU's stays: the caller takes gpu_rgba). */
void rig_colour_done(rig_colour_work *w);

#endif
