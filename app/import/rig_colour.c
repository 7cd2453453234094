#include "rig_colour.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "board_limits.h"
#include "rig_jpeg.h"
#include "rig_limits.h"

#include <assimp/material.h>
#include <assimp/texture.h>
#include <png.h>

/* glTF's colour factors and vertex colours are linear, its textures and
 * the stored colours sRGB. */
static float to_linear(float s)
{
	return s <= 0.04045f ? s / 12.92f : powf((s + 0.055f) / 1.055f, 2.4f);
}

static uint8_t to_srgb(float l)
{
	l = l > 0.0f ? (l < 1.0f ? l : 1.0f) : 0.0f;   /* NaN from a broken file: black */
	float s = l <= 0.0031308f ? 12.92f * l : 1.055f * powf(l, 1.0f / 2.4f) - 0.055f;
	return (uint8_t)lrintf(255.0f * s);
}

static void note(rig_colour_work *w, const char *material, const char *texture, const char *why)
{
	if (!w->problems++)
		snprintf(w->problem, sizeof w->problem, "material '%.50s': texture '%.80s' %.80s: drawn in the material's colour", material,
			 texture, why);
}

static void drop_cache(rig_colour_work *w)
{
	free(w->rgba);
	w->rgba = NULL;
	w->cached[0] = '\0';
}

/* A PNG begun (its header read into img) decoded to RGBA8 in the cache;
 * why says what went wrong. */
static int finish_png(rig_colour_work *w, png_image *img, const char **why)
{
	if (!rig_limits_texture_fits(img->width, img->height, why)) {
		png_image_free(img);
		return 0;
	}
	img->format = PNG_FORMAT_RGBA;
	w->rgba = malloc(PNG_IMAGE_SIZE(*img));
	if (!w->rgba || !png_image_finish_read(img, NULL, w->rgba, 0, NULL)) {
		png_image_free(img);
		drop_cache(w);
		*why = "is truncated or damaged";
		return 0;
	}
	w->w = (int)img->width;
	w->h = (int)img->height;
	return 1;
}

/* What a texture that is neither says: the decoders are picked by the
 * bytes, whatever the name or the file's format hint says. */
#define NOT_READ "is neither PNG nor JPEG (PNG and JPEG textures are read)"

static int png_from_memory(rig_colour_work *w, const void *bytes, size_t n, const char **why)
{
	png_image img;
	memset(&img, 0, sizeof img);
	img.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_memory(&img, bytes, n)) {
		*why = "is not a PNG it can read";
		return 0;
	}
	return finish_png(w, &img, why);
}

static int png_from_stream(rig_colour_work *w, FILE *f, const char **why)
{
	png_image img;
	memset(&img, 0, sizeof img);
	img.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_stdio(&img, f)) {
		*why = "is not a PNG it can read";
		return 0;
	}
	return finish_png(w, &img, why);
}

/* A JPEG from the bytes, or (bytes NULL) from the file f, in the cache. */
static int jpeg_read(rig_colour_work *w, const void *bytes, size_t n, FILE *f, const char **why)
{
	rig_jpeg_pixels px;
	if (!rig_jpeg_read(bytes, n, f, &px, why))
		return 0;
	w->rgba = px.rgba;
	w->w = px.w;
	w->h = px.h;
	return 1;
}

static int is_png(const void *bytes, size_t n)
{
	return n >= 8 && !png_sig_cmp((png_const_bytep)bytes, 0, 8);
}

/* An embedded texture's bytes (a glb's image, a data URI) in the cache. */
static int decode_memory(rig_colour_work *w, const void *bytes, size_t n, const char **why)
{
	if (is_png(bytes, n))
		return png_from_memory(w, bytes, n, why);
	if (rig_jpeg_is(bytes, n))
		return jpeg_read(w, bytes, n, NULL, why);
	*why = NOT_READ;
	return 0;
}

/* A texture file's first bytes, then the file from its start through the
 * decoder they name. */
static int decode_stream(rig_colour_work *w, FILE *f, const char **why)
{
	uint8_t magic[8];
	size_t n = fread(magic, 1, sizeof magic, f);
	if (fseek(f, 0, SEEK_SET) != 0) {
		*why = "cannot be read";
		return 0;
	}
	if (is_png(magic, n))
		return png_from_stream(w, f, why);
	if (rig_jpeg_is(magic, n))
		return jpeg_read(w, NULL, 0, f, why);
	*why = NOT_READ;
	return 0;
}

/* 1: key's texture is the cached one; 0: the cache emptied for it; -1:
 * key is too long to be cached (*why says so). */
static int cache_lookup(rig_colour_work *w, const char *key, const char **why)
{
	if (w->rgba && !strcmp(w->cached, key))
		return 1;
	drop_cache(w);
	if (strlen(key) >= sizeof w->cached) {
		*why = "has too long a path";
		return -1;
	}
	return 0;
}

static void cache_keep(rig_colour_work *w, const char *key)
{
	memcpy(w->cached, key, strlen(key) + 1);
}

static int decode_file(rig_colour_work *w, const char *file, const char **why)
{
	FILE *f = fopen(file, "rb");
	if (!f) {
		*why = access(file, F_OK) == 0 ? "cannot be read" : "is missing";
		return 0;
	}
	int ok = decode_stream(w, f, why);
	fclose(f);
	return ok;
}

/* The texture named path (embedded "*N", or a file beside the model) in
 * the cache; 0, noted, when it cannot be read. */
static int load_texture(rig_colour_work *w, const struct aiScene *sc, const char *path, const char *material)
{
	const char *why = NULL;
	int ok = 0, hit = cache_lookup(w, path, &why);
	if (hit < 0)
		note(w, material, path, why);
	if (hit)
		return hit > 0;
	if (path[0] == '*') {
		unsigned i = (unsigned)strtoul(path + 1, NULL, 10);
		const struct aiTexture *t = i < sc->mNumTextures ? sc->mTextures[i] : NULL;
		if (!t)
			why = "is not in the file";
		else if (t->mHeight)
			why = NOT_READ;   /* texels the library decoded itself (mHeight rows) */
		else
			ok = decode_memory(w, t->pcData, t->mWidth, &why);
	} else {
		char file[1024];
		const char *slash = strrchr(w->model_path, '/');
		int dir = slash ? (int)(slash - w->model_path + 1) : 0;
		if ((size_t)snprintf(file, sizeof file, "%.*s%s", dir, w->model_path, path) >= sizeof file)
			why = "has too long a path";
		else
			ok = decode_file(w, file, &why);
	}
	if (!ok) {
		note(w, material, path, why);
		return 0;
	}
	cache_keep(w, path);
	return 1;
}

/* An RGBA8 texture (top row first) at (u, v), v down from the top,
 * bilinear, repeating; linear RGB. */
static void sample(const uint8_t *rgba, int w, int h, float u, float v, float rgb[3])
{
	float x = (u - floorf(u)) * (float)w - 0.5f, y = (v - floorf(v)) * (float)h - 0.5f;
	int x0 = (int)floorf(x), y0 = (int)floorf(y);
	float fx = x - (float)x0, fy = y - (float)y0;
	for (int c = 0; c < 3; c++)
		rgb[c] = 0.0f;
	for (int k = 0; k < 4; k++) {
		int xi = ((x0 + (k & 1)) % w + w) % w, yi = ((y0 + (k >> 1)) % h + h) % h;
		float f = ((k & 1) ? fx : 1.0f - fx) * ((k >> 1) ? fy : 1.0f - fy);
		const uint8_t *p = rgba + 4 * ((size_t)yi * (size_t)w + (size_t)xi);
		for (int c = 0; c < 3; c++)
			rgb[c] += f * to_linear((float)p[c] / 255.0f);
	}
}

/* The material's base colour (glTF's) or diffuse colour, linear; 0 when
 * it has neither. */
static int material_colour(const struct aiMaterial *mat, float rgb[3])
{
	struct aiColor4D c;
	if (aiGetMaterialColor(mat, AI_MATKEY_BASE_COLOR, &c) != aiReturn_SUCCESS &&
	    aiGetMaterialColor(mat, AI_MATKEY_COLOR_DIFFUSE, &c) != aiReturn_SUCCESS) {
		rgb[0] = rgb[1] = rgb[2] = 1.0f;
		return 0;
	}
	rgb[0] = c.r;
	rgb[1] = c.g;
	rgb[2] = c.b;
	return 1;
}

static int texture_path(const struct aiMaterial *mat, struct aiString *path)
{
	return aiGetMaterialTexture(mat, aiTextureType_BASE_COLOR, 0, path, NULL, NULL, NULL, NULL, NULL, NULL) ==
		       aiReturn_SUCCESS ||
	       aiGetMaterialTexture(mat, aiTextureType_DIFFUSE, 0, path, NULL, NULL, NULL, NULL, NULL, NULL) ==
		       aiReturn_SUCCESS;
}

void rig_colour_tally(rig_colour_work *w, const struct aiScene *sc, const struct aiMesh *am)
{
	const struct aiMaterial *mat = am->mMaterialIndex < sc->mNumMaterials ? sc->mMaterials[am->mMaterialIndex] : NULL;
	struct aiString path = { 0 };
	if (!mat || !am->mTextureCoords[0] || !texture_path(mat, &path) || path.length >= sizeof w->tally[0].path)
		return;
	int k = 0;
	while (k < w->tally_count && strcmp(w->tally[k].path, path.data))
		k++;
	if (k == w->tally_count) {
		if (k == (int)(sizeof w->tally / sizeof w->tally[0]))
			return; /* a rig of many textures: the first 16 are candidates enough */
		memcpy(w->tally[k].path, path.data, path.length + 1);
		w->tally[k].verts = 0;
		w->tally_count++;
	}
	w->tally[k].verts += am->mNumVertices;
}

void rig_colour_choose(rig_colour_work *w)
{
	w->gpu_path[0] = '\0';
	if (SKP_MAX_TEXTURE_SIDE <= 0)
		return; /* the board draws vertex colours alone: every texture baked */
	long most = 0;
	for (int k = 0; k < w->tally_count; k++)
		if (w->tally[k].verts > most) {
			most = w->tally[k].verts;
			memcpy(w->gpu_path, w->tally[k].path, sizeof w->gpu_path);
		}
}

/* The cached texture becomes the GPU's, the first time a mesh uses it; 0
 * when there is no memory for the copy (the texture is baked then). */
static int keep_for_gpu(rig_colour_work *w, const char *material)
{
	if (w->gpu_rgba)
		return 1;
	size_t bytes = 4 * (size_t)w->w * (size_t)w->h;
	w->gpu_rgba = malloc(bytes);
	if (!w->gpu_rgba)
		return 0;
	memcpy(w->gpu_rgba, w->rgba, bytes);
	w->gpu_w = w->w;
	w->gpu_h = w->h;
	snprintf(w->gpu_material, sizeof w->gpu_material, "%.63s", material);
	return 1;
}

int rig_colour_mesh(rig_colour_work *w, const struct aiScene *sc, const struct aiMesh *am, uint8_t (*out)[3],
		    float (*uv)[2], uint8_t *sampled)
{
	const struct aiMaterial *mat = am->mMaterialIndex < sc->mNumMaterials ? sc->mMaterials[am->mMaterialIndex] : NULL;
	struct aiString name = { 0 }, path = { 0 };
	float base[3] = { 1.0f, 1.0f, 1.0f };
	int own = 0, textured = 0, gpu = 0;
	if (mat) {
		aiGetMaterialString(mat, AI_MATKEY_NAME, &name);
		/* the library's stand-in for a mesh without a material is unnamed
		 * (glTF) or DefaultMaterial */
		own = material_colour(mat, base) && name.length && strcmp(name.data, AI_DEFAULT_MATERIAL_NAME) != 0;
		if (texture_path(mat, &path) && am->mTextureCoords[0])
			textured = load_texture(w, sc, path.data, name.data);
		gpu = textured && w->gpu_path[0] && !strcmp(path.data, w->gpu_path) && keep_for_gpu(w, name.data);
	}
	const struct aiColor4D *vc = am->mColors[0];
	const struct aiVector3D *tc = am->mTextureCoords[0];
	for (unsigned v = 0; v < am->mNumVertices; v++) {
		float rgb[3] = { base[0], base[1], base[2] }, t[3];
		/* the library turns glTF's top-left UV origin to OpenGL's bottom-left */
		uv[v][0] = gpu ? tc[v].x : 0.0f;
		uv[v][1] = gpu ? tc[v].y : 0.0f;
		sampled[v] = (uint8_t)gpu;
		if (textured && !gpu) {
			sample(w->rgba, w->w, w->h, tc[v].x, 1.0f - tc[v].y, t);
			for (int c = 0; c < 3; c++)
				rgb[c] *= t[c];
		}
		if (vc) {
			rgb[0] *= vc[v].r;
			rgb[1] *= vc[v].g;
			rgb[2] *= vc[v].b;
		}
		for (int c = 0; c < 3; c++)
			out[v][c] = to_srgb(rgb[c]);
	}
	w->textured += textured;
	own = own || textured || vc;
	w->coloured += own;
	return own;
}

void rig_colour_bake(const uint8_t *rgba, int w, int h, const float (*uv)[2], uint8_t *sampled, uint8_t (*colour)[3],
		     int n)
{
	for (int v = 0; v < n; v++) {
		if (!sampled[v])
			continue;
		float t[3];
		sample(rgba, w, h, uv[v][0], 1.0f - uv[v][1], t);
		for (int c = 0; c < 3; c++)
			colour[v][c] = to_srgb(to_linear((float)colour[v][c] / 255.0f) * t[c]);
		sampled[v] = 0;
	}
}

int rig_colour_file(rig_colour_work *w, const char *file, const char **why)
{
	int hit = cache_lookup(w, file, why);
	if (hit)
		return hit > 0;
	if (!decode_file(w, file, why))
		return 0;
	cache_keep(w, file);
	return 1;
}

void rig_colour_texel(const rig_colour_work *w, float u, float v, float rgb[3])
{
	sample(w->rgba, w->w, w->h, u, 1.0f - v, rgb);
}

uint8_t rig_colour_srgb(float linear)
{
	return to_srgb(linear);
}

void rig_colour_done(rig_colour_work *w)
{
	drop_cache(w);
}
