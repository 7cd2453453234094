#include "image_read.h"

#include <math.h>
#include <string.h>

#include "crc32.h"
#include "image_section.h"

static const char *const state_names[] = {
	"good", "I/O error", "short read", "CRC mismatch", "block of another image",
	"block out of place"
};

const char *skp_block_state_name(skp_block_state st)
{
	return (unsigned)st < sizeof state_names / sizeof state_names[0] ? state_names[st] : "?";
}

int skp_block_crc_ok(const uint8_t *block, uint32_t block_size)
{
	return crc32_compute(block, block_size - 4) == le_get32(block + block_size - 4);
}

uint32_t skp_image_block_size_hint(const uint8_t *block0, uint32_t n)
{
	if (n < SKP_IMAGE_BLOCK_HDR + 16 || memcmp(block0 + SKP_IMAGE_BLOCK_HDR, SKP_IMAGE_MAGIC, 8))
		return 0;
	uint32_t bs = le_get32(block0 + SKP_IMAGE_BLOCK_HDR + 12);
	return bs >= SKP_IMAGE_MIN_BLOCK && bs <= SKP_IMAGE_BLOCK_SIZE && bs % 16 == 0 ? bs : 0;
}

skp_block_state skp_image_frame_check(const skp_image *im, uint32_t block, int kind, unsigned item,
				      const uint8_t *buf)
{
	uint32_t bs = im->hdr.block_size;
	if (!skp_block_crc_ok(buf, bs))
		return SKP_BLOCK_CRC;
	if (le_get32(buf) != im->tag)
		return SKP_BLOCK_FOREIGN;
	if (le_get32(buf + 4) != block || (kind > 0 && (buf[8] != kind || le_get16(buf + 10) != item)))
		return SKP_BLOCK_MISPLACED;
	return SKP_BLOCK_OK;
}

skp_block_state skp_image_read_raw(const skp_image *im, uint32_t block, uint8_t *buf)
{
	int n = im->dev->read(im->dev->ctx, block, buf);
	if (n < 0)
		return n == SKP_BD_ERANGE ? SKP_BLOCK_SHORT : SKP_BLOCK_IO;
	return (uint32_t)n < im->hdr.block_size ? SKP_BLOCK_SHORT : SKP_BLOCK_OK;
}

skp_block_state skp_image_check_block(skp_image *im, uint32_t block, int kind, unsigned item,
				      uint8_t *buf)
{
	skp_block_state st = skp_image_read_raw(im, block, buf);
	return st != SKP_BLOCK_OK ? st : skp_image_frame_check(im, block, kind, item, buf);
}

skp_block_state skp_image_read_block(skp_image *im, uint32_t block, int kind, unsigned item,
				     uint8_t *buf)
{
	skp_block_state st = skp_image_check_block(im, block, kind, item, buf);
	if (st == SKP_BLOCK_OK || skp_image_rebuild(im, block, kind, item, buf) != SKP_BLOCK_OK)
		return st;
	im->rebuilt++;
	if (im->on_rebuild)
		im->on_rebuild(im->on_rebuild_ctx, block);
	return SKP_BLOCK_OK;
}


/* Header checks that need no other block, in the order a reader must make
 * them: what it is, whether it is intact, which version, whether it fits.
 * valid: the header decoded whole (version, size and CRC right). */
static skp_status check_header(const skp_image *im, const uint8_t *p, int n, int valid, skp_error *err)
{
	const skp_image_header *h = &im->hdr;
	uint32_t bs = im->dev->block_size;
	if (memcmp(p, SKP_IMAGE_MAGIC, 8))
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "not a skinplay image (no SKPIMAGE magic)");
	if (valid && h->block_size != bs)
		return skp_fail(err, SKP_ERR_RANGE, 0, "image block size %lu, storage opened with %lu",
				(unsigned long)h->block_size, (unsigned long)bs);
	if ((uint32_t)n < bs)
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "header block: short read");
	if (!skp_block_crc_ok(im->buf, bs))
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "header block: CRC mismatch");
	if (h->version < 1 || h->version > SKP_IMAGE_VERSION)
		return skp_fail(err, SKP_ERR_CORRUPT, 0, "image format version %u, this build reads versions 1 to %d",
				(unsigned)h->version, SKP_IMAGE_VERSION);
	unsigned size = h->version == 1 ? SKP_IMAGE_HEADER_V1 : SKP_IMAGE_HEADER_SIZE;
	if (h->header_size != size)
		return skp_fail(err, SKP_ERR_CORRUPT, 0, "header size %u, expected %u", (unsigned)h->header_size, size);
	if (!valid)
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "header CRC mismatch");
	return SKP_OK;
}

static skp_status limit(skp_error *err, const char *what, uint32_t need, long have, const char *name)
{
	if (need <= (uint32_t)have)
		return SKP_OK;
	return skp_fail(err, SKP_ERR_LIMIT, 0, "image needs %lu %s, board limit %s is %ld",
			(unsigned long)need, what, name, have);
}

static skp_status check_fit(const skp_image *im, skp_error *err)
{
	const skp_image_header *h = &im->hdr;
	skp_status rc = limit(err, "bones", h->bones, SKP_MAX_BONES, "SKP_MAX_BONES");
	if (!rc) rc = limit(err, "dofs per frame", h->dofs, SKP_MAX_DOF, "SKP_MAX_DOF");
	if (!rc) rc = limit(err, "vertices", h->verts, SKP_MAX_VERTS, "SKP_MAX_VERTS");
	if (!rc) rc = limit(err, "triangles", h->tris, SKP_MAX_TRIS, "SKP_MAX_TRIS");
	if (!rc) rc = limit(err, "influences per vertex", h->influences, SKP_MAX_INFLUENCES, "SKP_MAX_INFLUENCES");
	if (!rc) rc = limit(err, "clips", h->clips, SKP_IMAGE_MAX_CLIPS, "SKP_IMAGE_MAX_CLIPS");
	if (rc)
		return rc;
	if (h->block_count > im->dev->block_count)
		return skp_fail(err, SKP_ERR_CORRUPT, 0, "image truncated: the header says %lu blocks, the storage holds %lu",
				(unsigned long)h->block_count, (unsigned long)im->dev->block_count);
	/* version 2: data, parity, then the copy, which ends the image */
	if (h->version > 1 && ((uint64_t)h->data_blocks + h->parity_blocks + 1 != h->block_count ||
			       h->copy_block != h->block_count - 1 || h->parity_blocks > h->data_blocks))
		return skp_fail(err, SKP_ERR_CORRUPT, 0, "header: %lu data and %lu parity blocks do not make %lu",
				(unsigned long)h->data_blocks, (unsigned long)h->parity_blocks,
				(unsigned long)h->block_count);
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		const skp_image_section *s = &h->sec[i];
		uint32_t payload = h->block_size - SKP_IMAGE_BLOCK_EXTRA;
		if ((uint64_t)s->first + s->count > h->data_blocks ||
		    (i != SKP_SEC_CLIPS && ((uint64_t)s->count * payload < s->bytes || s->first == 0)))
			return skp_fail(err, SKP_ERR_CORRUPT, 0, "header: section %d out of the image", i + 1);
	}
	return SKP_OK;
}

static skp_status get_clip(skp_image *im, skp_image_clip *c, skp_error *err)
{
	uint32_t first;
	skp_status rc = sec_str(im, c->name, err);
	if (!rc) rc = sec_floats(im, &c->fps, 1, err);
	if (!rc) rc = sec_u32(im, &c->frame_count, err);
	if (!rc) rc = sec_u32(im, &first, err);
	if (!rc) rc = sec_u16(im, &c->dofs, err);
	if (!rc) rc = sec_u16(im, &c->frames_per_block, err);
	if (!rc) rc = sec_u32(im, &c->quant_first, err);
	if (!rc) rc = sec_u32(im, &c->quant_blocks, err);
	if (!rc) rc = sec_u32(im, &c->frames_first, err);
	if (!rc) rc = sec_u32(im, &c->frame_blocks, err);
	if (!rc) rc = sec_floats(im, &c->max_rot_err, 1, err);
	if (!rc) rc = sec_floats(im, &c->max_trans_err, 1, err);
	if (rc)
		return rc;
	c->first_number = (int32_t)first;
	uint32_t payload = im->hdr.block_size - SKP_IMAGE_BLOCK_EXTRA, fpb = c->frames_per_block;
	const skp_image_section *all = &im->hdr.sec[SKP_SEC_CLIPS];
	/* 64-bit sums: a crafted count near 2^32 must not wrap into range */
	uint64_t end = (uint64_t)all->first + all->count;
	if (c->dofs != im->hdr.dofs || fpb == 0 || fpb * 2u * c->dofs > payload || !(c->fps > 0) ||
	    !isfinite(c->fps) || (uint64_t)c->frame_blocks * fpb < c->frame_count ||
	    (uint64_t)c->frame_count + fpb <= (uint64_t)c->frame_blocks * fpb ||
	    c->quant_first < all->first || (uint64_t)c->quant_first + c->quant_blocks > end ||
	    (uint64_t)c->quant_blocks * payload < 8u * c->dofs ||
	    c->frames_first < all->first || (uint64_t)c->frames_first + c->frame_blocks > end)
		return sec_bad(im, err, "clip entry out of the image");
	return SKP_OK;
}

static skp_status load_directory(skp_image *im, skp_error *err)
{
	uint16_t n;
	sec_open(im, &im->hdr.sec[SKP_SEC_DIRECTORY], SKP_KIND_DIRECTORY, 0);
	skp_status rc = sec_u16(im, &n, err);
	if (rc)
		return rc;
	if (n != im->hdr.clips)
		return sec_bad(im, err, "clip count differs from the header's");
	for (int i = 0; i < n && !rc; i++)
		rc = get_clip(im, &im->clip[i], err);
	im->clip_count = rc ? 0 : n;
	return rc;
}

/* The header from block 0, checked in full. */
static skp_status header_from_block0(skp_image *im, skp_error *err)
{
	const skp_blockdev *dev = im->dev;
	int n = dev->read(dev->ctx, 0, im->buf);
	if (n == SKP_BD_ERANGE)
		n = 0; /* empty storage */
	if (n < 0)
		return image_block_fail(err, SKP_ERR_IO, 0, "header: I/O error");
	if ((uint32_t)n < SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_HEADER_V1)
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "header: short read (empty or truncated image)");
	const uint8_t *p = im->buf + SKP_IMAGE_BLOCK_HDR;
	int valid = skp_image_header_get(p, (uint32_t)n - SKP_IMAGE_BLOCK_HDR, &im->hdr);
	skp_status rc = check_header(im, p, n, valid, err);
	if (rc)
		return rc;
	im->tag = skp_image_tag(im->hdr.sequence);
	skp_block_state st = skp_image_frame_check(im, 0, SKP_KIND_HEADER, 0, im->buf);
	if (st != SKP_BLOCK_OK)
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "%s%s", "header block: ", skp_block_state_name(st));
	return SKP_OK;
}

/* Version 2: the header copy in the storage's last block, when block 0 is
 * unusable. 1 when its header is whole (its own CRC) and says it is there:
 * the rest of that block may be damaged too, the header is what counts. */
static int header_from_copy(skp_image *im)
{
	const skp_blockdev *dev = im->dev;
	uint32_t bs = dev->block_size, last = dev->block_count - 1;
	if (dev->block_count < 2 || dev->read(dev->ctx, last, im->buf) != (int)bs)
		return 0;
	skp_image_header h;
	const uint8_t *p = im->buf + bs - SKP_IMAGE_BLOCK_CRC - SKP_IMAGE_HEADER_SIZE;
	if (!skp_image_header_get(p, SKP_IMAGE_HEADER_SIZE, &h) || h.version < 2 || h.block_size != bs ||
	    h.copy_block != last)
		return 0;
	im->hdr = h;
	im->tag = skp_image_tag(h.sequence);
	return 1;
}

skp_status skp_image_open(skp_image *im, const skp_blockdev *dev, skp_error *err)
{
	skp_error_clear(err);
	memset(&im->hdr, 0, sizeof im->hdr);
	im->dev = dev;
	im->clip_count = 0;
	im->rebuilt = 0;
	im->header_from_copy = 0;
	if (dev->block_size < SKP_IMAGE_MIN_BLOCK || dev->block_size > SKP_IMAGE_BLOCK_SIZE)
		return skp_fail(err, SKP_ERR_RANGE, 0, "storage block size %lu: expected %d..%d",
				(unsigned long)dev->block_size, SKP_IMAGE_MIN_BLOCK, SKP_IMAGE_BLOCK_SIZE);
	skp_status rc = header_from_block0(im, err);
	if (rc && rc != SKP_ERR_RANGE && header_from_copy(im)) {
		im->header_from_copy = 1;
		if (im->on_rebuild)
			im->on_rebuild(im->on_rebuild_ctx, 0);
		skp_error_clear(err);
		rc = SKP_OK;
	}
	if (!rc)
		rc = check_fit(im, err);
	return rc ? rc : load_directory(im, err);
}

int skp_image_find_clip(const skp_image *im, const char *name)
{
	for (int i = 0; i < im->clip_count; i++)
		if (strcmp(im->clip[i].name, name) == 0)
			return i;
	return -1;
}
