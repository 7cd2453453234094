#include "play_image_source.h"

#include <string.h>

static int image_next(void *ctx, amc_frame *f, skp_error *err)
{
	play_image_source *s = ctx;
	int dofs = s->stream.c.dofs;
	int r = skp_clip_stream_next(&s->stream, f, err);
	if (r == 1) {
		memcpy(s->last.value, f->value, sizeof(float) * (size_t)dofs);
		s->last.number = f->number;
		s->have_last = 1;
		return 1;
	}
	if (r != SKP_CLIP_LOST)
		return r;
	s->lost_frames++;
	s->pass_lost++;
	/* nothing good yet: the ASF rest pose (every value 0), never undecoded values */
	if (!s->have_last) {
		memset(s->last.value, 0, sizeof s->last.value);
		s->last.number = (long)s->stream.c.first_number + (long)s->stream.next - 1;
		s->have_last = 1;
	}
	if (s->on_lost)
		s->on_lost(s->ctx, err->block, err->msg, s->last.number);
	memcpy(f->value, s->last.value, sizeof(float) * (size_t)dofs);
	f->number = s->last.number;
	f->line = 0;
	return 1;
}

static skp_status image_seek(void *ctx, long index, skp_error *err)
{
	play_image_source *s = ctx;
	if (index < 0 || index >= (long)s->stream.c.frame_count)
		return skp_fail(err, SKP_ERR_RANGE, 0, "clip %s has no frame index %ld", s->stream.c.name, index);
	if (index == 0 && s->on_rewind)
		s->on_rewind(s->ctx);
	if (index == 0)
		s->pass_lost = 0;
	skp_clip_stream_seek(&s->stream, (uint32_t)index);
	return SKP_OK;
}

skp_status play_image_source_open(play_image_source *s, skp_image *im, int clip, skp_error *err)
{
	s->have_last = 0;
	s->pass_lost = 0;
	return skp_clip_stream_open(&s->stream, im, clip, err);
}

play_source play_image_source_get(play_image_source *s)
{
	play_source src = { s, image_next, image_seek, (long)s->stream.c.frame_count, (double)s->stream.c.fps, 1 };
	return src;
}
