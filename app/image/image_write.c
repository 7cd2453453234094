#include "image_write.h"

#include <math.h>
#include <string.h>

#include "crc32.h"
#include "image_copies.h"
#include "image_digests.h"
#include "image_parity.h"
#include "image_error.h"
#include "image_write_internal.h"
#include "skin_compact.h"

/* Frames the block, CRCs it and writes it at the next position. */
skp_status image_flush_block(skp_image_writer *w, skp_error *err)
{
	uint8_t *b = w->block;
	uint32_t index = w->next_block++;
	skp_block_frame(b, w->hdr.id, index, w->kind, w->item);
	skp_block_seal(b, w->bs);
	sha256_update(&w->digest, b, w->bs);
	if (w->dev->write(w->dev->ctx, index, b) < 0)
		return image_block_fail(err, SKP_ERR_IO, index, "cannot write it");
	memset(b, 0, w->bs);
	w->fill = 0;
	return SKP_OK;
}

void image_sec_begin(skp_image_writer *w, uint8_t kind, uint16_t item)
{
	w->kind = kind;
	w->item = item;
	w->sec_first = w->next_block;
	w->sec_bytes = 0;
	w->fill = 0;
	memset(w->block, 0, w->bs);
}

/* Appends bytes to the current byte-stream section, across blocks. */
static skp_status put(skp_image_writer *w, const void *data, uint32_t n, skp_error *err)
{
	const uint8_t *p = data;
	while (n > 0) {
		uint32_t room = w->payload - w->fill, k = n < room ? n : room;
		memcpy(w->block + SKP_IMAGE_BLOCK_HDR + w->fill, p, k);
		w->fill += k;
		w->sec_bytes += k;
		p += k;
		n -= k;
		if (w->fill == w->payload && image_flush_block(w, err) != SKP_OK)
			return SKP_ERR_IO;
	}
	return SKP_OK;
}

/* Ends the section: the partial last block is written; returns its extent. */
skp_status image_sec_end(skp_image_writer *w, skp_image_section *out, skp_error *err)
{
	if (w->fill > 0 && image_flush_block(w, err) != SKP_OK)
		return SKP_ERR_IO;
	if (out) {
		out->first = w->sec_first;
		out->count = w->next_block - w->sec_first;
		out->bytes = w->sec_bytes;
	}
	return SKP_OK;
}

skp_status image_put_u8(skp_image_writer *w, unsigned v, skp_error *err)
{
	uint8_t b = (uint8_t)v;
	return put(w, &b, 1, err);
}

skp_status image_put_u16(skp_image_writer *w, unsigned v, skp_error *err)
{
	uint8_t b[2];
	le_put16(b, (uint16_t)v);
	return put(w, b, 2, err);
}

skp_status image_put_u32(skp_image_writer *w, uint32_t v, skp_error *err)
{
	uint8_t b[4];
	le_put32(b, v);
	return put(w, b, 4, err);
}

skp_status image_put_f32(skp_image_writer *w, float v, skp_error *err)
{
	uint32_t u;
	memcpy(&u, &v, 4);
	return image_put_u32(w, u, err);
}

static skp_status put_floats(skp_image_writer *w, const float *v, int n, skp_error *err)
{
	skp_status rc = SKP_OK;
	for (int i = 0; i < n && rc == SKP_OK; i++)
		rc = image_put_f32(w, v[i], err);
	return rc;
}

static skp_status put_str(skp_image_writer *w, const char *s, skp_error *err)
{
	size_t n = strlen(s);
	if (n >= SKP_MAX_NAME)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "name '%s' longer than %d bytes (board limit SKP_MAX_NAME)",
				s, SKP_MAX_NAME - 1);
	skp_status rc = image_put_u8(w, (unsigned)n, err);
	return rc ? rc : put(w, s, (uint32_t)n, err);
}

static skp_status put_bone(skp_image_writer *w, const skel_bone *b, skp_error *err)
{
	float rot[4] = { b->axis_rot.w, b->axis_rot.x, b->axis_rot.y, b->axis_rot.z };
	float dir[3] = { b->direction.x, b->direction.y, b->direction.z };
	float ax[3] = { b->axis_angle.x, b->axis_angle.y, b->axis_angle.z };
	skp_status rc = put_str(w, b->name, err);
	if (!rc) rc = image_put_u32(w, (uint32_t)(int32_t)b->id, err);
	if (!rc) rc = image_put_u16(w, (uint16_t)(int16_t)b->parent, err);
	if (!rc) rc = put_floats(w, dir, 3, err);
	if (!rc) rc = image_put_f32(w, b->length, err);
	if (!rc) rc = put_floats(w, ax, 3, err);
	if (!rc) rc = put(w, b->axis_order, 3, err);
	if (!rc) rc = image_put_u8(w, b->channel_count, err);
	if (!rc) rc = put(w, b->channel, b->channel_count, err);
	if (!rc) rc = image_put_u8(w, b->has_limits, err);
	for (int i = 0; i < b->channel_count && !rc; i++)
		rc = put_floats(w, b->limit[i], 2, err);
	if (!rc) rc = image_put_u16(w, b->dof_offset, err);
	if (!rc) rc = put_floats(w, rot, 4, err);
	float off[3] = { b->offset.x, b->offset.y, b->offset.z };
	return rc ? rc : put_floats(w, off, 3, err);
}

static skp_status put_skel(skp_image_writer *w, const skel *s, skp_error *err)
{
	float root[3] = { s->root_position.x, s->root_position.y, s->root_position.z };
	skp_status rc = put_str(w, s->name, err);
	if (!rc) rc = put_str(w, s->version, err);
	if (!rc) rc = image_put_f32(w, s->length_scale, err);
	if (!rc) rc = image_put_f32(w, s->mass_scale, err);
	if (!rc) rc = image_put_u8(w, s->angle_in_degrees, err);
	if (!rc) rc = put_floats(w, root, 3, err);
	if (!rc) rc = image_put_u16(w, (unsigned)s->count, err);
	if (!rc) rc = image_put_u16(w, (unsigned)s->dof_count, err);
	if (!rc) rc = put(w, s->eval_order, (uint32_t)s->count, err);
	for (int i = 0; i < s->count && !rc; i++)
		rc = put_bone(w, &s->bone[i], err);
	return rc;
}

skp_status skp_image_write_begin(skp_image_writer *w, skp_blockdev *dev, uint64_t sequence,
				 const uint8_t id[SKP_IMAGE_ID_BYTES], const skel *s, skp_error *err)
{
	uint32_t bs = dev->block_size;
	skp_error_clear(err);
	if (bs < SKP_IMAGE_MIN_BLOCK || bs > SKP_IMAGE_BLOCK_SIZE || bs % 16)
		return skp_fail(err, SKP_ERR_RANGE, 0,
				"block size %lu: expected a multiple of 16 from %d to %d (board limit SKP_IMAGE_BLOCK_SIZE)",
				(unsigned long)bs, SKP_IMAGE_MIN_BLOCK, SKP_IMAGE_BLOCK_SIZE);
	if (!dev->write)
		return skp_fail(err, SKP_ERR_IO, 0, "the storage is read-only");
	memset(&w->hdr, 0, sizeof w->hdr);
	w->dev = dev;
	w->s = s;
	w->bs = bs;
	w->payload = bs - SKP_IMAGE_BLOCK_EXTRA;
	memcpy(w->hdr.id, id, SKP_IMAGE_ID_BYTES);
	sha256_init(&w->digest);
	w->next_block = 1; /* block 0, the header, comes last */
	w->clip_count = 0;
	w->clip = NULL;
	w->parity_group = 0;
	w->hdr.version = SKP_IMAGE_VERSION;
	w->hdr.header_size = SKP_IMAGE_HEADER_SIZE;
	w->hdr.block_size = bs;
	w->hdr.sequence = sequence;
	w->hdr.bones = (uint32_t)s->count;
	w->hdr.dofs = (uint32_t)s->dof_count;
	w->hdr.influences = SKP_MAX_INFLUENCES;
	image_sec_begin(w, SKP_KIND_SKELETON, 0);
	skp_status rc = put_skel(w, s, err);
	return rc ? rc : image_sec_end(w, &w->hdr.sec[SKP_SEC_SKELETON], err);
}

/* Weights in 1/65535, the used ones summing to exactly 65535: round down,
 * then hand the remainder to the largest fractions. */
static void quantise_weights(const float *wf, int n, uint16_t *q)
{
	double sum = 0, frac[SKP_MAX_INFLUENCES];
	for (int i = 0; i < n; i++)
		sum += wf[i] > 0 ? wf[i] : 0;
	long left = SKP_IMAGE_QMAX;
	for (int i = 0; i < n; i++) {
		double x = sum > 0 ? (wf[i] > 0 ? wf[i] : 0) / sum * SKP_IMAGE_QMAX : (i == 0 ? SKP_IMAGE_QMAX : 0);
		q[i] = (uint16_t)floor(x);
		frac[i] = x - q[i];
		left -= q[i];
	}
	while (left-- > 0) {
		int best = 0;
		for (int i = 1; i < n; i++)
			if (frac[i] > frac[best])
				best = i;
		q[best]++;
		frac[best] = -1;
	}
}

static skp_status put_influences(skp_image_writer *w, const skin_weights *wt, int v, skp_error *err)
{
	uint8_t rec[SKP_IMAGE_INFLUENCE_BYTES] = { 0 };
	uint16_t q[SKP_MAX_INFLUENCES] = { 0 };
	int n = wt->count[v];
	quantise_weights(wt->weight[v], n, q);
	rec[0] = (uint8_t)n;
	for (int i = 0; i < n; i++) {
		rec[1 + i] = (uint8_t)wt->bone[v][i];
		le_put16(rec + 1 + SKP_MAX_INFLUENCES + 2 * i, q[i]);
	}
	return put(w, rec, sizeof rec, err);
}

/* Positions as 16-bit steps over the mesh's bounds, normals as octahedral
 * pairs (skin_compact.h), then the triangles. */
static skp_status put_mesh(skp_image_writer *w, const mesh *m, skp_error *err)
{
	_Static_assert(sizeof(vec3) == 3 * sizeof(float), "positions are read 3 floats apart");
	float origin[3], step[3];
	for (int i = 0; i < 3; i++)
		skin_quant_bounds(&m->pos[0].x + i, m->vert_count, 3, &origin[i], &step[i]);
	skp_status rc = put_floats(w, origin, 3, err);
	if (!rc) rc = put_floats(w, step, 3, err);
	for (int v = 0; v < m->vert_count && !rc; v++) {
		uint8_t rec[6];
		const float p[3] = { m->pos[v].x, m->pos[v].y, m->pos[v].z };
		for (int i = 0; i < 3; i++)
			le_put16(rec + 2 * i, skin_quantise(p[i], origin[i], step[i]));
		rc = put(w, rec, sizeof rec, err);
	}
	for (int v = 0; v < m->vert_count && !rc; v++) {
		uint8_t rec[4];
		int16_t ox, oy;
		skin_oct_encode(m->normal[v], &ox, &oy);
		le_put16(rec, (uint16_t)ox);
		le_put16(rec + 2, (uint16_t)oy);
		rc = put(w, rec, sizeof rec, err);
	}
	for (int t = 0; t < m->tri_count && !rc; t++)
		for (int k = 0; k < 3 && !rc; k++)
			rc = image_put_u32(w, m->tri[t][k], err);
	return rc;
}

static skp_status check_weights(const skp_image_writer *w, const skin_weights *wt, int verts,
				skp_error *err)
{
	if (wt->vert_count != verts)
		return skp_fail(err, SKP_ERR_RANGE, 0, "%d weighted vertices for a mesh of %d",
				wt->vert_count, verts);
	for (int v = 0; v < verts; v++) {
		if (wt->count[v] < 1 || wt->count[v] > SKP_MAX_INFLUENCES)
			return skp_fail(err, SKP_ERR_RANGE, 0, "vertex %d has %d influences (1..%d)", v,
					wt->count[v], SKP_MAX_INFLUENCES);
		for (int i = 0; i < wt->count[v]; i++)
			if (wt->bone[v][i] >= w->s->count)
				return skp_fail(err, SKP_ERR_RANGE, 0, "vertex %d: bone %d of %d", v,
						wt->bone[v][i], w->s->count);
	}
	return SKP_OK;
}

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
		rc = put(w, rec, sizeof rec, err);
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
	return rc ? rc : put(w, t->etc1, (uint32_t)t->chain.etc1_bytes, err);
}

/* Version 8's end of the bind section: the texture coordinates in 16-bit
 * steps over their bounds, which vertices sample, the ETC1 mip chain. */
static skp_status put_texture(skp_image_writer *w, const mesh *m, skp_error *err)
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

skp_status skp_image_write_bind(skp_image_writer *w, const mesh *m, const skin_weights *wt,
				const float *bind_values, long bind_number, skp_error *err)
{
	skp_status rc = check_weights(w, wt, m->vert_count, err);
	if (rc)
		return rc;
	w->hdr.verts = (uint32_t)m->vert_count;
	w->hdr.tris = (uint32_t)m->tri_count;
	image_sec_begin(w, SKP_KIND_BIND, 0);
	rc = image_put_u32(w, (uint32_t)m->vert_count, err);
	if (!rc) rc = image_put_u32(w, (uint32_t)m->tri_count, err);
	if (!rc) rc = image_put_u8(w, bind_values != NULL, err);
	if (!rc) rc = image_put_u32(w, (uint32_t)(int32_t)(bind_values ? bind_number : -1), err);
	if (!rc && bind_values)
		rc = put_floats(w, bind_values, w->s->dof_count, err);
	if (!rc)
		rc = put_mesh(w, m, err);
	for (int v = 0; v < m->vert_count && !rc; v++)
		rc = put_influences(w, wt, v, err);
	if (!rc && w->hdr.version >= 6) {
		rc = image_put_u8(w, m->coloured != 0, err);
		if (!rc && m->coloured)
			rc = put(w, m->colour, 3 * (uint32_t)m->vert_count, err);
	}
	if (!rc && w->hdr.version >= 8)
		rc = put_texture(w, m, err);
	return rc ? rc : image_sec_end(w, &w->hdr.sec[SKP_SEC_BIND], err);
}

static skp_status put_clip_entry(skp_image_writer *w, const skp_image_clip *c, skp_error *err)
{
	skp_status rc = put_str(w, c->name, err);
	if (!rc) rc = image_put_f32(w, c->fps, err);
	if (!rc) rc = image_put_u32(w, c->frame_count, err);
	if (!rc) rc = image_put_u32(w, (uint32_t)c->first_number, err);
	if (!rc) rc = image_put_u16(w, c->dofs, err);
	if (!rc) rc = image_put_u16(w, c->frames_per_block, err);
	if (!rc) rc = image_put_u32(w, c->quant_first, err);
	if (!rc) rc = image_put_u32(w, c->quant_blocks, err);
	if (!rc) rc = image_put_u32(w, c->frames_first, err);
	if (!rc) rc = image_put_u32(w, c->frame_blocks, err);
	if (!rc) rc = image_put_f32(w, c->max_rot_err, err);
	if (!rc) rc = image_put_f32(w, c->max_trans_err, err);
	if (rc || w->hdr.version < 5)
		return rc;
	rc = image_put_u8(w, c->coded, err);
	if (!rc) rc = image_put_u32(w, c->stream_bytes, err);
	if (!rc) rc = image_put_u32(w, c->segments, err);
	if (!rc) rc = image_put_f32(w, c->shell_err, err);
	return rc ? rc : image_put_f32(w, c->unit_cm, err);
}

/* Version 7: each block's leaf (block 0's zeros: it is written last),
 * read back as written, into digest blocks that end the data blocks; the
 * root, over the digest blocks' own leaves, into the header's digest. */
static skp_status write_digests(skp_image_writer *w, skp_error *err)
{
	uint32_t leaves = w->next_block, per = skp_digest_per_block(w->bs), first = w->next_block;
	image_sec_begin(w, SKP_KIND_DIGESTS, 0);
	for (uint32_t b = 1; b < leaves; b++) {
		if (w->dev->read(w->dev->ctx, b, w->tmp) != (int)w->bs)
			return image_block_fail(err, SKP_ERR_IO, b, "cannot read it back to take its digest");
		skp_block_leaf(w->tmp, w->bs, w->block + SKP_IMAGE_BLOCK_HDR + (b % per) * SKP_IMAGE_LEAF_BYTES);
		if ((b + 1) % per == 0 && image_flush_block(w, err) != SKP_OK)
			return SKP_ERR_IO;
	}
	if (leaves % per && image_flush_block(w, err) != SKP_OK)
		return SKP_ERR_IO;
	sha256_ctx root;
	uint8_t leaf[SKP_IMAGE_LEAF_BYTES];
	sha256_init(&root);
	for (uint32_t b = first; b < w->next_block; b++) {
		if (w->dev->read(w->dev->ctx, b, w->tmp) != (int)w->bs)
			return image_block_fail(err, SKP_ERR_IO, b, "cannot read it back to take its digest");
		skp_block_leaf(w->tmp, w->bs, leaf);
		sha256_update(&root, leaf, sizeof leaf);
	}
	sha256_final(&root, w->hdr.digest);
	return SKP_OK;
}

skp_status skp_image_write_end(skp_image_writer *w, skp_error *err)
{
	if (w->clip)
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip '%s' ended %lu frames early", w->clip->name,
				(unsigned long)w->frames_left);
	skp_image_header *h = &w->hdr;
	h->clips = (uint32_t)w->clip_count;
	h->sec[SKP_SEC_CLIPS].count = w->clip_count ? w->next_block - h->sec[SKP_SEC_CLIPS].first : 0;
	image_sec_begin(w, SKP_KIND_DIRECTORY, 0);
	skp_status rc = image_put_u16(w, (unsigned)w->clip_count, err);
	for (int i = 0; i < w->clip_count && !rc; i++)
		rc = put_clip_entry(w, &w->dir[i], err);
	if (!rc)
		rc = image_sec_end(w, &h->sec[SKP_SEC_DIRECTORY], err);
	if (!rc && h->version >= 7)
		rc = write_digests(w, err);
	if (rc)
		return rc;
	/* data, parity over it (block 0 from memory: it is written last), the
	 * copies, block 0 */
	h->data_blocks = w->next_block;
	h->parity_blocks = w->parity_group < 0 ? 0 : skp_parity_blocks(h->data_blocks, (uint32_t)w->parity_group);
	h->dir_copy = h->data_blocks + h->parity_blocks;
	h->copy_block = h->dir_copy + h->sec[SKP_SEC_DIRECTORY].count;
	h->block_count = h->copy_block + 1;
	if (h->version < 7)
		sha256_final(&w->digest, h->digest);
	skp_header_block_frame(w->head, h);
	rc = skp_parity_write(w->dev, h, w->head, w->block, w->tmp, err);
	if (!rc) rc = skp_image_write_copies(w->dev, h, w->block, err);
	if (rc)
		return rc;
	if (w->dev->write(w->dev->ctx, 0, w->head) < 0)
		return image_block_fail(err, SKP_ERR_IO, 0, "cannot write the header");
	w->next_block = h->block_count;
	return SKP_OK;
}
