/* A clip's blocks: pass 1's range, then a quantised clip's quantisation
 * and frames as they stream in, or a compressed clip's codec header and
 * stream whole. The directory entry they fill is written by
 * skp_image_write_end. */
#include "image_write_internal.h"

#include <math.h>
#include <string.h>

#include "codec_decode.h"

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
		rc = image_sec_end(w, &sec, err);
	c->quant_first = sec.first;
	c->quant_blocks = sec.count;
	return rc;
}

static skp_status put_quant(skp_image_writer *w, skp_image_clip *c, const skp_clip_range *r,
			    skp_error *err)
{
	skp_status rc = SKP_OK;
	c->max_rot_err = c->max_trans_err = 0;
	image_sec_begin(w, SKP_KIND_QUANT, (uint16_t)w->clip_count);
	for (int i = 0; i < r->dofs && !rc; i++) {
		w->qmin[i] = r->frames ? r->min[i] : 0;
		w->qstep[i] = r->frames ? quant_step(r->min[i], r->max[i]) : 0;
		float *worst = is_rotation(w->s, i) ? &c->max_rot_err : &c->max_trans_err;
		*worst = fmaxf(*worst, w->qstep[i] * 0.5f);
		rc = image_put_f32(w, w->qmin[i], err);
		if (!rc)
			rc = image_put_f32(w, w->qstep[i], err);
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
	image_sec_begin(w, SKP_KIND_FRAMES, (uint16_t)w->clip_count);
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
		if (image_flush_block(w, err) != SKP_OK)
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
	image_sec_begin(w, SKP_KIND_QUANT, (uint16_t)w->clip_count);
	skp_status rc = image_put_u16(w, cc->tracks, err);
	if (!rc) rc = image_put_u16(w, cc->segment_frames, err);
	for (int i = 0; i < cc->tracks && !rc; i++) {
		rc = image_put_f32(w, cc->track[i].base, err);
		if (!rc) rc = image_put_f32(w, cc->track[i].step, err);
		if (!rc) rc = image_put_u8(w, cc->track[i].bits, err);
	}
	for (uint32_t s = 0; s <= k->segments && !rc; s++)
		rc = image_put_u32(w, k->offsets[s], err);
	return quant_end(w, c, rc, err);
}

/* The stream in blocks, each with its count of bytes. */
static skp_status put_stream(skp_image_writer *w, skp_image_clip *c, const uint8_t *bytes, uint32_t n,
			     skp_error *err)
{
	uint32_t room = w->payload - SKP_IMAGE_FRAMES_COUNT;
	image_sec_begin(w, SKP_KIND_FRAMES, (uint16_t)w->clip_count);
	c->frames_first = w->next_block;
	for (uint32_t at = 0; at < n; at += room) {
		uint32_t k = n - at < room ? n - at : room;
		le_put16(w->block + SKP_IMAGE_BLOCK_HDR, (uint16_t)k);
		memcpy(w->block + SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_FRAMES_COUNT, bytes + at, k);
		w->fill = SKP_IMAGE_FRAMES_COUNT + k;
		if (image_flush_block(w, err) != SKP_OK)
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
