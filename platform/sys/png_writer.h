/* RGBA8 PNG files through libpng: screenshots and golden-image tests. */
#ifndef PNG_WRITER_H
#define PNG_WRITER_H

#include <stdint.h>

#include "skp_error.h"

/* Writes width x height RGBA8 pixels, rows packed (width * 4 bytes).
 * bottom_up: the first row in memory is the bottom of the image, as
 * glReadPixels and OSMesa give it. */
int png_write_rgba(const char *path, const uint8_t *rgba, int width, int height, int bottom_up,
		   skp_error *err);

/* Reads any PNG as RGBA8, top row first, into rgba (at most max_bytes);
 * *w and *h get the size. Fails with SKP_ERR_LIMIT when it does not fit. */
int png_read_rgba(const char *path, uint8_t *rgba, int max_bytes, int *w, int *h, skp_error *err);

#endif
