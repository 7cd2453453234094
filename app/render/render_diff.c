/* The difference view: the body coloured by how far each vertex of LBS
 * lies from DQBS, or by how far the skin has moved towards or away from
 * its bone since the bind pose, in millimetres at the body's real size,
 * with its legend across the top. */
#include <math.h>
#include <string.h>

#include "render_font.h"
#include "render_internal.h"
#include "skp_format.h"

#define DIFF_FULL_MM 40.0f     /* LBS from DQBS: the top of the scale */
#define DIFF_SIGNED_MM 30.0f   /* nearer or further from the bone: either end */
#define DIFF_STOPS 5
#define DIFF_BAR_STEPS 24

/* A sequential scale for a distance (dark blue for none, through cyan,
 * green and yellow to red), a diverging one for a signed change (blue
 * thinner, grey as bound, red thicker). t in 0..1. */
static vec3 ramp(float t, int is_signed)
{
	static const float seq[DIFF_STOPS][3] = {
		{ 0.20f, 0.26f, 0.55f }, { 0.15f, 0.62f, 0.85f }, { 0.35f, 0.82f, 0.35f },
		{ 0.98f, 0.84f, 0.18f }, { 0.90f, 0.18f, 0.12f },
	};
	static const float div[DIFF_STOPS][3] = {
		{ 0.15f, 0.30f, 0.90f }, { 0.45f, 0.62f, 0.92f }, { 0.72f, 0.72f, 0.72f },
		{ 0.95f, 0.60f, 0.45f }, { 0.92f, 0.18f, 0.12f },
	};
	const float (*c)[3] = is_signed ? div : seq;
	float x = fmaxf(0.0f, fminf(1.0f, t)) * (DIFF_STOPS - 1);
	int i = x >= DIFF_STOPS - 1 ? DIFF_STOPS - 2 : (int)x;
	float f = x - (float)i;
	return vec3_make(c[i][0] + (c[i + 1][0] - c[i][0]) * f, c[i][1] + (c[i + 1][1] - c[i][1]) * f,
			 c[i][2] + (c[i + 1][2] - c[i][2]) * f);
}

/* The scale in DIFF_LEVELS steps, made once: a vertex then costs a
 * multiply, a clamp and a 4-byte copy. */
#define DIFF_LEVELS 256

static const uint8_t *scale_table(int is_signed)
{
	static uint8_t table[2][DIFF_LEVELS][4];
	static int made;
	if (!made) {
		for (int k = 0; k < 2; k++)
			for (int i = 0; i < DIFF_LEVELS; i++) {
				vec3 c = ramp((float)i / (DIFF_LEVELS - 1), k);
				uint8_t *o = table[k][i];
				o[0] = (uint8_t)(c.x * 255.0f + 0.5f);
				o[1] = (uint8_t)(c.y * 255.0f + 0.5f);
				o[2] = (uint8_t)(c.z * 255.0f + 0.5f);
				o[3] = 255;
			}
		made = 1;
	}
	return table[is_signed ? 1 : 0][0];
}

void render_diff_colours(const float *diff, int n, float mm_per_unit, int is_signed, uint8_t *rgba)
{
	const uint8_t *table = scale_table(is_signed);
	/* to_ramp's line, in table steps: t = k * mm + c */
	float k = (DIFF_LEVELS - 1) * mm_per_unit * (is_signed ? 0.5f / DIFF_SIGNED_MM : 1.0f / DIFF_FULL_MM);
	float c = is_signed ? 0.5f * (DIFF_LEVELS - 1) : 0.0f;
	for (int v = 0; v < n; v++) {
		float t = diff[v] * k + c + 0.5f;
		/* NaN fails both tests: the middle of the scale (none, or as bound) */
		int i = t >= 0.0f ? (t < DIFF_LEVELS - 1 ? (int)t : DIFF_LEVELS - 1) : 0;
		if (!(t == t))
			i = (int)c;
		memcpy(rgba + 4 * v, table + 4 * i, 4);
	}
}

void render_diff_upload(renderer *r, const float *diff, int is_signed)
{
	const gl_api *gl = r->gl;
	render_diff_colours(diff, r->vert_count, r->mm_per_unit, is_signed, r->diff_rgba);
	gl->BindBuffer(GL_ARRAY_BUFFER, r->vbo_diff);
	gl->BufferSubData(GL_ARRAY_BUFFER, 0, (GLsizeiptr)r->vert_count * 4, r->diff_rgba);
	r->diff_ready = 1;
}

static const char *legend_title(const renderer *r, int is_signed)
{
	if (is_signed)
		return r->size_assumed ? "SKIN NEARER (-) OR FURTHER (+) FROM ITS BONE THAN BOUND, MM (BODY TAKEN AS 1.75 M):"
				       : "SKIN NEARER (-) OR FURTHER (+) FROM ITS BONE THAN BOUND, MM:";
	return r->size_assumed ? "HOW FAR LBS LIES FROM DQBS, MM (BODY TAKEN AS 1.75 M):" : "HOW FAR LBS LIES FROM DQBS, MM:";
}

/* A run of flat quads across [x0, x1) on row y (logical pixels from the
 * top of full), each its colour of the scale. */
static void draw_bar(renderer *r, render_rect full, int x0, int x1, int y, int h, int is_signed)
{
	const gl_api *gl = r->gl;
	mat4 px = mat4_ortho(0, (float)full.w, 0, (float)full.h, -1, 1);
	mat4 m = mat4_mul(&r->screen, &px);
	float y0 = (float)(full.h - y - h), y1 = (float)(full.h - y); /* GL's rows, counter-clockwise */
	gl->Disable(GL_DEPTH_TEST);
	for (int i = 0; i < DIFF_BAR_STEPS; i++) {
		float a = (float)x0 + (float)(x1 - x0) * (float)i / DIFF_BAR_STEPS;
		float b = (float)x0 + (float)(x1 - x0) * (float)(i + 1) / DIFF_BAR_STEPS;
		float q[18] = { a, y0, 0, b, y0, 0, b, y1, 0, a, y0, 0, b, y1, 0, a, y1, 0 };
		vec3 c = ramp(((float)i + 0.5f) / DIFF_BAR_STEPS, is_signed);
		float rgba[4] = { c.x, c.y, c.z, 1.0f };
		render_flat(r, &m, rgba, GL_TRIANGLES, q, 6, 1.0f);
	}
	gl->Enable(GL_DEPTH_TEST);
}

/* The title on the first row, the scale on the second: its low end, the
 * bar, its high end. */
void render_diff_legend(renderer *r, render_rect full, int scale, int y0, int is_signed)
{
	static const float text_rgba[4] = { 0.95f, 0.95f, 0.85f, 1.0f };
	char lo[16], hi[16];
	int line = (FONT_CELL_H + 2) * scale, x = 4 * scale;
	render_text(r, full, x, y0, scale, legend_title(r, is_signed), text_rgba);
	if (is_signed) {
		skp_format(lo, sizeof lo, "-%d", (int)DIFF_SIGNED_MM);
		skp_format(hi, sizeof hi, "+%d MM", (int)DIFF_SIGNED_MM);
	} else {
		skp_format(lo, sizeof lo, "0");
		skp_format(hi, sizeof hi, "%d+ MM", (int)DIFF_FULL_MM);
	}
	int y = y0 + line, w = render_text(r, full, x, y, scale, lo, text_rgba);
	int bar0 = x + w + 2 * scale, bar1 = bar0 + full.w / 3;
	draw_bar(r, full, bar0, bar1, y - scale, FONT_CELL_H * scale, is_signed);
	render_text(r, full, bar1 + 2 * scale, y, scale, hi, text_rgba);
}
