#include "image_read.h"

#include <math.h>
#include <string.h>

#include "crc32.h"
#include "image_copies.h"
#include "image_digests.h"
#include "image_error.h"
#include "image_header_parity.h"
#include "image_section.h"

static int block_size_ok(uint32_t bs)
{
	return bs >= SKP_IMAGE_MIN_BLOCK && bs <= SKP_IMAGE_BLOCK_SIZE && bs % 16 == 0;
}

uint32_t skp_image_block_size_hint(const uint8_t *block0, uint32_t n)
{
	skp_image_header h;
	if (n < SKP_IMAGE_BLOCK_HDR || !skp_image_header_get(block0 + SKP_IMAGE_BLOCK_HDR, n - SKP_IMAGE_BLOCK_HDR, &h))
		return 0;
	return block_size_ok(h.block_size) ? h.block_size : 0;
}

/* Images before version 4 carry no id (their blocks' frames were 12 bytes,
 * so their header starts at byte 12): refused by name, so the operator
 * knows to pack the show again rather than suspect the card. Their header
 * CRC must hold (104 bytes in version 1, 116 in 2 and 3), or it is damage. */
#define OLD_FRAME 12

static skp_status older_version(const uint8_t *block, uint32_t n, skp_error *err)
{
	const uint8_t *p = block + OLD_FRAME;
	if (n < OLD_FRAME + 12 || memcmp(p, SKP_IMAGE_MAGIC, 8))
		return SKP_OK;
	unsigned v = le_get16(p + 8), size = v == 1 ? 104 : 116;
	if (v < 1 || v >= SKP_IMAGE_VERSION_MIN || n < OLD_FRAME + size || le_get16(p + 10) != size ||
	    crc32_compute(p, size - 4) != le_get32(p + size - 4))
		return SKP_OK;
	return image_block_fail(err, SKP_ERR_CORRUPT, 0,
				"image format version %u (skintool 0.16 or older, without an image id): this build plays "
				"versions %d to %d; pack the show again", v, SKP_IMAGE_VERSION_MIN, SKP_IMAGE_VERSION);
}

/* Header checks that need no other block, in the order a reader must make
 * them: what it is, which version, whether it is intact, whether it fits.
 * valid: the header decoded whole (version, size and CRC right). */
static skp_status check_header(const skp_image *im, const uint8_t *p, uint32_t n, int valid, skp_error *err)
{
	const skp_image_header *h = &im->hdr;
	if (memcmp(p, SKP_IMAGE_MAGIC, 8))
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "not a skinplay image (no SKPIMAGE magic)");
	if (valid && h->block_size != im->dev->block_size)
		return skp_fail(err, SKP_ERR_RANGE, 0, "image block size %lu, storage opened with %lu",
				(unsigned long)h->block_size, (unsigned long)im->dev->block_size);
	if (h->version > SKP_IMAGE_VERSION)
		return skp_fail(err, SKP_ERR_CORRUPT, 0, "image format version %u, this build reads versions %d to %d",
				(unsigned)h->version, SKP_IMAGE_VERSION_MIN, SKP_IMAGE_VERSION);
	if (n + SKP_IMAGE_BLOCK_HDR < im->dev->block_size)
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "header block: short read");
	if (!skp_block_crc_ok(im->buf, im->dev->block_size))
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "header block: CRC mismatch");
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

static skp_status check_limits(const skp_image_header *h, skp_error *err)
{
	skp_status rc = limit(err, "bones", h->bones, SKP_MAX_BONES, "SKP_MAX_BONES");
	if (!rc) rc = limit(err, "dofs per frame", h->dofs, SKP_MAX_DOF, "SKP_MAX_DOF");
	if (!rc) rc = limit(err, "vertices", h->verts, SKP_MAX_VERTS, "SKP_MAX_VERTS");
	if (!rc) rc = limit(err, "triangles", h->tris, SKP_MAX_TRIS, "SKP_MAX_TRIS");
	if (!rc) rc = limit(err, "influences per vertex", h->influences, SKP_MAX_INFLUENCES, "SKP_MAX_INFLUENCES");
	if (!rc) rc = limit(err, "clips", h->clips, SKP_IMAGE_MAX_CLIPS, "SKP_IMAGE_MAX_CLIPS");
	return rc;
}

/* Version 7: the digest blocks, as many as the leaves need, end the data
 * blocks. */
static skp_status check_digest_layout(const skp_image_header *h, skp_error *err)
{
	uint32_t first = skp_digest_first(h);
	if (h->version < 7 || (first < h->data_blocks && skp_digest_blocks(first, h->block_size) == h->data_blocks - first))
		return SKP_OK;
	return skp_fail(err, SKP_ERR_CORRUPT, 0, "header: %lu data blocks, but the directory ends at block %lu and "
			"its %lu blocks' digests need %lu more", (unsigned long)h->data_blocks, (unsigned long)first,
			(unsigned long)first, (unsigned long)skp_digest_blocks(first, h->block_size));
}

/* Data, parity, the directory copy, then the header copy, which ends the
 * image; every section among the data blocks. 64-bit sums: a crafted count
 * near 2^32 cannot wrap into range. */
static skp_status check_layout(const skp_image_header *h, skp_error *err)
{
	uint64_t dir = h->sec[SKP_SEC_DIRECTORY].count, payload = h->block_size - SKP_IMAGE_BLOCK_EXTRA;
	if ((uint64_t)h->data_blocks + h->parity_blocks + dir + 1 != h->block_count || h->parity_blocks > h->data_blocks ||
	    (uint64_t)h->dir_copy != (uint64_t)h->data_blocks + h->parity_blocks || h->copy_block != h->block_count - 1 ||
	    dir == 0)
		return skp_fail(err, SKP_ERR_CORRUPT, 0,
				"header: %lu data, %lu parity and %lu directory copy blocks and a header copy do not make %lu",
				(unsigned long)h->data_blocks, (unsigned long)h->parity_blocks, (unsigned long)dir,
				(unsigned long)h->block_count);
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		const skp_image_section *s = &h->sec[i];
		if ((uint64_t)s->first + s->count > h->data_blocks ||
		    (i != SKP_SEC_CLIPS && (s->count * payload < s->bytes || s->first == 0)))
			return skp_fail(err, SKP_ERR_CORRUPT, 0, "header: section %d out of the image", i + 1);
	}
	return check_digest_layout(h, err);
}

/* The storage must hold every data block; what it lacks after them (the
 * header copy, the directory copy, parity) is counted, not refused. */
static skp_status check_storage(skp_image *im, skp_error *err)
{
	const skp_image_header *h = &im->hdr;
	uint32_t held = im->dev->block_count;
	if (held < h->data_blocks)
		return skp_fail(err, SKP_ERR_CORRUPT, 0,
				"image truncated: the header says %lu blocks (%lu of data), the storage holds %lu",
				(unsigned long)h->block_count, (unsigned long)h->data_blocks, (unsigned long)held);
	im->missing = held < h->block_count ? h->block_count - held : 0;
	return SKP_OK;
}

/* Version 5's fields of a directory entry (version 4: a quantised clip). */
static skp_status get_clip_v5(skp_image *im, skp_image_clip *c, skp_error *err)
{
	c->coded = 0;
	c->stream_bytes = c->segments = 0;
	c->shell_err = c->unit_cm = 0;
	if (im->hdr.version < 5)
		return SKP_OK;
	skp_status rc = sec_u8(im, &c->coded, err);
	if (!rc) rc = sec_u32(im, &c->stream_bytes, err);
	if (!rc) rc = sec_u32(im, &c->segments, err);
	if (!rc) rc = sec_floats(im, &c->shell_err, 1, err);
	if (!rc) rc = sec_floats(im, &c->unit_cm, 1, err);
	return rc;
}

/* The frames blocks hold what the entry says: whole frames (quantised) or
 * the stream's bytes (compressed), every block but the last full. */
static int frames_fit(const skp_image_clip *c, uint32_t room)
{
	uint32_t fpb = c->frames_per_block;
	if (c->coded > 1)
		return 0;
	if (c->coded)
		return fpb == 0 && c->segments > 0 && c->segments <= c->frame_count &&
		       (uint64_t)c->frame_blocks * room >= c->stream_bytes &&
		       (uint64_t)c->stream_bytes + room > (uint64_t)c->frame_blocks * room &&
		       isfinite(c->shell_err) && isfinite(c->unit_cm);
	return fpb != 0 && fpb * 2u * c->dofs <= room && (uint64_t)c->frame_blocks * fpb >= c->frame_count &&
	       (uint64_t)c->frame_count + fpb > (uint64_t)c->frame_blocks * fpb && c->stream_bytes == 0;
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
	if (!rc) rc = get_clip_v5(im, c, err);
	if (rc)
		return rc;
	c->first_number = (int32_t)first;
	uint32_t room = skp_image_stream_room(im->hdr.block_size);
	uint64_t quant = c->coded ? 4u + 9u * c->dofs + 4u * ((uint64_t)c->segments + 1u) : 8u * c->dofs;
	const skp_image_section *all = &im->hdr.sec[SKP_SEC_CLIPS];
	uint64_t end = (uint64_t)all->first + all->count;
	if (c->dofs != im->hdr.dofs || !frames_fit(c, room) || !(c->fps > 0) || !isfinite(c->fps) ||
	    c->quant_first < all->first || (uint64_t)c->quant_first + c->quant_blocks > end ||
	    (uint64_t)c->quant_blocks * (room + SKP_IMAGE_FRAMES_COUNT) < quant ||
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

/* The header from block 0, checked in full; *older when it is an older
 * version's (no copy of this version to look for). */
static skp_status header_from_block0(skp_image *im, int *older, skp_error *err)
{
	const skp_blockdev *dev = im->dev;
	int n = dev->read(dev->ctx, 0, im->buf);
	if (n == SKP_BD_ERANGE)
		n = 0; /* empty storage */
	if (n < 0)
		return image_block_fail(err, SKP_ERR_IO, 0, "header: I/O error");
	skp_status rc = older_version(im->buf, (uint32_t)n, err);
	*older = rc != SKP_OK;
	if (rc)
		return rc;
	if ((uint32_t)n < SKP_IMAGE_BLOCK_HDR + 12)
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "header: short read (empty or truncated image)");
	const uint8_t *p = im->buf + SKP_IMAGE_BLOCK_HDR;
	uint32_t len = (uint32_t)n - SKP_IMAGE_BLOCK_HDR;
	int valid = skp_image_header_get(p, len, &im->hdr);
	rc = check_header(im, p, len, valid, err);
	if (rc)
		return rc;
	skp_block_state st = skp_image_frame_check(im, 0, SKP_KIND_HEADER, 0, im->buf);
	if (st != SKP_BLOCK_OK)
		return image_block_fail(err, SKP_ERR_CORRUPT, 0, "header block: %s", skp_block_state_name(st));
	return SKP_OK;
}

/* Block 0 unusable: the header copy (image_copies.c), when there is one
 * made with the storage's block size. An older image or another block size
 * keeps block 0's message. */
static skp_status header_from_copy(skp_image *im, skp_status rc0)
{
	skp_image_header h;
	if (rc0 == SKP_ERR_RANGE)
		return rc0;
	/* nothing of block 0's header is kept: its block size, damaged, would
	 * have every block read short */
	memset(&im->hdr, 0, sizeof im->hdr);
	im->hdr.block_size = im->dev->block_size;
	if (!skp_image_copy_header(im, &h)) {
		if (!skp_image_parity_header(im, &h))
			return rc0;
		im->header_from_parity = 1;
	}
	im->hdr = h;
	im->header_from_copy = 1;
	if (im->on_rebuild)
		im->on_rebuild(im->on_rebuild_ctx, 0);
	return SKP_OK;
}

#define HEADER_WITNESSES 3 /* data blocks after block 0 asked whose the image is */

/* Whose blocks 1..HEADER_WITNESSES are: *own of them carry the header's
 * id, *other a whole block of another id (kept in other_id). */
static void witnesses(skp_image *im, int *own, int *other, uint8_t *other_id)
{
	*own = *other = 0;
	for (uint32_t b = 1; b <= HEADER_WITNESSES && b < im->hdr.data_blocks; b++) {
		if (skp_image_read_raw(im, b, im->buf) != SKP_BLOCK_OK || !skp_block_crc_ok(im->buf, im->hdr.block_size))
			continue;
		if (!memcmp(im->buf, im->hdr.id, SKP_IMAGE_ID_BYTES)) {
			(*own)++;
		} else {
			(*other)++;
			memcpy(other_id, im->buf, SKP_IMAGE_ID_BYTES);
		}
	}
}

/* A whole block 0 may still be another image's: copied in with a good CRC,
 * or an in-place write of another pack cut short after a block or two. The
 * blocks after it say whose the image is: when more of them carry another
 * id than block 0's, and the header copy is that image's, the copy's header
 * is the image's. */
static void header_confirm(skp_image *im)
{
	uint8_t id[SKP_IMAGE_ID_BYTES];
	skp_image_header h;
	int own, other;
	witnesses(im, &own, &other, id);
	if (other <= own || !skp_image_copy_header(im, &h) || memcmp(h.id, id, sizeof id))
		return;
	im->hdr = h;
	im->header_from_copy = 1;
	if (im->on_rebuild)
		im->on_rebuild(im->on_rebuild_ctx, 0);
}

skp_status skp_image_open(skp_image *im, const skp_blockdev *dev, skp_error *err)
{
	skp_error_clear(err);
	memset(&im->hdr, 0, sizeof im->hdr);
	im->dev = dev;
	im->clip_count = 0;
	im->rebuilt = 0;
	im->rebuilt_from = "parity";
	im->header_from_copy = 0;
	im->header_from_parity = 0;
	im->missing = 0;
	im->digests = 0;
	im->digest_first = 0;
	im->leaves_at = UINT32_MAX;
	if (!block_size_ok(dev->block_size))
		return skp_fail(err, SKP_ERR_RANGE, 0, "storage block size %lu: expected a multiple of 16 from %d to %d",
				(unsigned long)dev->block_size, SKP_IMAGE_MIN_BLOCK, SKP_IMAGE_BLOCK_SIZE);
	int older = 0;
	skp_status rc = header_from_block0(im, &older, err);
	if (rc && !older && header_from_copy(im, rc) == SKP_OK) {
		skp_error_clear(err);
		rc = SKP_OK;
	} else if (!rc) {
		header_confirm(im);
	}
	if (!rc) rc = check_limits(&im->hdr, err);
	if (!rc) rc = check_layout(&im->hdr, err);
	if (!rc) rc = check_storage(im, err);
	if (!rc) rc = skp_image_digests_open(im, err);
	return rc ? rc : load_directory(im, err);
}

int skp_image_find_clip(const skp_image *im, const char *name)
{
	for (int i = 0; i < im->clip_count; i++)
		if (strcmp(im->clip[i].name, name) == 0)
			return i;
	return -1;
}
