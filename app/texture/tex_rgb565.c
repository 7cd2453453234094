/* RGB8 <-> RGB565: see tex_rgb565.h. */
#include "tex_rgb565.h"

/* v * top / 255 rounded to nearest, in integers. */
static unsigned scale_rounded(unsigned v, unsigned top)
{
	return (v * top + 127u) / 255u;
}

uint16_t tex_rgb565_from_rgb8(uint8_t r, uint8_t g, uint8_t b)
{
	return (uint16_t)(scale_rounded(r, 31u) << 11 | scale_rounded(g, 63u) << 5 | scale_rounded(b, 31u));
}

void tex_rgb565_to_rgb8(uint16_t v, uint8_t rgb[3])
{
	unsigned r = v >> 11 & 31u, g = v >> 5 & 63u, b = v & 31u;
	rgb[0] = (uint8_t)(r << 3 | r >> 2);
	rgb[1] = (uint8_t)(g << 2 | g >> 4);
	rgb[2] = (uint8_t)(b << 3 | b >> 2);
}

void tex_rgb565_from_rgb8_pixels(const uint8_t *rgb, size_t count, uint16_t *out)
{
	for (size_t i = 0; i < count; i++, rgb += 3)
		out[i] = tex_rgb565_from_rgb8(rgb[0], rgb[1], rgb[2]);
}
