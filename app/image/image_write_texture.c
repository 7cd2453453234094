/* Version 8's end of the bind section: the body's texture coordinates in
 * 16-bit steps over their bounds, which vertices sample the texture, and
 * the texture's ETC1 mip chain (image_format.h: BIND). */
#include "image_write_internal.h"

#include "skin_compact.h"

static skp_status put_uv(skp_image_writer *w, const mesh *m, skp_error *err)
{
	float origin[2], step[2];
	skp_status rc = SKP_OK;
	for (int i = 0; i < 2; i++) {
		skin_quant_bounds(&m->uv[0][i], m->vert_count, 2, &origin[i], &step[i]);
		if (!rc) rc = image_put_f32(w, origin[i], err);
	}
	for (int i = 0; i < 2 && !rc; i++)
		rc = image_put_f32(w, step[i], err);
	for (int v = 0; v < m->vert_count && !rc; v++) {
		uint8_t rec[4];
		le_put16(rec, skin_quantise(m->uv[v][0], origin[0], step[0]));
		le_put16(rec + 2, skin_quantise(m->uv[v][1], origin[1], step[1]));
		rc = image_put_bytes(w, rec, sizeof rec, err);
	}
	for (int v = 0; v < m->vert_count && !rc; v++)
		rc = image_put_u8(w, m->sampled[v] != 0, err);
	return rc;
}

static skp_status put_chain(skp_image_writer *w, const tex_image *t, skp_error *err)
{
	skp_status rc = image_put_u16(w, (unsigned)t->width, err);
	if (!rc) rc = image_put_u16(w, (unsigned)t->height, err);
	if (!rc) rc = image_put_u8(w, SKP_IMAGE_TEXTURE_ETC1, err);
	if (!rc) rc = image_put_u32(w, (uint32_t)t->chain.etc1_bytes, err);
	return rc ? rc : image_put_bytes(w, t->etc1, (uint32_t)t->chain.etc1_bytes, err);
}

skp_status image_put_texture(skp_image_writer *w, const mesh *m, skp_error *err)
{
	const tex_image *t = w->texture;
	int textured = m->textured && t && t->width > 0;
	if (textured && t->chain.etc1_bytes > sizeof t->etc1)
		return skp_fail(err, SKP_ERR_RANGE, 0, "texture chain of %lu bytes in a %lu-byte buffer",
				(unsigned long)t->chain.etc1_bytes, (unsigned long)sizeof t->etc1);
	skp_status rc = image_put_u8(w, textured, err);
	if (!rc && textured)
		rc = put_uv(w, m, err);
	return rc || !textured ? rc : put_chain(w, t, err);
}
