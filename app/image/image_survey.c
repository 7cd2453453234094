#include "image_survey.h"

#include <string.h>

#include "image_copies.h"
#include "sha256.h"

void skp_image_block_role(const skp_image *im, uint32_t b, int *kind, unsigned *item)
{
	static const int sec_kind[] = { SKP_KIND_SKELETON, SKP_KIND_BIND, SKP_KIND_DIRECTORY };
	const skp_image_header *h = &im->hdr;
	*item = 0;
	*kind = b == 0 ? SKP_KIND_HEADER : 0;
	for (int i = 0; i < 3; i++)
		if (b >= h->sec[i].first && b - h->sec[i].first < h->sec[i].count)
			*kind = sec_kind[i];
	if (im->digest_first && b >= im->digest_first && b < h->data_blocks)
		*kind = SKP_KIND_DIGESTS;
	for (int c = 0; c < im->clip_count; c++) {
		const skp_image_clip *cl = &im->clip[c];
		if (b >= cl->quant_first && b - cl->quant_first < cl->quant_blocks)
			*kind = SKP_KIND_QUANT, *item = (unsigned)c;
		if (b >= cl->frames_first && b - cl->frames_first < cl->frame_blocks)
			*kind = SKP_KIND_FRAMES, *item = (unsigned)c;
	}
}

static void survey_data(skp_image *im, uint32_t b, skp_block_report *r, uint8_t *buf)
{
	r->role = SKP_ROLE_DATA;
	skp_image_block_role(im, b, &r->kind, &r->item);
	r->group = skp_image_group(&im->hdr, b);
	r->state = skp_image_check_block(im, b, r->kind, r->item, buf);
	r->repairable = r->state != SKP_BLOCK_OK && skp_image_recover(im, b, r->kind, r->item, buf) == SKP_BLOCK_OK;
}

/* The parity block XORed with its group's data blocks is all zeros when it
 * matches them; a bad data block makes the answer unknown. */
static void survey_parity(skp_image *im, uint32_t b, skp_block_report *r, uint8_t *buf)
{
	const skp_image_header *h = &im->hdr;
	r->role = SKP_ROLE_PARITY;
	r->group = b - h->data_blocks;
	r->state = skp_image_read_raw(im, b, buf);
	int data_good = 1;
	for (uint32_t d = r->group; d < h->data_blocks; d += h->parity_blocks) {
		int kind;
		unsigned item;
		skp_image_block_role(im, d, &kind, &item);
		if (skp_image_check_block(im, d, kind, item, im->scratch) != SKP_BLOCK_OK) {
			data_good = 0;
			continue;
		}
		for (uint32_t i = 0; i < h->block_size; i++)
			buf[i] ^= im->scratch[i];
	}
	r->checked = data_good;
	if (r->state == SKP_BLOCK_OK && data_good)
		for (uint32_t i = 0; i < h->block_size; i++)
			if (buf[i]) {
				r->state = SKP_BLOCK_CRC;
				break;
			}
	r->repairable = r->state != SKP_BLOCK_OK && data_good;
}

/* A copy must be framed as one and hold what it copies (rebuilt from
 * there when not: the header always, a directory block when the primary
 * reads, from parity at most). */
static void survey_copy(skp_image *im, uint32_t b, skp_block_report *r, uint8_t *buf)
{
	const skp_image_header *h = &im->hdr;
	r->role = b == h->copy_block ? SKP_ROLE_COPY : SKP_ROLE_DIR_COPY;
	r->kind = b == h->copy_block ? SKP_KIND_HEADER : SKP_KIND_DIRECTORY;
	r->item = 1;
	r->state = skp_image_check_block(im, b, r->kind, 1, buf);
	/* what it copies, framed as this block (a rebuild reads its group
	 * through im->scratch) */
	skp_block_state want = skp_image_recover(im, b, r->kind, 1, im->buf);
	if (r->state == SKP_BLOCK_OK && want == SKP_BLOCK_OK && memcmp(buf, im->buf, h->block_size))
		r->state = SKP_BLOCK_MISPLACED;
	r->repairable = r->state != SKP_BLOCK_OK && want == SKP_BLOCK_OK;
}

void skp_image_survey(skp_image *im, uint32_t b, skp_block_report *r, uint8_t *buf)
{
	const skp_image_header *h = &im->hdr;
	memset(r, 0, sizeof *r);
	r->checked = 1;
	if (b < h->data_blocks)
		survey_data(im, b, r, buf);
	else if (b < h->data_blocks + h->parity_blocks)
		survey_parity(im, b, r, buf);
	else
		survey_copy(im, b, r, buf);
}

const char *skp_block_report_what(const skp_block_report *r)
{
	static const char *const kinds[] = { "data", "header", "skeleton", "bind", "clip directory",
					     "clip quantisation", "clip frames", "block digests" };
	if (r->role != SKP_ROLE_DATA)
		return r->role == SKP_ROLE_PARITY ? "parity" : r->role == SKP_ROLE_COPY ? "header copy" : "directory copy";
	return r->kind >= 0 && r->kind <= SKP_KIND_DIGESTS ? kinds[r->kind] : "data";
}

void skp_image_verify(skp_image *im, uint8_t *buf, void (*bad)(void *ctx, uint32_t block, const skp_block_report *r),
		      void *ctx, skp_image_verdict *v)
{
	sha256_ctx digest;
	uint8_t sum[SKP_IMAGE_DIGEST_BYTES];
	skp_block_report r;
	memset(v, 0, sizeof *v);
	v->digest = 1;
	sha256_init(&digest);
	for (uint32_t b = 0; b < im->hdr.block_count; b++) {
		skp_image_survey(im, b, &r, buf);
		int usable = r.state == SKP_BLOCK_OK || r.repairable;
		if (b > 0 && b < im->hdr.data_blocks && usable && !im->digest_first) /* version 7: the leaves did */
			sha256_update(&digest, buf, im->hdr.block_size);
		if (b < im->hdr.data_blocks && !usable)
			v->digest = -1;
		if (r.state == SKP_BLOCK_OK)
			continue;
		v->bad++;
		v->beyond += !r.repairable;
		if (bad)
			bad(ctx, b, &r);
	}
	sha256_final(&digest, sum);
	/* version 7: every usable data block matched its leaf (or was rebuilt
	 * to), so the image holds when its digest blocks gave the root */
	int holds = im->digest_first ? im->digests : !memcmp(sum, im->hdr.digest, sizeof sum);
	if (v->digest == 1 && !holds)
		v->digest = 0;
}
