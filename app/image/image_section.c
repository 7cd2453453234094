#include "image_section.h"

#include <string.h>

#include "image_error.h"
#include "image_recover.h"
#include "skp_format.h"

void sec_open(skp_image *im, const skp_image_section *sec, uint8_t kind, uint16_t item)
{
	im->s_block = sec->first;
	im->s_end = sec->first + sec->count;
	im->s_left = sec->bytes;
	im->s_pos = im->hdr.block_size - SKP_IMAGE_BLOCK_EXTRA; /* nothing buffered */
	im->s_kind = kind;
	im->s_item = item;
}

static const char *const kind_names[] = {
	"", "header", "skeleton", "bind", "clip directory", "clip quantisation", "clip frames"
};

skp_status sec_get(skp_image *im, void *out, uint32_t n, skp_error *err)
{
	uint8_t *o = out;
	uint32_t payload = im->hdr.block_size - SKP_IMAGE_BLOCK_EXTRA;
	const char *what = kind_names[im->s_kind];
	if (n > im->s_left)
		return image_block_fail(err, SKP_ERR_CORRUPT, im->s_block, "%s section ends early", what);
	while (n > 0) {
		if (im->s_pos == payload) {
			if (im->s_block >= im->s_end)
				return image_block_fail(err, SKP_ERR_CORRUPT, im->s_block, "%s section ends early", what);
			skp_block_state st = skp_image_read_block(im, im->s_block, im->s_kind, im->s_item, im->buf);
			if (st != SKP_BLOCK_OK)
				return image_block_fail(err, st == SKP_BLOCK_IO ? SKP_ERR_IO : SKP_ERR_CORRUPT, im->s_block,
						  "%s section: %s", what, skp_block_state_name(st));
			im->s_block++;
			im->s_pos = 0;
		}
		uint32_t k = payload - im->s_pos < n ? payload - im->s_pos : n;
		memcpy(o, im->buf + SKP_IMAGE_BLOCK_HDR + im->s_pos, k);
		im->s_pos += k;
		im->s_left -= k;
		o += k;
		n -= k;
	}
	return SKP_OK;
}

long sec_block(const skp_image *im)
{
	return im->s_pos == 0 ? (long)im->s_block : (long)im->s_block - 1;
}

skp_status sec_bad(skp_image *im, skp_error *err, const char *what)
{
	skp_fail(err, SKP_ERR_CORRUPT, 0, "%s section: %s", kind_names[im->s_kind], what);
	if (err)
		err->block = sec_block(im);
	return SKP_ERR_CORRUPT;
}

skp_status sec_u8(skp_image *im, uint8_t *v, skp_error *err)
{
	return sec_get(im, v, 1, err);
}

skp_status sec_u16(skp_image *im, uint16_t *v, skp_error *err)
{
	uint8_t b[2] = { 0, 0 }; /* decoded even when the read failed */
	skp_status rc = sec_get(im, b, 2, err);
	*v = le_get16(b);
	return rc;
}

skp_status sec_u32(skp_image *im, uint32_t *v, skp_error *err)
{
	uint8_t b[4] = { 0, 0, 0, 0 }; /* decoded even when the read failed */
	skp_status rc = sec_get(im, b, 4, err);
	*v = le_get32(b);
	return rc;
}

skp_status sec_floats(skp_image *im, float *v, int n, skp_error *err)
{
	skp_status rc = SKP_OK;
	for (int i = 0; i < n && !rc; i++) {
		uint32_t u;
		rc = sec_u32(im, &u, err);
		memcpy(&v[i], &u, 4);
	}
	return rc;
}

skp_status sec_str(skp_image *im, char *s, skp_error *err)
{
	uint8_t n;
	skp_status rc = sec_u8(im, &n, err);
	if (rc)
		return rc;
	if (n >= SKP_MAX_NAME)
		return sec_bad(im, err, "name longer than SKP_MAX_NAME");
	char raw[SKP_MAX_NAME];
	rc = sec_get(im, raw, n, err);
	raw[n] = '\0';
	skp_escape_name(s, SKP_MAX_NAME, raw); /* names are printed and shown */
	return rc;
}
