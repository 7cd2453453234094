#include "image_stream.h"

#include "image_error.h"

#include <string.h>

static void ring_clear(skp_clip_stream *p)
{
	for (int i = 0; i < SKP_IMAGE_RING_BLOCKS; i++)
		p->slot[i].block = UINT32_MAX;
}

/* Block read into buf: as the storage holds it; when bad, the copy kept
 * from an earlier rebuild, else rebuilt (and kept). */
static skp_block_state read_frames_block(skp_clip_stream *p, uint32_t block, uint8_t *buf)
{
	unsigned item = (unsigned)p->clip;
	skp_block_state st = skp_image_check_block(p->im, block, SKP_KIND_FRAMES, item, buf);
	if (st == SKP_BLOCK_OK)
		return st;
	for (int k = 0; k < SKP_IMAGE_CACHE_BLOCKS; k++)
		if (p->kept[k] == block) {
			memcpy(buf, p->keep[k], p->im->hdr.block_size);
			p->kept_uses++;
			return SKP_BLOCK_OK;
		}
	st = skp_image_read_block(p->im, block, SKP_KIND_FRAMES, item, buf);
	if (st == SKP_BLOCK_OK && SKP_IMAGE_CACHE_BLOCKS > 0) {
		int k = p->keep_next++ % SKP_IMAGE_CACHE_BLOCKS;
		p->kept[k] = block;
		memcpy(p->keep[k], buf, p->im->hdr.block_size);
	}
	return st;
}

skp_status skp_clip_stream_open(skp_clip_stream *p, skp_image *im, int clip, skp_error *err)
{
	skp_error_clear(err);
	if (clip < 0 || clip >= im->clip_count)
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip %d: the image has %d", clip, im->clip_count);
	p->im = im;
	p->clip = clip;
	p->c = im->clip[clip];
	p->reads = 0;
	p->keep_next = 0;
	p->kept_uses = 0;
	for (int k = 0; k < SKP_IMAGE_CACHE_BLOCKS; k++)
		p->kept[k] = UINT32_MAX;
	ring_clear(p);
	p->seg = UINT32_MAX;
	skp_status rc = p->c.coded ? skp_image_load_codec(im, clip, &p->cc, err)
				   : skp_image_load_quant(im, clip, p->qmin, p->qstep, err);
	skp_clip_stream_seek(p, 0);
	return rc;
}

/* The ring keeps its blocks (each slot knows which block it holds): a
 * short clip looping, or a seek back into what was read, reads nothing
 * again. */
void skp_clip_stream_seek(skp_clip_stream *p, uint32_t index)
{
	p->next = index;
	p->fetch = p->c.coded ? 0 : index / p->c.frames_per_block;
}

static uint32_t room(const skp_clip_stream *p)
{
	return skp_image_stream_room(p->im->hdr.block_size);
}

/* Reads frame block b (clip-relative) into its ring slot: good when its
 * frame and its count of frames are what the directory says. */
static skp_clip_slot *load(skp_clip_stream *p, uint32_t b)
{
	skp_clip_slot *s = &p->slot[b % SKP_IMAGE_RING_BLOCKS];
	uint8_t *block = p->ring[b % SKP_IMAGE_RING_BLOCKS];
	if (s->block == b)
		return s;
	s->block = b;
	s->state = (uint8_t)read_frames_block(p, p->c.frames_first + b, block);
	if (s->state == SKP_BLOCK_OK && le_get16(block + SKP_IMAGE_BLOCK_HDR) != skp_image_block_count(&p->c, room(p), b))
		s->state = SKP_BLOCK_COUNT;
	p->reads++;
	return s;
}

/* Keeps the ring full ahead of the head, one block per frame at most, so a
 * slow medium costs a little every frame rather than a stall per block. */
static void prefetch(skp_clip_stream *p, uint32_t head)
{
	if (p->fetch <= head)
		p->fetch = head + 1;
	if (p->fetch < p->c.frame_blocks && p->fetch < head + SKP_IMAGE_RING_BLOCKS)
		load(p, p->fetch++);
}

static void decode(const skp_clip_stream *p, const uint8_t *block, uint32_t index, amc_frame *f)
{
	uint32_t at = SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_FRAMES_COUNT + (index % p->c.frames_per_block) * 2u * p->c.dofs;
	const uint8_t *q = block + at;
	for (int i = 0; i < p->c.dofs; i++)
		f->value[i] = (float)((double)p->qmin[i] + (double)le_get16(q + 2 * i) * (double)p->qstep[i]);
	f->number = (long)p->c.first_number + (long)index;
	f->line = 0;
}

static int lost(skp_error *err, int state, uint32_t block)
{
	image_block_fail(err, state == SKP_BLOCK_IO ? SKP_ERR_IO : SKP_ERR_CORRUPT, block, "%s",
			 skp_block_state_name((skp_block_state)state));
	return SKP_CLIP_LOST;
}

static int next_quantised(skp_clip_stream *p, amc_frame *f, skp_error *err)
{
	uint32_t index = p->next++, b = index / p->c.frames_per_block;
	skp_clip_slot *s = load(p, b);
	int state = s->state;
	if (state == SKP_BLOCK_OK)
		decode(p, p->ring[b % SKP_IMAGE_RING_BLOCKS], index, f);
	prefetch(p, b);
	return state == SKP_BLOCK_OK ? 1 : lost(err, state, p->c.frames_first + b);
}

/* Gathers segment seg's bytes from its blocks (through the ring) and
 * starts decoding it; a block that fails loses the segment. */
static void gather(skp_clip_stream *p, uint32_t seg, skp_error *err)
{
	uint32_t span[2], per = room(p);
	p->seg = seg;
	p->seg_state = SKP_BLOCK_OK;
	p->seg_refused = 0;
	p->seg_last = 0;
	if (skp_image_load_span(p->im, p->clip, seg, span, err) != SKP_OK) {
		p->seg_refused = 1;
		p->seg_block = err->block >= 0 ? (uint32_t)err->block : p->c.quant_first;
		return;
	}
	uint32_t first = span[0] / per;
	p->seg_last = span[1] > span[0] ? (span[1] - 1) / per : first;
	for (uint32_t b = first; b <= p->seg_last && span[1] > span[0]; b++) {
		skp_clip_slot *s = load(p, b);
		if (s->state != SKP_BLOCK_OK) {
			p->seg_state = s->state;
			p->seg_block = p->c.frames_first + b;
			return;
		}
		uint32_t from = b == first ? span[0] - b * per : 0;
		uint32_t to = b == p->seg_last ? span[1] - b * per : per;
		memcpy(p->seg_bytes + (b * per + from - span[0]),
		       p->ring[b % SKP_IMAGE_RING_BLOCKS] + SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_FRAMES_COUNT + from, to - from);
	}
	if (codec_begin(&p->dec, &p->cc, seg, p->seg_bytes, span[1] - span[0], err) != SKP_OK) {
		p->seg_refused = 1;
		p->seg_block = p->c.frames_first + first;
	}
}

/* The blocks after the segment being decoded, one a frame, as many as the
 * ring holds beside its last block (the next segment's first). */
static void prefetch_coded(skp_clip_stream *p)
{
	if (p->fetch <= p->seg_last)
		p->fetch = p->seg_last + 1;
	if (p->fetch < p->c.frame_blocks && p->fetch < p->seg_last + SKP_IMAGE_RING_BLOCKS)
		load(p, p->fetch++);
}

static int next_coded(skp_clip_stream *p, amc_frame *f, skp_error *err)
{
	uint32_t index = p->next++, seg = index / p->cc.segment_frames, at = index % p->cc.segment_frames;
	if (seg != p->seg)
		gather(p, seg, err);
	else if (!p->seg_refused && p->seg_state == SKP_BLOCK_OK && p->dec.frame > at)
		codec_begin(&p->dec, &p->cc, seg, p->seg_bytes, p->dec.nbytes, err); /* a seek back */
	int rc = 1;
	while (rc == 1 && !p->seg_refused && p->seg_state == SKP_BLOCK_OK && p->dec.frame < at)
		rc = codec_next(&p->dec, p->value, err);
	if (rc == 1 && !p->seg_refused && p->seg_state == SKP_BLOCK_OK)
		rc = codec_next(&p->dec, p->value, err);
	if (rc != 1 && !p->seg_refused && p->seg_state == SKP_BLOCK_OK) {
		p->seg_refused = 1;
		p->seg_block = p->c.frames_first + (p->seg_last ? p->seg_last : 0);
	}
	prefetch_coded(p);
	if (p->seg_state != SKP_BLOCK_OK)
		return lost(err, p->seg_state, p->seg_block);
	if (p->seg_refused)
		return image_block_fail(err, SKP_ERR_CORRUPT, p->seg_block,
					"compressed segment %lu of clip %s refused by the decoder", (unsigned long)seg,
					p->c.name),
		       SKP_CLIP_LOST;
	memcpy(f->value, p->value, sizeof(float) * p->cc.tracks);
	f->number = (long)p->c.first_number + (long)index;
	f->line = 0;
	return 1;
}

int skp_clip_stream_next(skp_clip_stream *p, amc_frame *f, skp_error *err)
{
	if (p->next >= p->c.frame_count)
		return 0;
	return p->c.coded ? next_coded(p, f, err) : next_quantised(p, f, err);
}
