/* Where skinplay's frames come from: an AMC stream, or the clips of an
 * image. A clip that cannot play is skipped with a log line and a notice on
 * screen; with none that can, the body holds its bind pose under a message
 * and the loop goes on (the watchdog is fed by the frame loop), so bad data
 * never ends a kiosk. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "skinplay.h"

void frames_notice(player *p, const char *text, double seconds)
{
	snprintf(p->notice, sizeof p->notice, "%s", text);
	p->notice_frames = (long)(seconds * (p->o.fps > 0 ? p->o.fps : 60.0));
}

/* No clip can play: the bind pose, for ever (until SIGTERM). */
static void hold_bind_pose(player *p)
{
	p->hold = 1;
	memcpy(p->frame.value, p->body.pose_value, sizeof p->frame.value);
	p->frame.number = 0;
	p->frame.line = 0;
	snprintf(p->clip, sizeof p->clip, "NO CLIP");
	fprintf(stderr, "image: no clip of %s can play: holding the bind pose\n", show_path(&p->show));
	frames_notice(p, "NO PLAYABLE CLIP IN THIS SHOW", 1e9);
}

/* Opens clip c of the image, or the next one that can play when it cannot
 * (or fails now, the medium worse than at acceptance). */
static void select_clip(player *p, int c)
{
	for (int tries = show_clip_count(&p->show); tries > 0; tries--) {
		int next = show_next_playable(&p->show, c);
		if (next < 0)
			break;
		if (next != c && c >= 0) {
			char text[96];
			snprintf(text, sizeof text, "CLIP %s SKIPPED: DAMAGED", show_clip(&p->show, c)->name);
			fprintf(stderr, "image: clip %s cannot play: showing %s\n", show_clip(&p->show, c)->name,
				show_clip(&p->show, next)->name);
			frames_notice(p, text, 3.0);
		}
		if (show_select_clip(&p->show, show_clip(&p->show, next)->name, -1) == 0) {
			snprintf(p->clip, sizeof p->clip, "%s", show_clip(&p->show, next)->name);
			p->kiosk.ps.clip = next;
			p->hold = 0;
			return;
		}
		p->show.playable[next] = 0;
		c = next;
	}
	hold_bind_pose(p);
}

/* The lowest point of the body in the clip's first frame: the floor. */
float frames_first(player *p)
{
	amc_frame *f = &p->frame;
	if (p->o.image_count && (p->o.clip || p->o.start >= 0)) {
		/* asked for by name or frame: that, or a message and no show */
		if (show_select_clip(&p->show, p->o.clip, p->o.start) < 0 || show_next_frame(&p->show, f) <= 0)
			return NAN;
		p->pending = 1;
	} else if (p->o.image_count) {
		select_clip(p, 0);
		if (!p->hold)
			show_next_frame(&p->show, f);
		p->pending = 1;
	} else if (cli_read_frame(p->o.amc, &p->body.skel, p->o.start, f) < 0)
		return NAN;
	cli_skin_frame(&p->skin, f->value);
	cli_skin_run(&p->skin, SKIN_DQBS, p->pos[0], p->nrm[0]);
	float lo = INFINITY;
	for (int v = 0; v < p->body.mesh.vert_count; v++)
		lo = fminf(lo, p->pos[0][3 * v + 1]);
	return lo;
}

int frames_open(player *p)
{
	if (p->o.image_count)
		return 0; /* frames_first() opened the clip and read ahead its first frame */
	if (cli_motion_open(&p->motion, p->o.amc, &p->body.skel) < 0)
		return -1;
	if (p->o.start < 0)
		return 0;
	/* skip to the start frame (the stream has no index to seek with) and
	 * keep it for the first next_frame() */
	int r;
	while ((r = cli_motion_next(&p->motion, &p->frame)) > 0 && p->frame.number < p->o.start)
		;
	if (r == 0)
		fprintf(stderr, "%s: no frame %ld\n", p->o.amc, p->o.start);
	p->pending = r > 0;
	return r <= 0 ? -1 : 0;
}

/* The next frame of the clip, looping on a display and whenever --frames
 * asks for more frames than the clip has (`make soak`). 1, 0 at the end, -1. */
int frames_next(player *p)
{
	if (p->pending) {
		p->pending = 0;
		return 1;
	}
	if (p->hold)
		return p->headless && p->o.frames < 0 ? 0 : 1;
	int r = p->o.image_count ? show_next_frame(&p->show, &p->frame) : cli_motion_next(&p->motion, &p->frame);
	if (r != 0 || (p->headless && p->o.frames < 0))
		return r;
	if (p->o.image_count) {
		show_rewind(&p->show);
		return show_next_frame(&p->show, &p->frame);
	}
	cli_motion_close(&p->motion);
	if (cli_motion_open(&p->motion, p->o.amc, &p->body.skel) < 0)
		return -1;
	return cli_motion_next(&p->motion, &p->frame);
}

long frames_clip_length(player *p)
{
	if (p->o.image_count) {
		const show_source *s = &p->show;
		return s->clip >= 0 ? (long)s->slot[s->active].im.clip[s->clip].frame_count : 1;
	}
	long n = cli_motion_count(p->o.amc, &p->body.skel);
	return n > 0 ? n : 1;
}

/* PLAY long, NEXT: back to the first frame of the clip (or of clip i). */
int frames_restart(player *p, int clip)
{
	p->pending = 0;
	if (p->o.image_count) {
		if (p->hold)
			return 0;
		if (clip < 0) {
			show_rewind(&p->show);
			return 0;
		}
		select_clip(p, clip);
		return 0;
	}
	cli_motion_close(&p->motion);
	return cli_motion_open(&p->motion, p->o.amc, &p->body.skel);
}

