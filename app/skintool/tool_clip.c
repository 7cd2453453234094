#include "tool_clip.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "motion_file.h"

static int grow(tool_clip *c, long *cap)
{
	long want = *cap ? *cap * 2 : 1024;
	float *p = realloc(c->frames, sizeof(float) * (size_t)want * (size_t)(c->dofs ? c->dofs : 1));
	if (!p)
		return -1;
	c->frames = p;
	*cap = want;
	return 0;
}

int tool_clip_load(const char *path, const skel *s, tool_clip *c)
{
	static motion_file m;
	static amc_frame f;
	long cap = 0;
	int r;
	memset(c, 0, sizeof *c);
	c->dofs = s->dof_count;
	if (motion_file_open(&m, path, s) < 0)
		return -1;
	c->rate = m.is_bvh ? 1.0 / m.layout.frame_time : 0.0;
	while ((r = motion_file_next(&m, &f)) > 0) {
		if (c->n == cap && grow(c, &cap) < 0) {
			fprintf(stderr, "%s: out of memory at frame %ld\n", path, f.number);
			r = -1;
			break;
		}
		if (c->n == 0)
			c->first_number = f.number;
		memcpy(c->frames + (size_t)c->n * (size_t)c->dofs, f.value, sizeof(float) * (size_t)c->dofs);
		c->n++;
	}
	motion_file_close(&m);
	if (r == 0 && c->n == 0) {
		fprintf(stderr, "%s: no frames\n", path);
		r = -1;
	}
	if (r < 0)
		tool_clip_free(c);
	return r < 0 ? -1 : 0;
}

void tool_clip_free(tool_clip *c)
{
	free(c->frames);
	c->frames = NULL;
	c->n = 0;
}
