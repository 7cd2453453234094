/* A contact sheet: key frames shrunk into one PNG, for the headless demo. */
#ifndef SKINPLAY_SHEET_H
#define SKINPLAY_SHEET_H

#include <stdint.h>

#include "board_limits.h"

#define SHEET_COLUMNS 4
#define SHEET_MAX_CELLS 16
/* two thirds of the board's largest frame each way (host: 2560x1440) */
#define SHEET_MAX_W (SKP_DISPLAY_MAX_W * 2 / 3)
#define SHEET_MAX_H (SKP_DISPLAY_MAX_H * 2 / 3)
#define SHEET_MAX_BYTES (SHEET_MAX_W * SHEET_MAX_H * 4)

typedef struct sheet {
	int cell_w, cell_h, scale;
	int cells;
	uint8_t rgba[SHEET_MAX_BYTES];   /* top row first */
} sheet;

/* Cells of frame size / scale, the scale chosen so 4 columns fit. */
void sheet_init(sheet *s, int frame_w, int frame_h);
/* Adds a frame (RGBA, bottom row first, as glReadPixels gives it);
 * returns 0, or -1 when the sheet is full. */
int sheet_add(sheet *s, const uint8_t *rgba, int frame_w, int frame_h);
/* Writes the cells added so far; 0 or -1 (reported). */
int sheet_write(const sheet *s, const char *path);

#endif
