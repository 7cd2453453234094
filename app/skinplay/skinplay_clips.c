/* Which clip plays: an AMC or BVH file, or the clips of an image, each
 * handed to the playback engine as its source. A clip that cannot play is
 * skipped with a log line and a notice on screen; with none that can, the
 * body holds its bind pose under a message and the loop goes on (the
 * watchdog is fed by the frame loop), so bad data never ends a kiosk. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli_error.h"
#include "cli_quiet.h"
#include "skinplay.h"

/* " (and N more since the last one said)" for a rate-limited line. */
static const char *said_since(unsigned long held)
{
	static char text[64];
	if (!held)
		return "";
	snprintf(text, sizeof text, " (and %lu more like it since the last line)", held);
	return text;
}

void clips_notice(skinplay *p, const char *text, double seconds)
{
	snprintf(p->notice, sizeof p->notice, "%s", text);
	p->notice_until = p->now + (uint64_t)(seconds * 1e9);
}

static void bind_pose(skinplay *p)
{
	fk_pose(&p->body.skel, p->body.pose_value, &p->skin.pose);
}

/* The joints' bounds in one pose (the held bind pose), as an extent's. */
static void survey_pose(skinplay *p, const skel_pose *pose)
{
	play_extent *s = &p->extent;
	s->frames = 1;
	s->first_root = s->lo = s->hi = pose->tip[0];
	for (int b = 0; b < p->body.skel.count; b++) {
		s->lo = vec3_min(s->lo, vec3_min(pose->head[b], pose->tip[b]));
		s->hi = vec3_max(s->hi, vec3_max(pose->head[b], pose->tip[b]));
	}
}

void clips_frame(skinplay *p, int immediate)
{
	const play_extent *s = &p->extent;
	if (!p->render_ready || s->frames <= 0 || !(s->hi.y >= s->lo.y))
		return;
	vec3 pad = vec3_make(p->flesh, p->flesh, p->flesh), root = vec3_make(s->first_root.x, 0.0f, s->first_root.z);
	vec3 lo = vec3_sub(vec3_sub(s->lo, root), pad), hi = vec3_add(vec3_sub(s->hi, root), pad);
	if (p->o.wall.columns > 0 && p->o.root == BOARD_ROOT_TRAVEL) {
		/* a wall's camera stays put: it frames the whole way travelled */
		lo = vec3_add(lo, s->travel_lo);
		hi = vec3_add(hi, s->travel_hi);
	}
	render_set_extent(&p->r, lo, hi, immediate);
}

/* No clip can play: the bind pose, for ever (until SIGTERM). */
static void hold_bind_pose(skinplay *p)
{
	p->hold = 1;
	bind_pose(p);
	survey_pose(p, &p->skin.pose);
	clips_frame(p, 0);
	snprintf(p->clip, sizeof p->clip, "NO CLIP");
	fprintf(stderr, "image: no clip of %s can play: holding the bind pose\n", show_path(&p->show));
	clips_notice(p, "NO PLAYABLE CLIP IN THIS SHOW", 1e9);
}

/* One pass over the clip: the space the body takes, which the camera
 * frames, and the camera's turn: --yaw, or the clip's mean facing. */
static void face_clip(skinplay *p)
{
	skp_error err;
	float yaw = p->o.yaw_mode == 1 ? p->o.yaw_deg * (float)(M_PI / 180.0) : 0.0f;
	/* every other frame: the peak of a kick is not missed */
	if (play_extent_clip(&p->body.skel, &p->src, 2, &p->scratch_frame, &p->scratch_pose, &p->extent, &err) !=
	    SKP_OK)
		p->extent.frames = 0;
	if (p->o.yaw_mode == 0 && p->extent.frames > 0 && p->extent.facing_known)
		yaw = p->extent.facing;
	p->yaw = yaw;
	fprintf(cli_note(), "clip: %ld frames at %.6g Hz (%.2f s); camera yaw %.0f degrees%s\n", p->src.frames, p->src.rate,
		(double)p->src.frames / p->src.rate, round(yaw / (M_PI / 180.0)) + 0.0, /* + 0.0: never "-0" */
		p->o.yaw_mode == 1 ? " (--yaw)" : p->extent.facing_known ? " (the clip's mean facing)" : "");
	if (p->render_ready)
		render_set_yaw(&p->r, yaw + p->cam_yaw, 0);
	clips_frame(p, 0);
}

/* The engine on p->src from its first frame, fading from what is shown;
 * a new clip (not a restart of this one) also turns the camera to it. */
static int start_clip(skinplay *p, const char *name, int new_clip)
{
	skp_error err;
	if (new_clip)
		face_clip(p);
	if (play_start(&p->eng, &p->src, p->now, &err) != SKP_OK) {
		cli_error(name, &err);
		return -1;
	}
	p->engine_failed = 0;
	snprintf(p->clip, sizeof p->clip, "%s", name);
	char *dot = strrchr(p->clip, '.');
	if (dot && !p->o.image_count)
		*dot = '\0';
	if (new_clip && p->clips_started++ == 0)
		snprintf(p->first_clip, sizeof p->first_clip, "%s", p->clip);
	return 0;
}

/* Opens clip c of the image, or the next one that can play when it cannot
 * (or fails now, the medium worse than at acceptance). */
static void select_clip(skinplay *p, int c)
{
	for (int tries = show_clip_count(&p->show); tries > 0; tries--) {
		int next = show_next_playable(&p->show, c);
		if (next < 0)
			break;
		const char *name = show_clip(&p->show, next)->name;
		if (next != c && c >= 0) {
			char text[96];
			unsigned long held;
			snprintf(text, sizeof text, "CLIP %s SKIPPED: DAMAGED", show_clip(&p->show, c)->name);
			if (skp_ratelimit_take(&p->skip_said, p->now, &held))
				fprintf(stderr, "image: clip %s cannot play: showing %s%s\n", show_clip(&p->show, c)->name, name,
					said_since(held));
			clips_notice(p, text, 3.0);
		}
		if (show_select_clip(&p->show, name, &p->src) == 0 && start_clip(p, name, 1) == 0) {
			p->kiosk.ps.clip = next;
			p->hold = 0;
			return;
		}
		p->show.playable[next] = 0;
		c = next;
	}
	hold_bind_pose(p);
}

void clips_select(skinplay *p, int c)
{
	select_clip(p, c);
}

/* --start FRAME: the clip's clock set to that frame's time. */
static int start_at_frame(skinplay *p, const char *what)
{
	long first = p->eng.cur.number_a, index = p->o.start - first;
	if (index < 0 || index > p->eng.cur.last) {
		fprintf(stderr, "%s: no frame %ld (frames %ld..%ld)\n", what, p->o.start, first, first + p->eng.cur.last);
		return -1;
	}
	p->start_time = (double)index / p->src.rate;
	play_set_clip_time(&p->eng, p->start_time, p->now);
	return 0;
}

/* A run for its frames, not a screen's (the display is not open yet when
 * the first clip is chosen): frames written, or a headless GL platform
 * named. --platform none stands for the kiosk in soaks: it plays on. */
static int batch_run(const skinplay *p)
{
	const char *pl = p->o.platform;
	return p->o.out_dir || (pl && (!strcmp(pl, "surfaceless") || !strcmp(pl, "osmesa")));
}

/* In a batch run a --clip the show does not have is a mistake: refused,
 * with the names it has. -1. */
static int no_such_clip(skinplay *p)
{
	fprintf(stderr, "skinplay: %s has no clip '%s'; its clips:", cli_shown(show_path(&p->show)), cli_shown(p->o.clip));
	for (int i = 0; i < show_clip_count(&p->show); i++)
		fprintf(stderr, "%s %s", i ? "," : "", cli_shown(show_clip(&p->show, i)->name));
	fprintf(stderr, "\n");
	return -1;
}

/* The clip asked for by name (--clip) or frame (--start); on a screen one
 * that is not in the show or cannot play gives way to the next that can,
 * with a notice: a kiosk never goes dark over it. 1 when it plays as
 * asked, -1 (a batch run, no such clip) refused. */
static int open_asked(skinplay *p)
{
	if (show_select_clip(&p->show, p->o.clip, &p->src) == 0 &&
	    start_clip(p, show_clip(&p->show, p->show.clip)->name, 1) == 0) {
		p->kiosk.ps.clip = p->show.clip;
		return 1;
	}
	int c = -1;
	for (int i = 0; p->o.clip && i < show_clip_count(&p->show); i++)
		if (!strcmp(show_clip(&p->show, i)->name, p->o.clip))
			c = i;
	if (c < 0 && p->o.clip && batch_run(p))
		return no_such_clip(p);
	c = c < 0 ? 0 : c;
	char text[96];
	snprintf(text, sizeof text, "CLIP %s CANNOT PLAY", cli_shown(p->o.clip));
	fprintf(stderr, "skinplay: --clip %s cannot play: the next clip that can plays instead\n", cli_shown(p->o.clip));
	select_clip(p, c);
	clips_notice(p, text, 5.0);
	return 0;
}

static int open_first(skinplay *p)
{
	const char *what = p->o.image_count ? show_path(&p->show) : p->o.amc;
	if (!p->o.image_count) {
		if (clip_file_open(&p->text, p->o.amc, &p->body.skel, p->o.fps, &p->src) < 0 ||
		    start_clip(p, cli_basename(p->o.amc), 1) < 0)
			return -1;
	} else if (p->o.clip || p->o.start >= 0) {
		int asked = open_asked(p);
		if (asked <= 0)
			return asked; /* --start was for the clip asked for */
	} else
		select_clip(p, 0);
	return p->o.start >= 0 && !p->hold ? start_at_frame(p, what) : 0;
}

/* How far the body's bounds [lo, hi] reach past its joints' in the pose
 * shown, on the side where it is most: the head over its bone, a foot's
 * sole under its joints. The camera grows every clip's bounds by it. */
static float flesh_past_joints(skinplay *p, vec3 lo, vec3 hi)
{
	play_extent saved = p->extent;
	survey_pose(p, &p->skin.pose);
	vec3 a = vec3_sub(p->extent.lo, lo), b = vec3_sub(hi, p->extent.hi);
	p->extent = saved;
	float f = fmaxf(fmaxf(fmaxf(a.x, a.y), a.z), fmaxf(fmaxf(b.x, b.y), b.z));
	return f > 0.0f ? f : 0.0f;
}

/* The lowest point of the body in the clip's first frame: the floor. */
float clips_first(skinplay *p)
{
	play_config cfg = { p->o.speed, (uint32_t)p->o.blend_ms, p->o.root, 1 };
	skp_ratelimit_init(&p->skip_said, SKP_RATELIMIT_HOUR);
	skp_ratelimit_init(&p->fail_said, SKP_RATELIMIT_HOUR);
	play_init(&p->eng, &p->body.skel, &cfg);
	/* synchronised devices hold the root at one place whichever clip each
	 * started with */
	p->eng.have_origin = p->o.sync == 1;
	p->now = 0;
	if (open_first(p) < 0)
		return NAN;
	if (!p->hold && clips_pose(p) < 0)
		return NAN;
	runtime_skin_pose(&p->skin, &p->skin.pose);
	runtime_skin_run(&p->skin, SKIN_DQBS, p->pos[0], p->nrm[0]);
	vec3 lo = vec3_make(INFINITY, INFINITY, INFINITY), hi = vec3_scale(lo, -1.0f);
	for (int v = 0; v < p->body.mesh.vert_count; v++) {
		const float *q = &p->pos[0][3 * v];
		lo = vec3_min(lo, vec3_make(q[0], q[1], q[2]));
		hi = vec3_max(hi, vec3_make(q[0], q[1], q[2]));
	}
	p->flesh = flesh_past_joints(p, lo, hi);
	return lo.y;
}

int clips_show_loops(const skinplay *p)
{
	return p->o.loop == BOARD_LOOP_SHOW && p->o.image_count && !p->hold &&
	       show_next_playable(&p->show, (p->show.clip + 1) % show_clip_count(&p->show)) != p->show.clip;
}

/* The pass ended and the show goes on: the next clip, round the end,
 * crossfading from the pose on screen. 1 when it changed. */
static int next_in_show(skinplay *p)
{
	if (p->eng.pass == 0 || !clips_show_loops(p))
		return 0;
	select_clip(p, (p->show.clip + 1) % show_clip_count(&p->show));
	return !p->hold;
}

int clips_pose(skinplay *p)
{
	skp_error err;
	p->show.now = p->now;   /* the image's log lines are limited on this clock */
	if (p->hold)
		return 0;
	skp_status st = play_update(&p->eng, p->now, &err);
	if (st == SKP_OK && next_in_show(p))
		st = play_update(&p->eng, p->now, &err);
	if (st != SKP_OK) {
		/* headless, a file that cannot be read is an error; a kiosk holds */
		if (p->headless)
			return cli_error(p->o.image_count ? show_path(&p->show) : p->o.amc, &err), -1;
		unsigned long held;
		if (!p->engine_failed && skp_ratelimit_take(&p->fail_said, p->now, &held)) {
			cli_error(p->o.image_count ? show_path(&p->show) : p->o.amc, &err);
			fprintf(stderr, "skinplay: clip %s cannot be read on: holding its last pose%s\n", p->clip,
				said_since(held));
		}
		if (!p->engine_failed)
			clips_notice(p, "THIS CLIP CANNOT BE READ ON", 5.0);
		p->engine_failed = 1;
		return 0;
	}
	p->skin.pose = p->eng.pose;
	return 0;
}

void clips_restart(skinplay *p, int clip)
{
	if (p->hold)
		return;
	if (clip >= 0 && p->o.image_count) {
		select_clip(p, clip);
		return;
	}
	start_clip(p, p->o.image_count ? show_clip(&p->show, p->show.clip)->name : cli_basename(p->o.amc), 0);
}

/* Display frames before a looping clip of that many seconds wraps: those
 * whose time is short of its end (the next clip shows at the end's time). */
static long frames_before_end(const skinplay *p, double seconds)
{
	long n = (long)ceil(seconds * p->o.display_rate / p->o.speed - 1e-9);
	return n > 0 ? n : 1;
}

long clips_pass_frames(skinplay *p)
{
	if (p->hold)
		return 1;
	if (!clips_show_loops(p))
		return play_pass_frames_from(&p->eng, p->o.display_rate, p->start_time);
	long n = frames_before_end(p, play_duration(&p->eng) - p->start_time);
	for (int i = 0; i < show_clip_count(&p->show); i++) {
		const skp_image_clip *c = show_clip(&p->show, i);
		if (i != p->show.clip && p->show.playable[i])
			n += frames_before_end(p, (double)c->frame_count / c->fps);
	}
	return n;
}
