/* A small software rasteriser for the comparison report (skintool compare):
 * an RGBA canvas with anti-aliased lines and rings, text in the HUD's 5x7
 * font (render_font.h), and line charts of series over frames with axes,
 * ticks, labels and a legend, written as PNG. */
#ifndef REPORT_CHART_H
#define REPORT_CHART_H

#include <stdint.h>

/* Top row first, 4 bytes per pixel, the caller's memory. */
typedef struct canvas {
	uint8_t *px;
	int w, h;
} canvas;

typedef struct rgba8 {
	uint8_t r, g, b, a;
} rgba8;

void canvas_fill(canvas *c, rgba8 col);
void canvas_rect(canvas *c, int x, int y, int w, int h, rgba8 col);
/* Anti-aliased segment of the given width (pixel centres at +0.5). */
void canvas_line(canvas *c, float x0, float y0, float x1, float y1, float width, rgba8 col);
void canvas_ring(canvas *c, float cx, float cy, float radius, float width, rgba8 col);
/* Text at (x, y) top-left, glyphs scale x 5x7 pixels; returns its width. */
int canvas_text(canvas *c, int x, int y, int scale, const char *s, rgba8 col);
int canvas_text_width(int scale, const char *s);

#define CHART_MAX_SERIES 8

typedef struct chart_series {
	const char *label;
	const float *y;       /* n values, NAN: no point */
	rgba8 color;
	float width;
	int dashed;
} chart_series;

typedef struct chart {
	const char *title;    /* drawn above the plot */
	const char *x_label, *y_label;
	const long *x;        /* n frame numbers, increasing */
	int n;
	float ref_y;          /* a dashed reference line, NAN for none */
	chart_series series[CHART_MAX_SERIES];
	int series_count;
} chart;

/* Draws ch into c (the whole canvas). */
void chart_draw(canvas *c, const chart *ch);

/* Draws ch on a w x h canvas and writes it as PNG; -1 after reporting. */
int chart_write_png(const char *path, const chart *ch, int w, int h);

#endif
