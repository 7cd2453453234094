/* Shared between the renderer's files only. */
#ifndef RENDER_INTERNAL_H
#define RENDER_INTERNAL_H

#include "render.h"
#include "render_shaders.h"

/* the static vertex layout: pos3 nrm3 col3 bones4 weights4 */
#define STATIC_FLOATS 17
#define STATIC_STRIDE (STATIC_FLOATS * 4)

enum { U_MVP, U_BONE, U_KEY, U_FILL, U_SKIN, U_USE_COL, U_COLOR, U_POINT, U_STRENGTH, U_FONT, U_TEX, U_USE_TEX, U_COUNT };

/* uniform locations per program, looked up once at init */
extern GLint render_loc[SHADER_COUNT][U_COUNT];

/* A rectangle in logical pixels (before the screen rotation). */
typedef struct render_rect {
	int x, y, w, h;
} render_rect;

void render_logical_size(const renderer *r, int *w, int *h);
void render_set_viewport(const renderer *r, render_rect rect);

/* A distinct colour per bone (the weight view's and its legend's). */
vec3 render_bone_color(int bone);

void render_grid_and_shadow(renderer *r, const mat4 *vp, vec3 root);
void render_skeleton(renderer *r, const mat4 *vp, const skel_pose *pose);
void render_body(renderer *r, const mat4 *vp, const render_frame *f, int panel);
/* Streams floats through the scratch vertex buffer (r->vbo_misc). */
void render_stream(renderer *r, const float *data, int floats);
/* The flat program: one colour, mvp, point size. */
void render_use_flat(renderer *r, const mat4 *vp, const float rgba[4], float point);
/* Vertices (xyz) drawn as mode in one colour, lines line_width wide. */
void render_flat(renderer *r, const mat4 *vp, const float rgba[4], GLenum mode, const float *xyz, int vertices,
		 float line_width);
/* Float attribute slot from the bound buffer; 16-bit snorm ones. */
void render_attrib(const gl_api *gl, GLuint slot, int size, int stride, size_t offset);
void render_attrib_snorm16(const gl_api *gl, GLuint slot, int size, size_t offset);
void render_disable_attribs(const gl_api *gl);
/* The width of s in logical pixels at scale. */
int render_text_width(const char *s, int scale);
/* Text at logical pixel (x, y) from the top-left, in glyph pixels of
 * `scale` screen pixels; returns the width drawn. */
int render_text(renderer *r, render_rect area, int x, int y, int scale, const char *s,
		const float rgba[4]);

/* The difference view (render_diff.c): colours from f->diff into
 * vbo_diff; the legend (RENDER_DIFF_LEGEND_ROWS rows) from row y0 of full. */
void render_diff_upload(renderer *r, const float *diff, int is_signed);
#define RENDER_DIFF_LEGEND_ROWS 2
void render_diff_legend(renderer *r, render_rect full, int scale, int y0, int is_signed);

/* The close-up (render_inset.c): splits panel area into the body's part
 * and the inset's (0: no inset this frame, body = area); draws the inset
 * and its texts (text scale at most scale); rings the joint on the body. */
typedef struct render_bands {
	int foot, top, scale;    /* logical pixels kept for text under and over the body */
} render_bands;
/* 1 when f asks for a close-up this renderer can show (a compare view,
 * a titled joint of the skeleton). */
int render_closeup_on(const renderer *r, const render_frame *f);
int render_inset_split(const renderer *r, const render_frame *f, int n, render_rect area, const render_bands *b,
		       render_rect *body, render_rect *inset);
void render_inset_draw(renderer *r, const render_frame *f, int panel, render_rect area, render_rect inset,
		       const render_bands *b);
void render_inset_ring(renderer *r, const mat4 *vp);
/* The body lit as seen from azimuth (the lights turn with the camera). */
void render_body_seen(renderer *r, const mat4 *vp, const render_frame *f, int panel, float azimuth);

/* Frees the body's texture and its buffers (render_texture.c). */
void render_texture_shutdown(renderer *r);

#endif
