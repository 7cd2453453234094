/* Shared between the renderer's files only. */
#ifndef RENDER_INTERNAL_H
#define RENDER_INTERNAL_H

#include "render.h"
#include "render_shaders.h"

/* the static vertex layout: pos3 nrm3 col3 bones4 weights4 */
#define STATIC_FLOATS 17
#define STATIC_STRIDE (STATIC_FLOATS * 4)

enum { U_MVP, U_BONE, U_KEY, U_FILL, U_SKIN, U_USE_COL, U_COLOR, U_POINT, U_STRENGTH, U_FONT, U_COUNT };

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
/* Text at logical pixel (x, y) from the top-left, in glyph pixels of
 * `scale` screen pixels; returns the width drawn. */
int render_text(renderer *r, render_rect area, int x, int y, int scale, const char *s,
		const float rgba[4]);

#endif
