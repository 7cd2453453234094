/* RGB8 <-> RGB565: the fallback format, for a GPU without ETC1 and for
 * the 16-bit textures GLES2 takes (GL_RGB, GL_UNSIGNED_SHORT_5_6_5). */
#ifndef TEX_RGB565_H
#define TEX_RGB565_H

#include <stddef.h>
#include <stdint.h>

/* One pixel, each channel rounded to the nearest of its 32 or 64 levels
 * (not truncated: truncation darkens the picture by half a step). */
uint16_t tex_rgb565_from_rgb8(uint8_t r, uint8_t g, uint8_t b);

/* One pixel back to 8 bits a channel by bit replication, so that 0 stays
 * 0 and the top level is 255, as GPUs expand it. */
void tex_rgb565_to_rgb8(uint16_t v, uint8_t rgb[3]);

/* count pixels, RGB8 packed in, RGB565 out. */
void tex_rgb565_from_rgb8_pixels(const uint8_t *rgb, size_t count, uint16_t *out);

#endif
