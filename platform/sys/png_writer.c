#include "png_writer.h"

#include <png.h>
#include <string.h>

/* libpng's simplified API: it keeps its setjmp error handling inside, and
 * a negative row stride writes bottom-up rows without a copy. */

int png_write_rgba(const char *path, const uint8_t *rgba, int width, int height, unsigned how, skp_error *err)
{
	png_image image;

	if (!path || !rgba || width < 1 || height < 1 || width > (1 << 16) || height > (1 << 16))
		return skp_fail(err, SKP_ERR_RANGE, 0, "%s: cannot write a %dx%d PNG", path ? path : "(null)",
				width, height);
	memset(&image, 0, sizeof image);
	image.version = PNG_IMAGE_VERSION;
	image.width = (png_uint_32)width;
	image.height = (png_uint_32)height;
	image.format = PNG_FORMAT_RGBA;
	image.flags = how & PNG_WRITE_FAST ? PNG_IMAGE_FLAG_FAST : 0;
	png_int_32 stride = (png_int_32)width * 4;
	if (!png_image_write_to_file(&image, path, 0, rgba, how & PNG_WRITE_BOTTOM_UP ? -stride : stride, NULL))
		return skp_fail(err, SKP_ERR_IO, 0, "%s: cannot write PNG: %s", path, image.message);
	return SKP_OK;
}

int png_read_rgba(const char *path, uint8_t *rgba, int max_bytes, int *w, int *h, skp_error *err)
{
	png_image image;
	int rc = SKP_OK;

	memset(&image, 0, sizeof image);
	image.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&image, path))
		return skp_fail(err, SKP_ERR_IO, 0, "%s: cannot read PNG: %s", path, image.message);
	image.format = PNG_FORMAT_RGBA;
	if (max_bytes < 0 || PNG_IMAGE_SIZE(image) > (png_alloc_size_t)max_bytes) {
		rc = skp_fail(err, SKP_ERR_LIMIT, 0, "%s: %lux%lu PNG does not fit in %d bytes", path,
			      (unsigned long)image.width, (unsigned long)image.height, max_bytes);
		goto done;
	}
	if (!png_image_finish_read(&image, NULL, rgba, 0, NULL)) {
		rc = skp_fail(err, SKP_ERR_IO, 0, "%s: cannot read PNG: %s", path, image.message);
		goto done;
	}
	*w = (int)image.width;
	*h = (int)image.height;
done:
	png_image_free(&image);
	return rc;
}
