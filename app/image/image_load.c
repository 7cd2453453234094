/* Loading an opened image's sections: the skeleton, the bound body (mesh
 * and weights) and a clip's quantisation, each checked as it is read. */
#include "image_read.h"

#include <math.h>
#include <string.h>

#include "image_error.h"
#include "image_load_texture.h"
#include "image_section.h"
#include "skin_compact.h"

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
	float sum = b->direction.x + b->direction.y + b->direction.z + b->offset.x + b->offset.y + b->offset.z +
		    b->length + b->axis_angle.x +
		    b->axis_angle.y + b->axis_angle.z + b->axis_rot.w + b->axis_rot.x + b->axis_rot.y + b->axis_rot.z;
	if (!isfinite(sum) || !(b->length >= 0))
		return sec_bad(im, err, "bone geometry not finite");
	*dof += b->channel_count;
	return SKP_OK;
}

static skp_status get_bone(skp_image *im, skel_bone *b, skp_error *err)
{
	/* zeroed: the bone is filled below even when a read failed */
	uint32_t id = 0;
	uint16_t parent = 0;
	float rot[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
	skp_status rc = sec_str(im, b->name, err);
	if (!rc) rc = sec_u32(im, &id, err);
	if (!rc) rc = sec_u16(im, &parent, err);
	if (!rc) rc = sec_floats(im, &b->direction.x, 3, err);
	if (!rc) rc = sec_floats(im, &b->length, 1, err);
	if (!rc) rc = sec_floats(im, &b->axis_angle.x, 3, err);
	if (!rc) rc = sec_get(im, b->axis_order, 3, err);
	if (!rc) rc = sec_u8(im, &b->channel_count, err);
	if (rc)
		return rc;
	if (b->channel_count > SKEL_MAX_CHANNELS)
		return sec_bad(im, err, "more than 7 channels on a bone");
	rc = sec_get(im, b->channel, b->channel_count, err);
	if (!rc) rc = sec_u8(im, &b->has_limits, err);
	for (int i = 0; i < b->channel_count && !rc; i++)
		rc = sec_floats(im, b->limit[i], 2, err);
	if (!rc) rc = sec_u16(im, &b->dof_offset, err);
	if (!rc) rc = sec_floats(im, rot, 4, err);
	if (!rc) rc = sec_floats(im, &b->offset.x, 3, err);
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
	skp_status rc = sec_str(im, s->name, err);
	if (!rc) rc = sec_u8(im, (uint8_t *)s->version, err);
	if (!rc) {
		uint8_t n = (uint8_t)s->version[0];
		if (n >= sizeof s->version)
			return sec_bad(im, err, "version longer than 15 bytes");
		rc = sec_get(im, s->version, n, err);
		s->version[n] = '\0';
	}
	if (!rc) rc = sec_floats(im, &s->length_scale, 1, err);
	if (!rc) rc = sec_floats(im, &s->mass_scale, 1, err);
	if (!rc) rc = sec_u8(im, &s->angle_in_degrees, err);
	if (!rc) rc = sec_floats(im, &s->root_position.x, 3, err);
	if (!rc) rc = sec_u16(im, &count, err);
	if (!rc) rc = sec_u16(im, &dofs, err);
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
	uint8_t rec[SKP_IMAGE_INFLUENCE_BYTES];
	skp_status rc = sec_get(im, rec, sizeof rec, err);
	if (rc)
		return rc;
	int n = rec[0];
	uint32_t sum = 0;
	if (n < 1 || n > SKP_MAX_INFLUENCES)
		return sec_bad(im, err, "influence count not 1..4");
	w->count[v] = (uint8_t)n;
	const uint8_t *weights = rec + 1 + SKP_MAX_INFLUENCES;
	for (int i = 0; i < SKP_MAX_INFLUENCES; i++) {
		uint16_t bone = rec[1 + i], q = le_get16(weights + 2 * i);
		if (i < n && bone >= s->count)
			return sec_bad(im, err, "influence on a bone the skeleton does not have");
		w->bone[v][i] = i < n ? bone : 0;
		w->weight[v][i] = i < n ? (float)q / (float)SKP_IMAGE_QMAX : 0.0f;
		sum += i < n ? q : 0;
	}
	return sum == SKP_IMAGE_QMAX ? SKP_OK : sec_bad(im, err, "weights do not sum to 65535");
}

/* Within the fixed-point kernel's range (fx_pos: +-32767 units; a normal
 * near unit length), so that no algorithm can fail on it once playing. */
static int in_envelope(vec3 p, float limit)
{
	return p.x > -limit && p.x < limit && p.y > -limit && p.y < limit && p.z > -limit && p.z < limit;
}

/* A compact position record: three u16 steps from the mesh's origin */
static vec3 dequantise(const uint8_t rec[6], const float origin[3], const float step[3])
{
	return vec3_make(origin[0] + (float)le_get16(rec) * step[0], origin[1] + (float)le_get16(rec + 2) * step[1],
			 origin[2] + (float)le_get16(rec + 4) * step[2]);
}

/* Positions in 16-bit steps over the bounds, octahedral normals. Every q
 * of 0..65535 decodes inside the envelope once the bounds' two ends do. */
static skp_status get_compact_vertices(skp_image *im, mesh *m, skp_error *err)
{
	float origin[3], step[3];
	skp_status rc = sec_floats(im, origin, 3, err);
	if (!rc) rc = sec_floats(im, step, 3, err);
	if (rc)
		return rc;
	vec3 lo = vec3_make(origin[0], origin[1], origin[2]);
	vec3 hi = vec3_make(origin[0] + 65535.0f * step[0], origin[1] + 65535.0f * step[1], origin[2] + 65535.0f * step[2]);
	if (!(step[0] >= 0 && step[1] >= 0 && step[2] >= 0) || !in_envelope(lo, 32767.0f) || !in_envelope(hi, 32767.0f))
		return sec_bad(im, err, "position bounds outside +-32767 units (the fixed-point range)");
	for (int v = 0; v < m->vert_count && !rc; v++) {
		uint8_t rec[6];
		rc = sec_get(im, rec, sizeof rec, err);
		if (!rc)
			m->pos[v] = dequantise(rec, origin, step);
	}
	for (int v = 0; v < m->vert_count && !rc; v++) {
		uint8_t rec[4];
		rc = sec_get(im, rec, sizeof rec, err);
		if (!rc)
			m->normal[v] = vec3_normalize(skin_oct_decode((int16_t)le_get16(rec), (int16_t)le_get16(rec + 2)));
	}
	return rc;
}

static skp_status get_mesh(skp_image *im, mesh *m, skp_error *err)
{
	skp_status rc = get_compact_vertices(im, m, err);
	for (int t = 0; t < m->tri_count && !rc; t++) {
		for (int k = 0; k < 3 && !rc; k++)
			rc = sec_u32(im, &m->tri[t][k], err);
		if (!rc && (m->tri[t][0] >= (uint32_t)m->vert_count || m->tri[t][1] >= (uint32_t)m->vert_count ||
			    m->tri[t][2] >= (uint32_t)m->vert_count))
			return sec_bad(im, err, "triangle index beyond the vertices");
	}
	return rc;
}

/* Version 6's base colour per vertex, when the body has its own. */
static skp_status get_colours(skp_image *im, mesh *m, skp_error *err)
{
	uint8_t coloured = 0;
	skp_status rc = im->hdr.version >= 6 ? sec_u8(im, &coloured, err) : SKP_OK;
	if (!rc && coloured > 1)
		return sec_bad(im, err, "colour flag neither 0 nor 1");
	m->coloured = coloured;
	if (!rc && coloured)
		rc = sec_get(im, m->colour, 3 * (uint32_t)m->vert_count, err);
	m->textured = 0;
	im->texture_skipped = 0;
	return rc || im->hdr.version < 8 ? rc : image_get_texture(im, m, err);
}

skp_status skp_image_load_bind(skp_image *im, const skel *s, mesh *m, skin_weights *w,
			       float *bind_values, long *bind_number, skp_error *err)
{
	uint32_t verts, tris, number;
	uint8_t posed;
	sec_open(im, &im->hdr.sec[SKP_SEC_BIND], SKP_KIND_BIND, 0);
	skp_status rc = sec_u32(im, &verts, err);
	if (!rc) rc = sec_u32(im, &tris, err);
	if (!rc) rc = sec_u8(im, &posed, err);
	if (!rc) rc = sec_u32(im, &number, err);
	if (rc)
		return rc;
	if (verts != im->hdr.verts || tris != im->hdr.tris || verts > SKP_MAX_VERTS || tris > SKP_MAX_TRIS ||
	    posed > 1)
		return sec_bad(im, err, "vertex or triangle count differs from the header's");
	memset(bind_values, 0, sizeof(float) * SKP_MAX_DOF);
	*bind_number = posed ? (long)(int32_t)number : -1;
	if (posed && (rc = sec_floats(im, bind_values, s->dof_count, err)) != SKP_OK)
		return rc;
	for (int i = 0; i < s->dof_count; i++)
		if (!isfinite(bind_values[i]))
			return sec_bad(im, err, "bind pose value not finite");
	m->vert_count = (int)verts;
	m->tri_count = (int)tris;
	w->vert_count = (int)verts;
	rc = get_mesh(im, m, err);
	for (int v = 0; v < m->vert_count && !rc; v++)
		rc = get_influences(im, s, w, v, err);
	return rc ? rc : get_colours(im, m, err);
}

/* A compressed clip's quantisation section: the codec's header. */
static void open_quant(skp_image *im, int clip)
{
	const skp_image_clip *c = &im->clip[clip];
	skp_image_section sec = { c->quant_first, c->quant_blocks, c->quant_blocks * (im->hdr.block_size - SKP_IMAGE_BLOCK_EXTRA) };
	sec_open(im, &sec, SKP_KIND_QUANT, (uint16_t)clip);
}

skp_status skp_image_load_codec(skp_image *im, int clip, codec_clip *cc, skp_error *err)
{
	const skp_image_clip *c = &im->clip[clip];
	if (!c->coded)
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip %s is not compressed", c->name);
	open_quant(im, clip);
	skp_status rc = sec_u16(im, &cc->tracks, err);
	if (!rc) rc = sec_u16(im, &cc->segment_frames, err);
	if (!rc && cc->tracks != c->dofs)
		return sec_bad(im, err, "compressed clip: tracks differ from the clip's dofs");
	for (int i = 0; i < cc->tracks && !rc; i++) {
		rc = sec_floats(im, &cc->track[i].base, 1, err);
		if (!rc) rc = sec_floats(im, &cc->track[i].step, 1, err);
		if (!rc) rc = sec_u8(im, &cc->track[i].bits, err);
	}
	if (rc)
		return rc;
	cc->frames = c->frame_count;
	if (codec_clip_check(cc, err) != SKP_OK) {
		err->block = sec_block(im);
		return SKP_ERR_CORRUPT;
	}
	if (codec_segments(cc) != c->segments)
		return sec_bad(im, err, "compressed clip: segments differ from the directory's");
	return SKP_OK;
}

skp_status skp_image_load_span(skp_image *im, int clip, uint32_t s, uint32_t span[2], skp_error *err)
{
	const skp_image_clip *c = &im->clip[clip];
	uint8_t skip[64];
	if (!c->coded || s >= c->segments)
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip %s: no segment %lu", c->name, (unsigned long)s);
	open_quant(im, clip);
	uint32_t left = 4u + 9u * c->dofs + 4u * s;
	skp_status rc = SKP_OK;
	while (left && !rc) {
		uint32_t n = left < sizeof skip ? left : (uint32_t)sizeof skip;
		rc = sec_get(im, skip, n, err);
		left -= n;
	}
	if (!rc) rc = sec_u32(im, &span[0], err);
	if (!rc) rc = sec_u32(im, &span[1], err);
	if (rc)
		return rc;
	if (span[0] > span[1] || span[1] > c->stream_bytes || span[1] - span[0] > SKP_CODEC_SEGMENT_BYTES ||
	    (s == 0 && span[0] != 0) || (s + 1 == c->segments && span[1] != c->stream_bytes))
		return sec_bad(im, err, "compressed clip: segment offsets out of the stream (or beyond SKP_CODEC_SEGMENT_BYTES)");
	return SKP_OK;
}

/* A compressed clip's range per dof as a quantisation would give it
 * (min, and a step with 65535 of them to the track's top), so what is
 * judged of a clip (image_accept.c) is judged of both kinds alike. */
static skp_status codec_as_quant(skp_image *im, int clip, float *qmin, float *qstep, skp_error *err)
{
	static codec_clip cc;
	skp_status rc = skp_image_load_codec(im, clip, &cc, err);
	for (int i = 0; i < cc.tracks && !rc; i++) {
		const codec_track *t = &cc.track[i];
		double top = t->bits ? (double)codec_value(t, (int32_t)((1u << t->bits) - 1u)) : (double)t->base;
		qmin[i] = t->base;
		qstep[i] = (float)((top - (double)t->base) / SKP_IMAGE_QMAX);
	}
	return rc;
}

skp_status skp_image_load_quant(skp_image *im, int clip, float *qmin, float *qstep, skp_error *err)
{
	const skp_image_clip *c = &im->clip[clip];
	if (c->coded)
		return codec_as_quant(im, clip, qmin, qstep, err);
	skp_image_section sec = { c->quant_first, c->quant_blocks, 8u * c->dofs };
	sec_open(im, &sec, SKP_KIND_QUANT, (uint16_t)clip);
	skp_status rc = SKP_OK;
	for (int i = 0; i < c->dofs && !rc; i++) {
		rc = sec_floats(im, &qmin[i], 1, err);
		if (!rc)
			rc = sec_floats(im, &qstep[i], 1, err);
		if (!rc && !(qstep[i] >= 0))
			return sec_bad(im, err, "negative quantisation step");
		/* every decoded value min + q * step, q <= 65535, must be finite */
		if (!rc && !isfinite(qmin[i] + (float)SKP_IMAGE_QMAX * qstep[i]))
			return sec_bad(im, err, "quantisation range not finite");
	}
	return rc;
}

skp_status skp_image_check_frames(skp_image *im, int clip, skp_error *err)
{
	const skp_image_clip *c = &im->clip[clip];
	uint32_t last = c->frame_blocks - 1, block = c->frames_first + last;
	uint32_t room = skp_image_stream_room(im->hdr.block_size);
	/* im->buf: every section read starts with sec_open */
	if (c->frame_blocks == 0 || skp_image_read_block(im, block, SKP_KIND_FRAMES, (unsigned)clip, im->buf) != SKP_BLOCK_OK)
		return SKP_OK;
	uint32_t has = le_get16(im->buf + SKP_IMAGE_BLOCK_HDR), want = skp_image_block_count(c, room, last);
	if (has != want)
		return image_block_fail(err, SKP_ERR_CORRUPT, block, "the clip's last block holds %lu %s, the directory says %lu",
					(unsigned long)has, c->coded ? "stream bytes" : "frames", (unsigned long)want);
	return SKP_OK;
}
