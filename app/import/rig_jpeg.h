/* JPEG base colour textures for rig_colour.c, through libjpeg: decoded to
 * RGBA8 (top row first), embedded in the file or beside it. A damaged or
 * truncated file is an answer, never an exit: libjpeg's errors jump back
 * here, and its warnings (the premature end of a truncated file, corrupt
 * data it skipped) count as damage, since it would go on with grey or
 * garbled pixels. Grey JPEGs come out as RGB; CMYK (and YCCK) ones are
 * refused, their inks being no colour without the profile they were made
 * for. Progressive JPEGs read as baseline ones do. */
#ifndef RIG_JPEG_H
#define RIG_JPEG_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* 1 when the bytes begin as every JPEG does (FF D8 FF). */
int rig_jpeg_is(const void *bytes, size_t n);

/* A decoded JPEG: RGBA8, alpha 255, top row first; rgba is malloc()ed and
 * the caller's. */
typedef struct rig_jpeg_pixels {
	uint8_t *rgba;
	int w, h;
} rig_jpeg_pixels;

/* Decodes the n bytes at bytes, or (bytes NULL) the file f from where it
 * stands, refusing one larger than the importer reads (rig_limits.h) from
 * its header, before any pixel is decoded. 1 and out filled, or 0, out->rgba NULL and *why a
 * reason to follow the texture's name ("is truncated or damaged"). */
int rig_jpeg_read(const void *bytes, size_t n, FILE *f, rig_jpeg_pixels *out, const char **why);

#endif
