#include "skinplay_sheet.h"

#include <stdio.h>
#include <string.h>

#include "cli_inputs.h"
#include "png_writer.h"

void sheet_init(sheet *s, int frame_w, int frame_h)
{
	s->scale = 1;
	while ((frame_w / s->scale) * SHEET_COLUMNS > SHEET_MAX_W ||
	       (frame_h / s->scale) * (SHEET_MAX_CELLS / SHEET_COLUMNS) > SHEET_MAX_H)
		s->scale++;
	s->cell_w = frame_w / s->scale;
	s->cell_h = frame_h / s->scale;
	s->cells = 0;
	/* empty cells in the renderer's background colour, opaque */
	for (size_t i = 0; i < sizeof s->rgba; i += 4) {
		s->rgba[i] = 33; s->rgba[i + 1] = 38; s->rgba[i + 2] = 48; s->rgba[i + 3] = 255;
	}
}

/* box filter over scale x scale source pixels */
static void shrink_pixel(const uint8_t *src, int frame_w, int frame_h, int x, int y, int scale,
			 uint8_t *out)
{
	unsigned sum[4] = { 0, 0, 0, 0 };
	for (int dy = 0; dy < scale; dy++) {
		int sy = frame_h - 1 - (y * scale + dy); /* bottom-up source */
		const uint8_t *row = src + (size_t)sy * frame_w * 4;
		for (int dx = 0; dx < scale; dx++)
			for (int c = 0; c < 4; c++)
				sum[c] += row[(x * scale + dx) * 4 + c];
	}
	for (int c = 0; c < 4; c++)
		out[c] = (uint8_t)(sum[c] / (unsigned)(scale * scale));
}

int sheet_add(sheet *s, const uint8_t *rgba, int frame_w, int frame_h)
{
	if (s->cells >= SHEET_MAX_CELLS)
		return -1;
	int col = s->cells % SHEET_COLUMNS, row = s->cells / SHEET_COLUMNS;
	int sheet_w = s->cell_w * SHEET_COLUMNS;
	for (int y = 0; y < s->cell_h; y++)
		for (int x = 0; x < s->cell_w; x++) {
			uint8_t *dst = s->rgba + ((size_t)(row * s->cell_h + y) * sheet_w + col * s->cell_w + x) * 4;
			shrink_pixel(rgba, frame_w, frame_h, x, y, s->scale, dst);
		}
	s->cells++;
	return 0;
}

int sheet_write(const sheet *s, const char *path)
{
	skp_error err;
	int rows = (s->cells + SHEET_COLUMNS - 1) / SHEET_COLUMNS;
	if (rows == 0)
		return 0;
	if (cli_output_check(path) < 0)
		return -1;
	if (png_write_rgba(path, s->rgba, s->cell_w * SHEET_COLUMNS, s->cell_h * rows, 0, &err) != 0) {
		fprintf(stderr, "skinplay: %s: %s\n", path, err.msg);
		return -1;
	}
	return 0;
}
