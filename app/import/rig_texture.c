#include "rig_texture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


int rig_texture_side(int side)
{
	int p = 1;
	while (p <= side / 2)
		p *= 2;
	/* nearer by ratio: 1.5 times a power of two goes up, 1.4 down */
	if (p < side && (double)side / p > 1.41421356)
		p *= 2;
	return p < SKP_MAX_TEXTURE_SIDE ? p : SKP_MAX_TEXTURE_SIDE;
}

/* Channel c of the texture at (x, y) pixels from its top left, bilinear,
 * repeating (as the GPU samples it). */
static float bilinear(const uint8_t *rgba, int w, int h, float x, float y, int c)
{
	int x0 = (int)floorf(x), y0 = (int)floorf(y);
	float fx = x - (float)x0, fy = y - (float)y0, sum = 0.0f;
	for (int k = 0; k < 4; k++) {
		int xi = ((x0 + (k & 1)) % w + w) % w, yi = ((y0 + (k >> 1)) % h + h) % h;
		float f = ((k & 1) ? fx : 1.0f - fx) * ((k >> 1) ? fy : 1.0f - fy);
		sum += f * (float)rgba[4 * ((size_t)yi * (size_t)w + (size_t)xi) + (size_t)c];
	}
	return sum;
}

/* Pixel (x, y) of the W x H result (y from the bottom): the mean of n x m
 * bilinear samples spread over the source area it covers. */
static void resample_pixel(const uint8_t *rgba, int w, int h, int W, int H, int x, int y, uint8_t out[3])
{
	float sx = (float)w / (float)W, sy = (float)h / (float)H;
	int n = (int)ceilf(sx), m = (int)ceilf(sy);
	int top = H - 1 - y;
	for (int c = 0; c < 3; c++) {
		float sum = 0.0f;
		for (int j = 0; j < m; j++)
			for (int i = 0; i < n; i++)
				sum += bilinear(rgba, w, h, ((float)x + ((float)i + 0.5f) / (float)n) * sx - 0.5f,
						((float)top + ((float)j + 0.5f) / (float)m) * sy - 0.5f, c);
		out[c] = (uint8_t)lrintf(sum / (float)(n * m));
	}
}

/* RGB8 rows bottom first at W x H: flipped alone when the size is kept. */
static void to_board(const uint8_t *rgba, int w, int h, uint8_t *rgb, int W, int H)
{
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++) {
			uint8_t *dst = rgb + 3 * ((size_t)y * (size_t)W + (size_t)x);
			if (W == w && H == h)
				memcpy(dst, rgba + 4 * ((size_t)(h - 1 - y) * (size_t)w + (size_t)x), 3);
			else
				resample_pixel(rgba, w, h, W, H, x, y, dst);
		}
}

skp_status rig_texture_make(const uint8_t *rgba, int w, int h, tex_image *out, const tex_encode_progress *progress,
			    skp_error *err)
{
	out->width = out->height = 0;
	if (SKP_MAX_TEXTURE_SIDE <= 0)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "this board keeps no texture");
	int W = rig_texture_side(w), H = rig_texture_side(h);
	uint8_t *rgb = malloc(tex_rgb8_bytes(W, H));
	if (!rgb)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "out of memory for a %dx%d texture", W, H);
	to_board(rgba, w, h, rgb, W, H);
	tex_etc1_mipmaps mm;
	memset(&mm, 0, sizeof mm);
	skp_status rc = tex_encode_etc1_mipmaps(rgb, W, H, &mm, progress, err);
	free(rgb);
	if (rc == SKP_OK)
		rc = tex_image_begin(out, W, H, err);
	if (rc == SKP_OK && out->chain.etc1_bytes != mm.chain.etc1_bytes)
		rc = skp_fail(err, SKP_ERR_RANGE, 0, "the encoder's chain is %lu bytes, the image's %lu",
			      (unsigned long)mm.chain.etc1_bytes, (unsigned long)out->chain.etc1_bytes);
	if (rc == SKP_OK)
		memcpy(out->etc1, mm.blocks, mm.chain.etc1_bytes);
	else
		out->width = out->height = 0;
	tex_etc1_mipmaps_free(&mm);
	return rc;
}
