/* RGBA8 PNG files through libpng: screenshots and golden-image tests. */
#ifndef PNG_WRITER_H
#define PNG_WRITER_H

#include <stdint.h>

#include "skp_error.h"

/* How png_write_rgba writes (or-ed; 0: top row first, compressed well). */
enum {
	/* the first row in memory is the bottom of the image, as glReadPixels
	 * and OSMesa give it */
	PNG_WRITE_BOTTOM_UP = 1,
	/* speed over size (libpng's PNG_IMAGE_FLAG_FAST): a headless run's
	 * stream of frames, about 4x faster to write and 1.5x the bytes */
	PNG_WRITE_FAST = 2,
};

/* Writes width x height RGBA8 pixels, rows packed (width * 4 bytes). */
int png_write_rgba(const char *path, const uint8_t *rgba, int width, int height, unsigned how, skp_error *err);

/* Reads any PNG as RGBA8, top row first, into rgba (at most max_bytes);
 * *w and *h get the size. Fails with SKP_ERR_LIMIT when it does not fit. */
int png_read_rgba(const char *path, uint8_t *rgba, int max_bytes, int *w, int *h, skp_error *err);

#endif
