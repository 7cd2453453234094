#include "report_chart.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli_inputs.h"
#include "png_writer.h"
#include "render_font.h"
#include "tool_state.h"

static void blend(canvas *c, int x, int y, rgba8 col, float cover)
{
	if (x < 0 || y < 0 || x >= c->w || y >= c->h || !(cover > 0.0f))
		return;
	float a = (cover > 1.0f ? 1.0f : cover) * (float)col.a / 255.0f;
	uint8_t *p = c->px + 4 * ((size_t)y * (size_t)c->w + (size_t)x);
	p[0] = (uint8_t)lrintf((float)p[0] + ((float)col.r - (float)p[0]) * a);
	p[1] = (uint8_t)lrintf((float)p[1] + ((float)col.g - (float)p[1]) * a);
	p[2] = (uint8_t)lrintf((float)p[2] + ((float)col.b - (float)p[2]) * a);
	p[3] = (uint8_t)lrintf((float)p[3] + (255.0f - (float)p[3]) * a);
}

void canvas_rect(canvas *c, int x, int y, int w, int h, rgba8 col)
{
	for (int j = y; j < y + h; j++)
		for (int i = x; i < x + w; i++)
			blend(c, i, j, col, 1.0f);
}

void canvas_fill(canvas *c, rgba8 col)
{
	for (size_t i = 0; i < (size_t)c->w * (size_t)c->h; i++)
		memcpy(c->px + 4 * i, &col, 4);
}

/* Coverage by distance to the segment: 1 inside width / 2, a one-pixel
 * ramp outside, so lines look smooth at any slope. */
void canvas_line(canvas *c, float x0, float y0, float x1, float y1, float width, rgba8 col)
{
	float r = 0.5f * width;
	int xa = (int)floorf(fminf(x0, x1) - r - 1), xb = (int)ceilf(fmaxf(x0, x1) + r + 1);
	int ya = (int)floorf(fminf(y0, y1) - r - 1), yb = (int)ceilf(fmaxf(y0, y1) + r + 1);
	xa = xa < 0 ? 0 : xa; ya = ya < 0 ? 0 : ya;
	xb = xb > c->w - 1 ? c->w - 1 : xb; yb = yb > c->h - 1 ? c->h - 1 : yb;
	float dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
	for (int y = ya; y <= yb; y++)
		for (int x = xa; x <= xb; x++) {
			float px = (float)x + 0.5f - x0, py = (float)y + 0.5f - y0;
			float s = len2 > 0.0f ? (px * dx + py * dy) / len2 : 0.0f;
			s = s < 0.0f ? 0.0f : s > 1.0f ? 1.0f : s;
			float ex = px - s * dx, ey = py - s * dy;
			blend(c, x, y, col, r + 0.5f - sqrtf(ex * ex + ey * ey));
		}
}

void canvas_ring(canvas *c, float cx, float cy, float radius, float width, rgba8 col)
{
	float r = 0.5f * width;
	int xa = (int)floorf(cx - radius - r - 1), xb = (int)ceilf(cx + radius + r + 1);
	int ya = (int)floorf(cy - radius - r - 1), yb = (int)ceilf(cy + radius + r + 1);
	for (int y = ya; y <= yb; y++)
		for (int x = xa; x <= xb; x++) {
			float d = hypotf((float)x + 0.5f - cx, (float)y + 0.5f - cy);
			blend(c, x, y, col, r + 0.5f - fabsf(d - radius));
		}
}

static const uint8_t *font_atlas(int *atlas_w)
{
	static uint8_t atlas[128 * FONT_CELL_W * FONT_CELL_H];
	static int w;
	if (!w) {
		w = font_glyph_count() * FONT_CELL_W;
		font_rasterize(atlas, w);
	}
	*atlas_w = w;
	return atlas;
}

int canvas_text_width(int scale, const char *s)
{
	int n = (int)strlen(s);
	return n ? (n * (FONT_GLYPH_W + 1) - 1) * scale : 0;
}

int canvas_text(canvas *c, int x, int y, int scale, const char *s, rgba8 col)
{
	int aw;
	const uint8_t *atlas = font_atlas(&aw);
	int pen = x;
	for (; *s; s++, pen += (FONT_GLYPH_W + 1) * scale) {
		int g = font_glyph_index(*s);
		if (g < 0)
			continue;
		for (int gy = 0; gy < FONT_GLYPH_H; gy++)
			for (int gx = 0; gx < FONT_GLYPH_W; gx++)
				if (atlas[(size_t)(gy + 1) * (size_t)aw + (size_t)(g * FONT_CELL_W + gx + 1)])
					canvas_rect(c, pen + gx * scale, y + gy * scale, scale, scale, col);
	}
	return pen - x;
}

/* Tick spacing of 1, 2 or 5 times a power of ten giving about `want` ticks. */
static double nice_step(double range, int want)
{
	double rough = range / want, mag = pow(10.0, floor(log10(rough))), norm = rough / mag;
	return (norm < 1.5 ? 1 : norm < 3 ? 2 : norm < 7 ? 5 : 10) * mag;
}

static int step_decimals(double step)
{
	int d = (int)-floor(log10(step) + 1e-9);
	return d < 0 ? 0 : d > 6 ? 6 : d;
}

typedef struct plot {
	int l, t, w, h;      /* plot area on the canvas */
	double x0, x1, y0, y1;
} plot;

static float map_x(const plot *p, double x)
{
	return (float)(p->l + (x - p->x0) / (p->x1 - p->x0) * p->w);
}

static float map_y(const plot *p, double y)
{
	return (float)(p->t + (1.0 - (y - p->y0) / (p->y1 - p->y0)) * p->h);
}

static const rgba8 INK = { 51, 51, 51, 255 }, GRID = { 230, 232, 236, 255 },
		   AXIS = { 120, 120, 120, 255 }, REF = { 150, 150, 150, 255 };
#define TEXT_SCALE 2
#define GLYPH_H (FONT_GLYPH_H * TEXT_SCALE)

static void y_range(const chart *ch, plot *p)
{
	double lo = INFINITY, hi = -INFINITY;
	for (int s = 0; s < ch->series_count; s++)
		for (int i = 0; i < ch->n; i++) {
			double v = ch->series[s].y[i];
			if (isfinite(v)) {
				lo = v < lo ? v : lo;
				hi = v > hi ? v : hi;
			}
		}
	if (isfinite(ch->ref_y)) {
		lo = ch->ref_y < lo ? ch->ref_y : lo;
		hi = ch->ref_y > hi ? ch->ref_y : hi;
	}
	if (!(lo <= hi))
		lo = 0, hi = 1;
	if (hi - lo < 1e-6)
		lo -= 0.001 + 0.01 * fabs(lo), hi += 0.001 + 0.01 * fabs(hi);
	double pad = 0.06 * (hi - lo);
	p->y0 = lo - pad;
	p->y1 = hi + pad;
}

static void draw_axes(canvas *c, const chart *ch, const plot *p)
{
	char buf[32];
	double ys = nice_step(p->y1 - p->y0, 5);
	int yd = step_decimals(ys);
	for (double v = ceil(p->y0 / ys) * ys; v <= p->y1; v += ys) {
		float y = map_y(p, v);
		canvas_line(c, (float)p->l, y, (float)(p->l + p->w), y, 1.0f, GRID);
		canvas_line(c, (float)p->l - 6, y, (float)p->l, y, 1.0f, AXIS);
		snprintf(buf, sizeof buf, "%.*f", yd, fabs(v) < ys * 1e-6 ? 0.0 : v);
		canvas_text(c, p->l - 10 - canvas_text_width(TEXT_SCALE, buf),
			    (int)y - GLYPH_H / 2, TEXT_SCALE, buf, INK);
	}
	double xs = nice_step(p->x1 - p->x0 > 1 ? p->x1 - p->x0 : 1, 8);
	if (xs < 1)
		xs = 1;
	for (double v = ceil(p->x0 / xs) * xs; v <= p->x1; v += xs) {
		float x = map_x(p, v);
		canvas_line(c, x, (float)p->t, x, (float)(p->t + p->h), 1.0f, GRID);
		canvas_line(c, x, (float)(p->t + p->h), x, (float)(p->t + p->h + 6), 1.0f, AXIS);
		snprintf(buf, sizeof buf, "%.0f", v);
		canvas_text(c, (int)x - canvas_text_width(TEXT_SCALE, buf) / 2, p->t + p->h + 12,
			    TEXT_SCALE, buf, INK);
	}
	canvas_line(c, (float)p->l, (float)p->t, (float)p->l, (float)(p->t + p->h), 1.5f, AXIS);
	canvas_line(c, (float)p->l, (float)(p->t + p->h), (float)(p->l + p->w),
		    (float)(p->t + p->h), 1.5f, AXIS);
	if (ch->x_label)
		canvas_text(c, p->l + (p->w - canvas_text_width(TEXT_SCALE, ch->x_label)) / 2,
			    p->t + p->h + 18 + GLYPH_H, TEXT_SCALE, ch->x_label, INK);
	if (ch->y_label)
		canvas_text(c, 8, p->t - GLYPH_H - 10, TEXT_SCALE, ch->y_label, INK);
}

/* A polyline through the finite points; dashed ones drawn in pieces of
 * 10 px on, 6 px off along the path. */
static void draw_series(canvas *c, const chart *ch, const plot *p, const chart_series *s)
{
	float along = 0.0f;
	int have = 0;
	float px = 0, py = 0;
	for (int i = 0; i < ch->n; i++) {
		if (!isfinite(s->y[i])) {
			have = 0;
			continue;
		}
		float x = map_x(p, (double)ch->x[i]), y = map_y(p, s->y[i]);
		if (have && !s->dashed)
			canvas_line(c, px, py, x, y, s->width, s->color);
		if (have && s->dashed) {
			float len = hypotf(x - px, y - py);
			for (float u = 0.0f; u < len;) {
				float phase = fmodf(along + u, 16.0f), step = phase < 10.0f ? 10.0f - phase : 16.0f - phase;
				float v = u + step < len ? u + step : len;
				if (phase < 10.0f)
					canvas_line(c, px + (x - px) * u / len, py + (y - py) * u / len,
						    px + (x - px) * v / len, py + (y - py) * v / len, s->width, s->color);
				u = v;
			}
			along += len;
		}
		px = x, py = y, have = 1;
	}
}

static int legend_width(const chart *ch)
{
	int total = 0;
	for (int s = 0; s < ch->series_count; s++)
		total += 34 + canvas_text_width(TEXT_SCALE, ch->series[s].label) + 22;
	return total - 22;
}

static void draw_legend(canvas *c, const chart *ch, int right, int y)
{
	int x = right - legend_width(ch);
	for (int s = 0; s < ch->series_count; s++) {
		const chart_series *se = &ch->series[s];
		float my = (float)y + GLYPH_H / 2.0f;
		if (se->dashed) {
			canvas_line(c, (float)x, my, (float)x + 11, my, se->width, se->color);
			canvas_line(c, (float)x + 17, my, (float)x + 28, my, se->width, se->color);
		} else {
			canvas_line(c, (float)x, my, (float)x + 28, my, se->width + 0.5f, se->color);
		}
		x += 34;
		x += canvas_text(c, x, y, TEXT_SCALE, se->label, INK) + 22;
	}
}

void chart_draw(canvas *c, const chart *ch)
{
	static const rgba8 white = { 255, 255, 255, 255 };
	canvas_fill(c, white);
	plot p = { 96, 30 + 2 * GLYPH_H + 12, 0, 0, 0, 1, 0, 1 };
	p.w = c->w - p.l - 24;
	p.h = c->h - p.t - 2 * GLYPH_H - 40;
	if (ch->n > 0) {
		p.x0 = (double)ch->x[0];
		p.x1 = (double)ch->x[ch->n - 1];
	}
	if (p.x1 <= p.x0)
		p.x1 = p.x0 + 1;
	y_range(ch, &p);
	int title_w = ch->title ? canvas_text(c, 8, 10, TEXT_SCALE, ch->title, INK) : 0;
	/* the legend beside the title when both fit, else on the line below */
	draw_legend(c, ch, c->w - 24, 8 + title_w + 40 + legend_width(ch) <= c->w - 24 ? 10 : 16 + GLYPH_H);
	draw_axes(c, ch, &p);
	if (isfinite(ch->ref_y)) {
		chart_series ref = { NULL, NULL, REF, 1.0f, 1 };
		float y = map_y(&p, ch->ref_y);
		for (float x = (float)p.l; x < (float)(p.l + p.w); x += 12)
			canvas_line(c, x, y, fminf(x + 6, (float)(p.l + p.w)), y, ref.width, ref.color);
	}
	for (int s = 0; s < ch->series_count; s++)
		draw_series(c, ch, &p, &ch->series[s]);
}

#define CHART_MAX_BYTES ((size_t)2048 * 1024 * 4)

int chart_write_png(const char *path, const chart *ch, int w, int h)
{
	TOOL_STATE_ARRAY(uint8_t, px, CHART_MAX_BYTES);
	skp_error err;
	if ((size_t)w * (size_t)h * 4 > CHART_MAX_BYTES) {
		fprintf(stderr, "%s: a %dx%d chart is too big\n", path, w, h);
		return -1;
	}
	canvas c = { px, w, h };
	chart_draw(&c, ch);
	if (cli_output_check(path) < 0)
		return -1;
	if (png_write_rgba(path, px, w, h, 0, &err) != 0) {
		fprintf(stderr, "%s: %s\n", path, err.msg);
		return -1;
	}
	return 0;
}
