/* A video wall: screens side by side (and in rows), each drawing its tile
 * of one picture the size of the whole wall. The camera frames the body
 * for the wall's shape; a tile's projection is the wall's, scaled by the
 * wall's size in screens and moved so that the tile fills the screen. The
 * bezels are the picture behind the screens' frames: a figure crossing
 * from one screen to the next is where it would be seen through a window
 * frame, not squeezed together. Also the device's own camera. */
#include "render.h"

void render_set_view(renderer *r, const render_view_cam *v)
{
	r->cam.pitch = v->pitch;
	r->cam.distance = v->distance;
	r->cam.aim = v->aim;
}

void render_set_wall(renderer *r, const render_wall *w)
{
	r->wall = *w;
}

void render_wall_span(const render_wall *w, int width, int height, float *sx, float *sy)
{
	*sx = (float)(w->columns * width + (w->columns - 1) * w->bezel) / (float)width;
	*sy = (float)(w->rows * height + (w->rows - 1) * w->bezel) / (float)height;
}

/* In normalised device coordinates the wall spans -1..1; tile c spans the
 * part [c (w + bezel), c (w + bezel) + w] of its width in pixels (rows
 * likewise, from the top). x' = sx x + sx - 1 - 2 c (w + bezel) / w maps it
 * onto -1..1. */
mat4 render_wall_tile(const render_wall *w, int width, int height)
{
	float sx, sy;
	render_wall_span(w, width, height, &sx, &sy);
	mat4 t = mat4_identity();
	t.m[0] = sx;
	t.m[5] = sy;
	t.m[12] = sx - 1.0f - 2.0f * (float)w->column * (float)(width + w->bezel) / (float)width;
	t.m[13] = 1.0f - sy + 2.0f * (float)w->row * (float)(height + w->bezel) / (float)height;
	return t;
}
