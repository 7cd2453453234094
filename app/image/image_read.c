#include "image_read.h"

#include <string.h>

#include "crc32.h"

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

void skp_image_header_get(const uint8_t *p, skp_image_header *h)
{
	h->version = le_get16(p + 8);
	h->header_size = le_get16(p + 10);
	h->block_size = le_get32(p + 12);
	h->block_count = le_get32(p + 16);
	h->sequence = le_get64(p + 20);
	h->bones = le_get32(p + 28);
	h->dofs = le_get32(p + 32);
	h->verts = le_get32(p + 36);
	h->tris = le_get32(p + 40);
	h->influences = le_get32(p + 44);
	h->clips = le_get32(p + 48);
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		h->sec[i].first = le_get32(p + 52 + 12 * i);
		h->sec[i].count = le_get32(p + 56 + 12 * i);
		h->sec[i].bytes = le_get32(p + 60 + 12 * i);
	}
	h->crc = le_get32(p + 100);
}

static skp_block_state check_block(const skp_image *im, uint32_t block, int kind, unsigned item,
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

skp_block_state skp_image_read_block(skp_image *im, uint32_t block, int kind, unsigned item,
				     uint8_t *buf)
{
	int n = im->dev->read(im->dev->ctx, block, buf);
	if (n < 0)
		return n == SKP_BD_ERANGE ? SKP_BLOCK_SHORT : SKP_BLOCK_IO;
	if ((uint32_t)n < im->hdr.block_size)
		return SKP_BLOCK_SHORT;
	return check_block(im, block, kind, item, buf);
}

static skp_status block_fail(skp_error *err, skp_status code, uint32_t block, const char *fmt,
			     const char *what, const char *why)
{
	skp_fail(err, code, 0, fmt, what, why);
	if (err)
		err->block = (long)block;
	return code;
}

/* Header checks that need no other block, in the order a reader must make
 * them: what it is, whether it is intact, which version, whether it fits. */
static skp_status check_header(const skp_image *im, const uint8_t *p, int n, skp_error *err)
{
	const skp_image_header *h = &im->hdr;
	uint32_t bs = im->dev->block_size;
	int header_ok = crc32_compute(p, SKP_IMAGE_HEADER_SIZE - 4) == h->crc;
	if (memcmp(p, SKP_IMAGE_MAGIC, 8))
		return block_fail(err, SKP_ERR_CORRUPT, 0, "%s%s", "not a skinplay image ",
				  "(no SKPIMAGE magic in block 0)");
	if (header_ok && h->block_size != bs)
		return skp_fail(err, SKP_ERR_RANGE, 0, "image block size %lu, storage opened with %lu",
				(unsigned long)h->block_size, (unsigned long)bs);
	if ((uint32_t)n < bs)
		return block_fail(err, SKP_ERR_CORRUPT, 0, "%s%s", "header block: ", "short read");
	if (!skp_block_crc_ok(im->buf, bs))
		return block_fail(err, SKP_ERR_CORRUPT, 0, "%s%s", "header block: ", "CRC mismatch");
	if (h->version != SKP_IMAGE_VERSION)
		return skp_fail(err, SKP_ERR_CORRUPT, 0, "image format version %u, this build reads version %d",
				(unsigned)h->version, SKP_IMAGE_VERSION);
	if (h->header_size != SKP_IMAGE_HEADER_SIZE)
		return skp_fail(err, SKP_ERR_CORRUPT, 0, "header size %u, expected %d", (unsigned)h->header_size,
				SKP_IMAGE_HEADER_SIZE);
	if (!header_ok)
		return block_fail(err, SKP_ERR_CORRUPT, 0, "%s%s", "header ", "CRC mismatch");
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
	for (int i = 0; i < SKP_SEC_COUNT; i++) {
		const skp_image_section *s = &h->sec[i];
		uint32_t payload = h->block_size - SKP_IMAGE_BLOCK_EXTRA;
		if (s->first + s->count > h->block_count || s->first + s->count < s->first ||
		    (i != SKP_SEC_CLIPS && ((uint64_t)s->count * payload < s->bytes || s->first == 0)))
			return skp_fail(err, SKP_ERR_CORRUPT, 0, "header: section %d out of the image", i + 1);
	}
	return SKP_OK;
}

static void sec_open(skp_image *im, const skp_image_section *sec, uint8_t kind, uint16_t item)
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

/* n bytes of the open section, across its blocks. */
static skp_status sec_get(skp_image *im, void *out, uint32_t n, skp_error *err)
{
	uint8_t *o = out;
	uint32_t payload = im->hdr.block_size - SKP_IMAGE_BLOCK_EXTRA;
	const char *what = kind_names[im->s_kind];
	if (n > im->s_left)
		return block_fail(err, SKP_ERR_CORRUPT, im->s_block, "%s section ends early%s", what, "");
	while (n > 0) {
		if (im->s_pos == payload) {
			if (im->s_block >= im->s_end)
				return block_fail(err, SKP_ERR_CORRUPT, im->s_block, "%s section ends early%s", what, "");
			skp_block_state st = skp_image_read_block(im, im->s_block, im->s_kind, im->s_item, im->buf);
			if (st != SKP_BLOCK_OK)
				return block_fail(err, st == SKP_BLOCK_IO ? SKP_ERR_IO : SKP_ERR_CORRUPT, im->s_block,
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

/* The block the stream's last bytes came from, for messages. */
static long sec_block(const skp_image *im)
{
	return im->s_pos == 0 ? (long)im->s_block : (long)im->s_block - 1;
}

static skp_status sec_bad(skp_image *im, skp_error *err, const char *what)
{
	skp_fail(err, SKP_ERR_CORRUPT, 0, "%s section: %s", kind_names[im->s_kind], what);
	if (err)
		err->block = sec_block(im);
	return SKP_ERR_CORRUPT;
}

static skp_status get_u8(skp_image *im, uint8_t *v, skp_error *err)
{
	return sec_get(im, v, 1, err);
}

static skp_status get_u16(skp_image *im, uint16_t *v, skp_error *err)
{
	uint8_t b[2] = { 0, 0 }; /* decoded even when the read failed */
	skp_status rc = sec_get(im, b, 2, err);
	*v = le_get16(b);
	return rc;
}

static skp_status get_u32(skp_image *im, uint32_t *v, skp_error *err)
{
	uint8_t b[4] = { 0, 0, 0, 0 }; /* decoded even when the read failed */
	skp_status rc = sec_get(im, b, 4, err);
	*v = le_get32(b);
	return rc;
}

static skp_status get_floats(skp_image *im, float *v, int n, skp_error *err)
{
	skp_status rc = SKP_OK;
	for (int i = 0; i < n && !rc; i++) {
		uint32_t u;
		rc = get_u32(im, &u, err);
		memcpy(&v[i], &u, 4);
	}
	return rc;
}

static skp_status get_str(skp_image *im, char *s, skp_error *err)
{
	uint8_t n;
	skp_status rc = get_u8(im, &n, err);
	if (rc)
		return rc;
	if (n >= SKP_MAX_NAME)
		return sec_bad(im, err, "name longer than SKP_MAX_NAME");
	rc = sec_get(im, s, n, err);
	s[n] = '\0';
	return rc;
}

static skp_status get_clip(skp_image *im, skp_image_clip *c, skp_error *err)
{
	uint32_t first;
	skp_status rc = get_str(im, c->name, err);
	if (!rc) rc = get_floats(im, &c->fps, 1, err);
	if (!rc) rc = get_u32(im, &c->frame_count, err);
	if (!rc) rc = get_u32(im, &first, err);
	if (!rc) rc = get_u16(im, &c->dofs, err);
	if (!rc) rc = get_u16(im, &c->frames_per_block, err);
	if (!rc) rc = get_u32(im, &c->quant_first, err);
	if (!rc) rc = get_u32(im, &c->quant_blocks, err);
	if (!rc) rc = get_u32(im, &c->frames_first, err);
	if (!rc) rc = get_u32(im, &c->frame_blocks, err);
	if (!rc) rc = get_floats(im, &c->max_rot_err, 1, err);
	if (!rc) rc = get_floats(im, &c->max_trans_err, 1, err);
	if (rc)
		return rc;
	c->first_number = (int32_t)first;
	uint32_t payload = im->hdr.block_size - SKP_IMAGE_BLOCK_EXTRA, fpb = c->frames_per_block;
	const skp_image_section *all = &im->hdr.sec[SKP_SEC_CLIPS];
	if (c->dofs != im->hdr.dofs || fpb == 0 || fpb * 2u * c->dofs > payload || !(c->fps > 0) ||
	    (uint64_t)c->frame_blocks * fpb < c->frame_count ||
	    c->quant_first < all->first || c->quant_first + c->quant_blocks > all->first + all->count ||
	    c->frames_first < all->first || c->frames_first + c->frame_blocks > all->first + all->count)
		return sec_bad(im, err, "clip entry out of the image");
	return SKP_OK;
}

static skp_status load_directory(skp_image *im, skp_error *err)
{
	uint16_t n;
	sec_open(im, &im->hdr.sec[SKP_SEC_DIRECTORY], SKP_KIND_DIRECTORY, 0);
	skp_status rc = get_u16(im, &n, err);
	if (rc)
		return rc;
	if (n != im->hdr.clips)
		return sec_bad(im, err, "clip count differs from the header's");
	for (int i = 0; i < n && !rc; i++)
		rc = get_clip(im, &im->clip[i], err);
	im->clip_count = rc ? 0 : n;
	return rc;
}

skp_status skp_image_open(skp_image *im, const skp_blockdev *dev, skp_error *err)
{
	skp_error_clear(err);
	memset(&im->hdr, 0, sizeof im->hdr);
	im->dev = dev;
	im->clip_count = 0;
	if (dev->block_size < SKP_IMAGE_MIN_BLOCK || dev->block_size > SKP_IMAGE_BLOCK_SIZE)
		return skp_fail(err, SKP_ERR_RANGE, 0, "storage block size %lu: expected %d..%d",
				(unsigned long)dev->block_size, SKP_IMAGE_MIN_BLOCK, SKP_IMAGE_BLOCK_SIZE);
	int n = dev->read(dev->ctx, 0, im->buf);
	if (n == SKP_BD_ERANGE)
		n = 0; /* empty storage */
	if (n < 0)
		return block_fail(err, SKP_ERR_IO, 0, "%s%s", "header: ", "I/O error");
	if ((uint32_t)n < SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_HEADER_SIZE)
		return block_fail(err, SKP_ERR_CORRUPT, 0, "%s%s", "header: ", "short read (empty or truncated image)");
	const uint8_t *p = im->buf + SKP_IMAGE_BLOCK_HDR;
	skp_image_header_get(p, &im->hdr);
	skp_status rc = check_header(im, p, n, err);
	if (rc)
		return rc;
	im->tag = skp_image_tag(im->hdr.sequence);
	skp_block_state st = check_block(im, 0, SKP_KIND_HEADER, 0, im->buf);
	if (st != SKP_BLOCK_OK)
		return block_fail(err, SKP_ERR_CORRUPT, 0, "%s%s", "header block: ", skp_block_state_name(st));
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

static skp_status check_bone(skp_image *im, const skel *s, int i, int *dof, skp_error *err)
{
	const skel_bone *b = &s->bone[i];
	if (i == 0 ? b->parent != -1 : (b->parent < 0 || b->parent >= s->count))
		return sec_bad(im, err, "bone parent out of range");
	if (b->channel_count > SKEL_MAX_CHANNELS || b->dof_offset != *dof)
		return sec_bad(im, err, "bone channels do not add up");
	for (int c = 0; c < b->channel_count; c++)
		if (b->channel[c] > SKEL_L)
			return sec_bad(im, err, "unknown channel");
	for (int a = 0; a < 3; a++)
		if (b->axis_order[a] > 2)
			return sec_bad(im, err, "unknown rotation axis");
	*dof += b->channel_count;
	return SKP_OK;
}

static skp_status get_bone(skp_image *im, skel_bone *b, skp_error *err)
{
	/* zeroed: the bone is filled below even when a read failed */
	uint32_t id = 0;
	uint16_t parent = 0;
	float rot[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
	skp_status rc = get_str(im, b->name, err);
	if (!rc) rc = get_u32(im, &id, err);
	if (!rc) rc = get_u16(im, &parent, err);
	if (!rc) rc = get_floats(im, &b->direction.x, 3, err);
	if (!rc) rc = get_floats(im, &b->length, 1, err);
	if (!rc) rc = get_floats(im, &b->axis_angle.x, 3, err);
	if (!rc) rc = sec_get(im, b->axis_order, 3, err);
	if (!rc) rc = get_u8(im, &b->channel_count, err);
	if (rc)
		return rc;
	if (b->channel_count > SKEL_MAX_CHANNELS)
		return sec_bad(im, err, "more than 7 channels on a bone");
	rc = sec_get(im, b->channel, b->channel_count, err);
	if (!rc) rc = get_u8(im, &b->has_limits, err);
	for (int i = 0; i < b->channel_count && !rc; i++)
		rc = get_floats(im, b->limit[i], 2, err);
	if (!rc) rc = get_u16(im, &b->dof_offset, err);
	if (!rc) rc = get_floats(im, rot, 4, err);
	b->id = (long)(int32_t)id;
	b->parent = (int16_t)parent;
	b->axis_rot.w = rot[0];
	b->axis_rot.x = rot[1];
	b->axis_rot.y = rot[2];
	b->axis_rot.z = rot[3];
	return rc;
}

/* Parents before children in eval_order, every bone once. */
static skp_status check_order(skp_image *im, const skel *s, skp_error *err)
{
	uint8_t placed[SKP_MAX_BONES] = { 0 };
	for (int i = 0; i < s->count; i++) {
		int b = s->eval_order[i];
		if (b >= s->count || placed[b] || (b != 0 && !placed[s->bone[b].parent]) || (i == 0) != (b == 0))
			return sec_bad(im, err, "bone order is not parents first");
		placed[b] = 1;
	}
	return SKP_OK;
}

skp_status skp_image_load_skel(skp_image *im, skel *s, skp_error *err)
{
	uint16_t count, dofs;
	memset(s, 0, sizeof *s);
	sec_open(im, &im->hdr.sec[SKP_SEC_SKELETON], SKP_KIND_SKELETON, 0);
	skp_status rc = get_str(im, s->name, err);
	if (!rc) rc = get_u8(im, (uint8_t *)s->version, err);
	if (!rc) {
		uint8_t n = (uint8_t)s->version[0];
		if (n >= sizeof s->version)
			return sec_bad(im, err, "version longer than 15 bytes");
		rc = sec_get(im, s->version, n, err);
		s->version[n] = '\0';
	}
	if (!rc) rc = get_floats(im, &s->length_scale, 1, err);
	if (!rc) rc = get_floats(im, &s->mass_scale, 1, err);
	if (!rc) rc = get_u8(im, &s->angle_in_degrees, err);
	if (!rc) rc = get_floats(im, &s->root_position.x, 3, err);
	if (!rc) rc = get_u16(im, &count, err);
	if (!rc) rc = get_u16(im, &dofs, err);
	if (rc)
		return rc;
	if (count < 1 || count > SKP_MAX_BONES || count != im->hdr.bones || dofs != im->hdr.dofs)
		return sec_bad(im, err, "bone or dof count differs from the header's");
	s->count = count;
	s->dof_count = dofs;
	rc = sec_get(im, s->eval_order, count, err);
	for (int i = 0; i < count && !rc; i++)
		rc = get_bone(im, &s->bone[i], err);
	int dof = 0;
	for (int i = 0; i < count && !rc; i++)
		rc = check_bone(im, s, i, &dof, err);
	if (!rc && dof != s->dof_count)
		return sec_bad(im, err, "dof count differs from the bones' channels");
	return rc ? rc : check_order(im, s, err);
}

static skp_status get_influences(skp_image *im, const skel *s, skin_weights *w, int v, skp_error *err)
{
	uint8_t rec[1 + 4 * SKP_MAX_INFLUENCES];
	skp_status rc = sec_get(im, rec, sizeof rec, err);
	if (rc)
		return rc;
	int n = rec[0];
	uint32_t sum = 0;
	if (n < 1 || n > SKP_MAX_INFLUENCES)
		return sec_bad(im, err, "influence count not 1..4");
	w->count[v] = (uint8_t)n;
	for (int i = 0; i < SKP_MAX_INFLUENCES; i++) {
		uint16_t bone = le_get16(rec + 1 + 2 * i), q = le_get16(rec + 1 + 2 * SKP_MAX_INFLUENCES + 2 * i);
		if (i < n && bone >= s->count)
			return sec_bad(im, err, "influence on a bone the skeleton does not have");
		w->bone[v][i] = i < n ? bone : 0;
		w->weight[v][i] = i < n ? (float)q / (float)SKP_IMAGE_QMAX : 0.0f;
		sum += i < n ? q : 0;
	}
	return sum == SKP_IMAGE_QMAX ? SKP_OK : sec_bad(im, err, "weights do not sum to 65535");
}

static skp_status get_mesh(skp_image *im, mesh *m, skp_error *err)
{
	skp_status rc = SKP_OK;
	for (int v = 0; v < m->vert_count && !rc; v++)
		rc = get_floats(im, &m->pos[v].x, 3, err);
	for (int v = 0; v < m->vert_count && !rc; v++)
		rc = get_floats(im, &m->normal[v].x, 3, err);
	for (int t = 0; t < m->tri_count && !rc; t++) {
		for (int k = 0; k < 3 && !rc; k++)
			rc = get_u32(im, &m->tri[t][k], err);
		if (!rc && (m->tri[t][0] >= (uint32_t)m->vert_count || m->tri[t][1] >= (uint32_t)m->vert_count ||
			    m->tri[t][2] >= (uint32_t)m->vert_count))
			return sec_bad(im, err, "triangle index beyond the vertices");
	}
	return rc;
}

skp_status skp_image_load_bind(skp_image *im, const skel *s, mesh *m, skin_weights *w,
			       float *bind_values, long *bind_number, skp_error *err)
{
	uint32_t verts, tris, number;
	uint8_t posed;
	sec_open(im, &im->hdr.sec[SKP_SEC_BIND], SKP_KIND_BIND, 0);
	skp_status rc = get_u32(im, &verts, err);
	if (!rc) rc = get_u32(im, &tris, err);
	if (!rc) rc = get_u8(im, &posed, err);
	if (!rc) rc = get_u32(im, &number, err);
	if (rc)
		return rc;
	if (verts != im->hdr.verts || tris != im->hdr.tris || verts > SKP_MAX_VERTS || tris > SKP_MAX_TRIS ||
	    posed > 1)
		return sec_bad(im, err, "vertex or triangle count differs from the header's");
	memset(bind_values, 0, sizeof(float) * SKP_MAX_DOF);
	*bind_number = posed ? (long)(int32_t)number : -1;
	if (posed && (rc = get_floats(im, bind_values, s->dof_count, err)) != SKP_OK)
		return rc;
	m->vert_count = (int)verts;
	m->tri_count = (int)tris;
	w->vert_count = (int)verts;
	rc = get_mesh(im, m, err);
	for (int v = 0; v < m->vert_count && !rc; v++)
		rc = get_influences(im, s, w, v, err);
	return rc;
}

skp_status skp_image_load_quant(skp_image *im, int clip, float *qmin, float *qstep, skp_error *err)
{
	const skp_image_clip *c = &im->clip[clip];
	skp_image_section sec = { c->quant_first, c->quant_blocks, 8u * c->dofs };
	sec_open(im, &sec, SKP_KIND_QUANT, (uint16_t)clip);
	skp_status rc = SKP_OK;
	for (int i = 0; i < c->dofs && !rc; i++) {
		rc = get_floats(im, &qmin[i], 1, err);
		if (!rc)
			rc = get_floats(im, &qstep[i], 1, err);
		if (!rc && !(qstep[i] >= 0))
			return sec_bad(im, err, "negative quantisation step");
	}
	return rc;
}
