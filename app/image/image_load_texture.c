#include "image_load_texture.h"

#include <math.h>

#include "image_section.h"

static skp_status get_uv(skp_image *im, mesh *m, skp_error *err)
{
	float origin[2], step[2];
	skp_status rc = sec_floats(im, origin, 2, err);
	if (!rc) rc = sec_floats(im, step, 2, err);
	if (rc)
		return rc;
	for (int i = 0; i < 2; i++)
		if (!isfinite(origin[i]) || !isfinite(origin[i] + 65535.0f * step[i]) || !(step[i] >= 0))
			return sec_bad(im, err, "texture coordinate bounds not finite");
	for (int v = 0; v < m->vert_count && !rc; v++) {
		uint8_t rec[4];
		rc = sec_get(im, rec, sizeof rec, err);
		m->uv[v][0] = origin[0] + (float)le_get16(rec) * step[0];
		m->uv[v][1] = origin[1] + (float)le_get16(rec + 2) * step[1];
	}
	if (!rc) rc = sec_get(im, m->sampled, (uint32_t)m->vert_count, err);
	for (int v = 0; v < m->vert_count && !rc; v++)
		if (m->sampled[v] > 1)
			return sec_bad(im, err, "a vertex's texture flag neither 0 nor 1");
	return rc;
}

/* The texture's size and format, checked against the bytes it says. */
static skp_status get_shape(skp_image *im, uint16_t *w, uint16_t *h, uint32_t *bytes, skp_error *err)
{
	uint8_t format = 0;
	skp_status rc = sec_u16(im, w, err);
	if (!rc) rc = sec_u16(im, h, err);
	if (!rc) rc = sec_u8(im, &format, err);
	if (!rc) rc = sec_u32(im, bytes, err);
	if (rc)
		return rc;
	if (format != SKP_IMAGE_TEXTURE_ETC1)
		return sec_bad(im, err, "texture format not ETC1 (1)");
	tex_mip_chain chain;
	skp_error ignored;
	if (!tex_is_power_of_two(*w) || !tex_is_power_of_two(*h) || tex_mip_chain_make(*w, *h, &chain, &ignored) != SKP_OK)
		return sec_bad(im, err, "texture sides not powers of two up to 4096");
	if (chain.etc1_bytes != *bytes)
		return sec_bad(im, err, "texture bytes differ from its mip chain's");
	return SKP_OK;
}

skp_status image_get_texture(skp_image *im, mesh *m, skp_error *err)
{
	uint8_t textured = 0;
	skp_status rc = sec_u8(im, &textured, err);
	if (rc || !textured)
		return rc;
	if (textured > 1)
		return sec_bad(im, err, "texture flag neither 0 nor 1");
	uint16_t w = 0, h = 0;
	uint32_t bytes = 0;
	rc = get_uv(im, m, err);
	if (!rc) rc = get_shape(im, &w, &h, &bytes, err);
	if (rc)
		return rc;
	skp_error ignored;
	tex_image *t = im->texture;
	if (!t || tex_image_begin(t, w, h, &ignored) != SKP_OK) {
		/* the section ends here: its bytes need not be read */
		im->texture_skipped = 1;
		return SKP_OK;
	}
	rc = sec_get(im, t->etc1, bytes, err);
	if (rc) {
		t->width = t->height = 0;
		return rc;
	}
	m->textured = 1;
	return SKP_OK;
}
