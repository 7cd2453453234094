#include "clip_file.h"
#include "cli_say.h"
#include "motion_file.h"

#include <math.h>

static int clip_next(void *ctx, amc_frame *f, skp_error *err)
{
	clip_file *c = ctx;
	int r = motion_file_read(&c->m, f, err);
	if (r > 0)
		c->next++;
	return r;
}

static skp_status clip_seek(void *ctx, long index, skp_error *err)
{
	static amc_frame skipped;
	clip_file *c = ctx;
	if (index < c->next || !c->open) {
		if (c->open)
			motion_file_close(&c->m);
		c->open = 0;
		if (motion_file_open(&c->m, c->path, c->s) < 0)
			return skp_fail(err, SKP_ERR_IO, 0, "cannot reopen the file");
		c->open = 1;
		c->next = 0;
	}
	while (c->next < index) {
		int r = clip_next(c, &skipped, err);
		if (r <= 0)
			return r < 0 ? (skp_status)r : skp_fail(err, SKP_ERR_RANGE, 0, "no frame index %ld", index);
	}
	return SKP_OK;
}

int clip_file_open(clip_file *c, const char *path, const skel *s, double amc_fps, play_source *out)
{
	long frames = motion_file_count(path, s);
	c->path = path;
	c->s = s;
	c->open = 0;
	if (frames < 0)
		return -1;
	if (frames == 0) {
		cli_warn("%s: no frames\n", path);
		return -1;
	}
	if (motion_file_open(&c->m, path, s) < 0)
		return -1;
	c->open = 1;
	c->next = 0;
	double rate = amc_fps > 0 ? amc_fps : CLI_DEFAULT_FPS;
	if (c->m.is_bvh) {
		double ft = c->m.layout.frame_time;
		if (!(ft >= 1e-6 && ft <= 10.0)) {
			cli_warn("%s: Frame Time %g s: expected 1 us to 10 s\n", path, ft);
			clip_file_close(c);
			return -1;
		}
		rate = 1.0 / ft;
	}
	play_source src = { c, clip_next, clip_seek, frames, rate, 0 };
	*out = src;
	return 0;
}

void clip_file_close(clip_file *c)
{
	if (c->open)
		motion_file_close(&c->m);
	c->open = 0;
}
