#include "image_write.h"

#include <math.h>
#include <string.h>

#include "codec_decode.h"
#include "crc32.h"
#include "image_copies.h"
#include "image_parity.h"
#include "image_error.h"
#include "skin_compact.h"

void skp_clip_range_init(skp_clip_range *r, const skel *s)
{
	r->dofs = s->dof_count;
	r->frames = 0;
	r->first_number = r->last_number = 0;
	for (int i = 0; i < r->dofs; i++) {
		r->min[i] = INFINITY;
		r->max[i] = -INFINITY;
	}
}

skp_status skp_clip_range_add(skp_clip_range *r, const amc_frame *f, skp_error *err)
{
	if (r->frames == 0)
		r->first_number = f->number;
	else if (f->number != r->last_number + 1)
		return skp_fail(err, SKP_ERR_SYNTAX, f->line,
				"frame %ld follows frame %ld: an image needs consecutive frame numbers",
				f->number, r->last_number);
	for (int i = 0; i < r->dofs; i++) {
		float v = f->value[i];
		if (!isfinite(v))
			return skp_fail(err, SKP_ERR_RANGE, f->line, "frame %ld: value %d is not finite",
					f->number, i + 1);
		r->min[i] = fminf(r->min[i], v);
		r->max[i] = fmaxf(r->max[i], v);
	}
	r->last_number = f->number;
	r->frames++;
	return SKP_OK;
}

/* Frames the block, CRCs it and writes it at the next position. */
static skp_status flush_block(skp_image_writer *w, skp_error *err)
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

static void sec_begin(skp_image_writer *w, uint8_t kind, uint16_t item)
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
		if (w->fill == w->payload && flush_block(w, err) != SKP_OK)
			return SKP_ERR_IO;
	}
	return SKP_OK;
}

/* Ends the section: the partial last block is written; returns its extent. */
static skp_status sec_end(skp_image_writer *w, skp_image_section *out, skp_error *err)
{
	if (w->fill > 0 && flush_block(w, err) != SKP_OK)
		return SKP_ERR_IO;
	if (out) {
		out->first = w->sec_first;
		out->count = w->next_block - w->sec_first;
		out->bytes = w->sec_bytes;
	}
	return SKP_OK;
}

static skp_status put_u8(skp_image_writer *w, unsigned v, skp_error *err)
{
	uint8_t b = (uint8_t)v;
	return put(w, &b, 1, err);
}

static skp_status put_u16(skp_image_writer *w, unsigned v, skp_error *err)
{
	uint8_t b[2];
	le_put16(b, (uint16_t)v);
	return put(w, b, 2, err);
}

static skp_status put_u32(skp_image_writer *w, uint32_t v, skp_error *err)
{
	uint8_t b[4];
	le_put32(b, v);
	return put(w, b, 4, err);
}

static skp_status put_f32(skp_image_writer *w, float v, skp_error *err)
{
	uint32_t u;
	memcpy(&u, &v, 4);
	return put_u32(w, u, err);
}

static skp_status put_floats(skp_image_writer *w, const float *v, int n, skp_error *err)
{
	skp_status rc = SKP_OK;
	for (int i = 0; i < n && rc == SKP_OK; i++)
		rc = put_f32(w, v[i], err);
	return rc;
}

static skp_status put_str(skp_image_writer *w, const char *s, skp_error *err)
{
	size_t n = strlen(s);
	if (n >= SKP_MAX_NAME)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "name '%s' longer than %d bytes (board limit SKP_MAX_NAME)",
				s, SKP_MAX_NAME - 1);
	skp_status rc = put_u8(w, (unsigned)n, err);
	return rc ? rc : put(w, s, (uint32_t)n, err);
}

static skp_status put_bone(skp_image_writer *w, const skel_bone *b, skp_error *err)
{
	float rot[4] = { b->axis_rot.w, b->axis_rot.x, b->axis_rot.y, b->axis_rot.z };
	float dir[3] = { b->direction.x, b->direction.y, b->direction.z };
	float ax[3] = { b->axis_angle.x, b->axis_angle.y, b->axis_angle.z };
	skp_status rc = put_str(w, b->name, err);
	if (!rc) rc = put_u32(w, (uint32_t)(int32_t)b->id, err);
	if (!rc) rc = put_u16(w, (uint16_t)(int16_t)b->parent, err);
	if (!rc) rc = put_floats(w, dir, 3, err);
	if (!rc) rc = put_f32(w, b->length, err);
	if (!rc) rc = put_floats(w, ax, 3, err);
	if (!rc) rc = put(w, b->axis_order, 3, err);
	if (!rc) rc = put_u8(w, b->channel_count, err);
	if (!rc) rc = put(w, b->channel, b->channel_count, err);
	if (!rc) rc = put_u8(w, b->has_limits, err);
	for (int i = 0; i < b->channel_count && !rc; i++)
		rc = put_floats(w, b->limit[i], 2, err);
	if (!rc) rc = put_u16(w, b->dof_offset, err);
	if (!rc) rc = put_floats(w, rot, 4, err);
	float off[3] = { b->offset.x, b->offset.y, b->offset.z };
	return rc ? rc : put_floats(w, off, 3, err);
}

static skp_status put_skel(skp_image_writer *w, const skel *s, skp_error *err)
{
	float root[3] = { s->root_position.x, s->root_position.y, s->root_position.z };
	skp_status rc = put_str(w, s->name, err);
	if (!rc) rc = put_str(w, s->version, err);
	if (!rc) rc = put_f32(w, s->length_scale, err);
	if (!rc) rc = put_f32(w, s->mass_scale, err);
	if (!rc) rc = put_u8(w, s->angle_in_degrees, err);
	if (!rc) rc = put_floats(w, root, 3, err);
	if (!rc) rc = put_u16(w, (unsigned)s->count, err);
	if (!rc) rc = put_u16(w, (unsigned)s->dof_count, err);
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
	sec_begin(w, SKP_KIND_SKELETON, 0);
	skp_status rc = put_skel(w, s, err);
	return rc ? rc : sec_end(w, &w->hdr.sec[SKP_SEC_SKELETON], err);
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
			rc = put_u32(w, m->tri[t][k], err);
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

skp_status skp_image_write_bind(skp_image_writer *w, const mesh *m, const skin_weights *wt,
				const float *bind_values, long bind_number, skp_error *err)
{
	skp_status rc = check_weights(w, wt, m->vert_count, err);
	if (rc)
		return rc;
	w->hdr.verts = (uint32_t)m->vert_count;
	w->hdr.tris = (uint32_t)m->tri_count;
	sec_begin(w, SKP_KIND_BIND, 0);
	rc = put_u32(w, (uint32_t)m->vert_count, err);
	if (!rc) rc = put_u32(w, (uint32_t)m->tri_count, err);
	if (!rc) rc = put_u8(w, bind_values != NULL, err);
	if (!rc) rc = put_u32(w, (uint32_t)(int32_t)(bind_values ? bind_number : -1), err);
	if (!rc && bind_values)
		rc = put_floats(w, bind_values, w->s->dof_count, err);
	if (!rc)
		rc = put_mesh(w, m, err);
	for (int v = 0; v < m->vert_count && !rc; v++)
		rc = put_influences(w, wt, v, err);
	return rc ? rc : sec_end(w, &w->hdr.sec[SKP_SEC_BIND], err);
}

/* The smallest float step covering the range in 65535 steps. */
static float quant_step(float lo, float hi)
{
	double range = (double)hi - (double)lo;
	float step = (float)(range / SKP_IMAGE_QMAX);
	while ((double)step * SKP_IMAGE_QMAX < range)
		step = nextafterf(step, INFINITY);
	return step;
}

static int is_rotation(const skel *s, int dof)
{
	for (int b = s->count - 1; b >= 0; b--)
		if (s->bone[b].dof_offset <= dof && dof < s->bone[b].dof_offset + s->bone[b].channel_count)
			return s->bone[b].channel[dof - s->bone[b].dof_offset] <= SKEL_RZ;
	return 0;
}

/* Closes a clip's quantisation section (rc: how writing it went) and
 * notes where it lies. */
static skp_status quant_end(skp_image_writer *w, skp_image_clip *c, skp_status rc, skp_error *err)
{
	skp_image_section sec = { 0, 0, 0 };
	if (!rc)
		rc = sec_end(w, &sec, err);
	c->quant_first = sec.first;
	c->quant_blocks = sec.count;
	return rc;
}

static skp_status put_quant(skp_image_writer *w, skp_image_clip *c, const skp_clip_range *r,
			    skp_error *err)
{
	skp_status rc = SKP_OK;
	c->max_rot_err = c->max_trans_err = 0;
	sec_begin(w, SKP_KIND_QUANT, (uint16_t)w->clip_count);
	for (int i = 0; i < r->dofs && !rc; i++) {
		w->qmin[i] = r->frames ? r->min[i] : 0;
		w->qstep[i] = r->frames ? quant_step(r->min[i], r->max[i]) : 0;
		float *worst = is_rotation(w->s, i) ? &c->max_rot_err : &c->max_trans_err;
		*worst = fmaxf(*worst, w->qstep[i] * 0.5f);
		rc = put_f32(w, w->qmin[i], err);
		if (!rc)
			rc = put_f32(w, w->qstep[i], err);
	}
	return quant_end(w, c, rc, err);
}

/* The next directory entry, its name and rate checked; NULL when they
 * cannot be (err says why). */
static skp_image_clip *new_entry(skp_image_writer *w, const char *name, float fps, skp_error *err)
{
	if (w->clip_count >= SKP_IMAGE_MAX_CLIPS)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "more than %d clips (board limit SKP_IMAGE_MAX_CLIPS)",
				SKP_IMAGE_MAX_CLIPS), NULL;
	if (strlen(name) >= SKP_MAX_NAME)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "clip name '%s' longer than %d bytes", name, SKP_MAX_NAME - 1),
		       NULL;
	if (!(fps > 0))
		return skp_fail(err, SKP_ERR_RANGE, 0, "frame rate %g: expected > 0", (double)fps), NULL;
	if (w->clip)
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip '%s' ended %lu frames early", w->clip->name,
				(unsigned long)w->frames_left), NULL;
	skp_image_clip *c = &w->dir[w->clip_count];
	memset(c, 0, sizeof *c);
	memcpy(c->name, name, strlen(name) + 1);
	c->fps = fps;
	return c;
}

skp_status skp_image_clip_begin(skp_image_writer *w, const char *name, float fps,
				const skp_clip_range *range, skp_error *err)
{
	uint32_t frame_bytes = 2u * (uint32_t)range->dofs, room = w->payload - SKP_IMAGE_FRAMES_COUNT;
	if (range->dofs != w->s->dof_count || frame_bytes > room || frame_bytes == 0)
		return skp_fail(err, SKP_ERR_RANGE, 0, "a frame of %d dofs does not fit a %lu-byte block",
				range->dofs, (unsigned long)w->bs);
	skp_image_clip *c = new_entry(w, name, fps, err);
	if (!c)
		return SKP_ERR_RANGE;
	c->frame_count = (uint32_t)range->frames;
	c->first_number = (int32_t)range->first_number;
	c->dofs = (uint16_t)range->dofs;
	c->frames_per_block = (uint16_t)(room / frame_bytes);
	skp_status rc = put_quant(w, c, range, err);
	if (rc)
		return rc;
	if (w->clip_count == 0)
		w->hdr.sec[SKP_SEC_CLIPS].first = c->quant_first;
	c->frames_first = w->next_block;
	c->frame_blocks = (c->frame_count + c->frames_per_block - 1) / c->frames_per_block;
	w->clip = c->frame_count ? c : NULL;
	w->frames_left = c->frame_count;
	w->in_block = 0;
	w->next_number = range->first_number;
	sec_begin(w, SKP_KIND_FRAMES, (uint16_t)w->clip_count);
	w->clip_count++;
	return SKP_OK;
}

skp_status skp_image_clip_frame(skp_image_writer *w, const amc_frame *f, skp_error *err)
{
	skp_image_clip *c = w->clip;
	if (!c || w->frames_left == 0)
		return skp_fail(err, SKP_ERR_RANGE, f->line, "frame %ld: more frames than the clip's first pass counted",
				f->number);
	if (f->number != w->next_number)
		return skp_fail(err, SKP_ERR_RANGE, f->line, "frame %ld: expected frame %ld (the input changed since the first pass?)",
				f->number, w->next_number);
	if (w->fill == 0)
		w->fill = SKP_IMAGE_FRAMES_COUNT; /* the block's count of frames, set when it is full */
	uint8_t *p = w->block + SKP_IMAGE_BLOCK_HDR + w->fill;
	for (int i = 0; i < c->dofs; i++) {
		double q = w->qstep[i] > 0 ? floor(((double)f->value[i] - w->qmin[i]) / w->qstep[i] + 0.5) : 0;
		if (!(q >= 0 && q <= SKP_IMAGE_QMAX))
			return skp_fail(err, SKP_ERR_RANGE, f->line, "frame %ld: value %d outside the first pass's range",
					f->number, i + 1);
		le_put16(p + 2 * i, (uint16_t)q);
	}
	w->fill += 2u * c->dofs;
	w->in_block++;
	w->next_number++;
	w->frames_left--;
	/* whole frames only: the block goes when the next frame would not fit */
	if (w->fill + 2u * c->dofs > w->payload || w->frames_left == 0) {
		le_put16(w->block + SKP_IMAGE_BLOCK_HDR, w->in_block);
		w->in_block = 0;
		if (flush_block(w, err) != SKP_OK)
			return SKP_ERR_IO;
	}
	if (w->frames_left == 0)
		w->clip = NULL;
	return SKP_OK;
}

/* The codec's header and the segments' offsets (image_format.h). */
static skp_status put_codec(skp_image_writer *w, skp_image_clip *c, const skp_coded_clip *k, skp_error *err)
{
	const codec_clip *cc = k->clip;
	sec_begin(w, SKP_KIND_QUANT, (uint16_t)w->clip_count);
	skp_status rc = put_u16(w, cc->tracks, err);
	if (!rc) rc = put_u16(w, cc->segment_frames, err);
	for (int i = 0; i < cc->tracks && !rc; i++) {
		rc = put_f32(w, cc->track[i].base, err);
		if (!rc) rc = put_f32(w, cc->track[i].step, err);
		if (!rc) rc = put_u8(w, cc->track[i].bits, err);
	}
	for (uint32_t s = 0; s <= k->segments && !rc; s++)
		rc = put_u32(w, k->offsets[s], err);
	return quant_end(w, c, rc, err);
}

/* The stream in blocks, each with its count of bytes. */
static skp_status put_stream(skp_image_writer *w, skp_image_clip *c, const uint8_t *bytes, uint32_t n,
			     skp_error *err)
{
	uint32_t room = w->payload - SKP_IMAGE_FRAMES_COUNT;
	sec_begin(w, SKP_KIND_FRAMES, (uint16_t)w->clip_count);
	c->frames_first = w->next_block;
	for (uint32_t at = 0; at < n; at += room) {
		uint32_t k = n - at < room ? n - at : room;
		le_put16(w->block + SKP_IMAGE_BLOCK_HDR, (uint16_t)k);
		memcpy(w->block + SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_FRAMES_COUNT, bytes + at, k);
		w->fill = SKP_IMAGE_FRAMES_COUNT + k;
		if (flush_block(w, err) != SKP_OK)
			return SKP_ERR_IO;
	}
	c->frame_blocks = w->next_block - c->frames_first;
	return SKP_OK;
}

static int offsets_ok(const skp_coded_clip *k)
{
	if (k->segments != codec_segments(k->clip) || k->offsets[0] != 0 || k->offsets[k->segments] != k->nbytes)
		return 0;
	for (uint32_t s = 0; s < k->segments; s++)
		if (k->offsets[s + 1] < k->offsets[s] || k->offsets[s + 1] - k->offsets[s] > SKP_CODEC_SEGMENT_BYTES)
			return 0;
	return 1;
}

skp_status skp_image_clip_coded(skp_image_writer *w, const char *name, float fps, const skp_coded_clip *k,
				skp_error *err)
{
	skp_error_clear(err);
	if (w->hdr.version < 5)
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip '%s': format version %u has no compressed clips", name,
				(unsigned)w->hdr.version);
	if (k->clip->tracks != w->s->dof_count || k->clip->frames == 0 || codec_clip_check(k->clip, err) != SKP_OK ||
	    !offsets_ok(k))
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip '%s': the compressed clip does not fit its skeleton or its segments",
				name);
	skp_image_clip *c = new_entry(w, name, fps, err);
	if (!c)
		return SKP_ERR_RANGE;
	c->frame_count = k->clip->frames;
	c->first_number = (int32_t)k->first_number;
	c->dofs = k->clip->tracks;
	c->coded = 1;
	c->stream_bytes = k->nbytes;
	c->segments = k->segments;
	c->max_rot_err = k->max_rot_err;
	c->max_trans_err = k->max_trans_err;
	c->shell_err = k->shell_err;
	c->unit_cm = k->unit_cm;
	skp_status rc = put_codec(w, c, k, err);
	if (!rc && w->clip_count == 0)
		w->hdr.sec[SKP_SEC_CLIPS].first = c->quant_first;
	if (!rc)
		rc = put_stream(w, c, k->bytes, k->nbytes, err);
	if (!rc)
		w->clip_count++;
	return rc;
}

static skp_status put_clip_entry(skp_image_writer *w, const skp_image_clip *c, skp_error *err)
{
	skp_status rc = put_str(w, c->name, err);
	if (!rc) rc = put_f32(w, c->fps, err);
	if (!rc) rc = put_u32(w, c->frame_count, err);
	if (!rc) rc = put_u32(w, (uint32_t)c->first_number, err);
	if (!rc) rc = put_u16(w, c->dofs, err);
	if (!rc) rc = put_u16(w, c->frames_per_block, err);
	if (!rc) rc = put_u32(w, c->quant_first, err);
	if (!rc) rc = put_u32(w, c->quant_blocks, err);
	if (!rc) rc = put_u32(w, c->frames_first, err);
	if (!rc) rc = put_u32(w, c->frame_blocks, err);
	if (!rc) rc = put_f32(w, c->max_rot_err, err);
	if (!rc) rc = put_f32(w, c->max_trans_err, err);
	if (rc || w->hdr.version < 5)
		return rc;
	rc = put_u8(w, c->coded, err);
	if (!rc) rc = put_u32(w, c->stream_bytes, err);
	if (!rc) rc = put_u32(w, c->segments, err);
	if (!rc) rc = put_f32(w, c->shell_err, err);
	return rc ? rc : put_f32(w, c->unit_cm, err);
}

skp_status skp_image_write_end(skp_image_writer *w, skp_error *err)
{
	if (w->clip)
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip '%s' ended %lu frames early", w->clip->name,
				(unsigned long)w->frames_left);
	skp_image_header *h = &w->hdr;
	h->clips = (uint32_t)w->clip_count;
	h->sec[SKP_SEC_CLIPS].count = w->clip_count ? w->next_block - h->sec[SKP_SEC_CLIPS].first : 0;
	sec_begin(w, SKP_KIND_DIRECTORY, 0);
	skp_status rc = put_u16(w, (unsigned)w->clip_count, err);
	for (int i = 0; i < w->clip_count && !rc; i++)
		rc = put_clip_entry(w, &w->dir[i], err);
	if (!rc)
		rc = sec_end(w, &h->sec[SKP_SEC_DIRECTORY], err);
	if (rc)
		return rc;
	/* data, parity over it (block 0 from memory: it is written last), the
	 * copies, block 0 */
	h->data_blocks = w->next_block;
	h->parity_blocks = w->parity_group < 0 ? 0 : skp_parity_blocks(h->data_blocks, (uint32_t)w->parity_group);
	h->dir_copy = h->data_blocks + h->parity_blocks;
	h->copy_block = h->dir_copy + h->sec[SKP_SEC_DIRECTORY].count;
	h->block_count = h->copy_block + 1;
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
