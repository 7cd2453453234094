/* Built-in 5x7 bitmap font for the HUD (no files to ship or load). */
#ifndef RENDER_FONT_H
#define RENDER_FONT_H

#include <stdint.h>

#define FONT_GLYPH_W 5
#define FONT_GLYPH_H 7
#define FONT_CELL_W 7   /* glyph plus a blank border, so filtering never bleeds */
#define FONT_CELL_H 9

/* Index of c's glyph in the atlas, or -1 when it draws nothing. */
int font_glyph_index(char c);
int font_glyph_count(void);

/* Writes all glyphs side by side into an 8-bit alpha atlas of
 * atlas_w x FONT_CELL_H (atlas_w >= font_glyph_count() * FONT_CELL_W). */
void font_rasterize(uint8_t *atlas, int atlas_w);

#endif
