#include "tex_image.h"

int tex_is_power_of_two(int n)
{
	return n > 0 && (n & (n - 1)) == 0;
}

skp_status tex_image_fits(int width, int height, skp_error *err)
{
	if (!tex_is_power_of_two(width) || !tex_is_power_of_two(height))
		return skp_fail(err, SKP_ERR_LIMIT, 0, "a %dx%d texture: its sides must be powers of two", width, height);
	if (width > SKP_MAX_TEXTURE_SIDE || height > SKP_MAX_TEXTURE_SIDE)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "a %dx%d texture: this board keeps %d pixels a side at most",
				width, height, SKP_MAX_TEXTURE_SIDE);
	return SKP_OK;
}

skp_status tex_image_begin(tex_image *t, int width, int height, skp_error *err)
{
	t->width = t->height = 0;
	skp_status rc = tex_image_fits(width, height, err);
	if (!rc)
		rc = tex_mip_chain_make(width, height, &t->chain, err);
	if (!rc && t->chain.etc1_bytes > sizeof t->etc1)
		rc = skp_fail(err, SKP_ERR_LIMIT, 0, "a %dx%d texture's %lu bytes do not fit in %lu", width, height,
			      (unsigned long)t->chain.etc1_bytes, (unsigned long)sizeof t->etc1);
	if (rc)
		return rc;
	t->width = width;
	t->height = height;
	return SKP_OK;
}
