#include "play_engine.h"

#include <math.h>
#include <string.h>

#include "play_blend.h"

void play_config_defaults(play_config *c)
{
	c->speed = 1.0;
	c->blend_ms = PLAY_BLEND_MS_DEFAULT;
	c->root = PLAY_ROOT_IN_PLACE;
	c->loop = 1;
}

void play_init(play_engine *e, const skel *s, const play_config *cfg)
{
	memset(e, 0, sizeof *e);
	e->s = s;
	e->cfg = *cfg;
	if (!(e->cfg.speed >= PLAY_SPEED_MIN && e->cfg.speed <= PLAY_SPEED_MAX))
		e->cfg.speed = 1.0;
	if (e->cfg.blend_ms > PLAY_BLEND_MS_MAX)
		e->cfg.blend_ms = PLAY_BLEND_MS_MAX;
	play_clock_init(&e->clock);
}

double play_duration(const play_engine *e)
{
	return (double)(e->cur.last + 1) / e->cur.src.rate;
}

long play_pass_frames_from(const play_engine *e, double hz, double from)
{
	double left = play_duration(e) - from;
	/* the epsilon keeps 343.0 from being 342.99999 */
	return left > 0.0 ? (long)floor(left * hz / e->cfg.speed + 1e-9) + 1 : 1;
}

long play_pass_frames(const play_engine *e, double hz)
{
	return play_pass_frames_from(e, hz, 0.0);
}

static vec3 root_of(const play_engine *e, const skel_local *l)
{
	return vec3_add(e->s->root_position, l->trans[0]);
}

/* In place: the root's horizontal position held at the origin; travel:
 * moved by the offset that carries this pass on from the last. */
static void place_root(const play_engine *e, skel_local *l)
{
	vec3 *t = &l->trans[0];
	if (e->cfg.root == PLAY_ROOT_IN_PLACE) {
		t->x = e->origin.x - e->s->root_position.x;
		t->z = e->origin.z - e->s->root_position.z;
	} else {
		t->x += e->travel.x;
		t->z += e->travel.z;
	}
}

static void begin_fade(play_engine *e, const skel_local *from, uint64_t at)
{
	if (!e->shown || e->cfg.blend_ms == 0)
		return;
	e->from = *from;
	e->fade_start = at;
	e->fading = 1;
}

skp_status play_start(play_engine *e, const play_source *src, uint64_t now, skp_error *err)
{
	uint64_t t = play_clock_active(&e->clock, now);
	skp_status st = play_cursor_open(&e->cur, e->s, src, err);
	if (st != SKP_OK)
		return st;
	e->first_root = root_of(e, &e->cur.a);
	if (!e->have_origin) {
		e->origin = e->first_root;
		e->have_origin = 1;
	}
	/* travel: the new clip goes on from where the body is */
	vec3 at = e->shown ? root_of(e, &e->local) : e->first_root;
	e->travel = vec3_make(at.x - e->first_root.x, 0.0f, at.z - e->first_root.z);
	begin_fade(e, &e->local, t);
	e->clip_start = t;
	e->pass = 0;
	e->started = 1;
	return SKP_OK;
}

/* The end of a pass: the next one starts where the clock is, fading from
 * the last frame, its root carried on by the pass's travel. */
static skp_status wrap(play_engine *e, double *clip_time, skp_error *err)
{
	double d = play_duration(e);
	long unused;
	skp_status st = play_cursor_sample(&e->cur, (double)e->cur.last, &e->sampled, &unused, err);
	if (st != SKP_OK)
		return st;
	vec3 last = root_of(e, &e->sampled);
	place_root(e, &e->sampled);
	e->clip_start += (uint64_t)llround(d / e->cfg.speed * 1e9);
	begin_fade(e, &e->sampled, e->clip_start);
	e->travel.x += last.x - e->first_root.x;
	e->travel.z += last.z - e->first_root.z;
	e->pass++;
	*clip_time -= d;
	return SKP_OK;
}

static double clip_time_at(const play_engine *e, uint64_t t)
{
	/* clip_start may lie before active time 0 (play_set_clip_time): the
	 * difference is right in unsigned arithmetic */
	int64_t d = (int64_t)(t - e->clip_start);
	return d > 0 ? (double)d * 1e-9 * e->cfg.speed : 0.0;
}

/* The captured index of a clip time, snapped to a whole frame when it is
 * one but for rounding (display frame n at 60 Hz is frame 2n at 120 Hz). */
static double frame_index(const play_engine *e, double clip_time)
{
	double x = clip_time * e->cur.src.rate, r = floor(x + 0.5);
	return fabs(x - r) < 1e-6 ? r : x;
}

/* The clip's pose at clip_time into sampled (root placed) and number. */
static skp_status sample(play_engine *e, double clip_time, skp_error *err)
{
	skp_status st = play_cursor_sample(&e->cur, frame_index(e, clip_time), &e->sampled, &e->number, err);
	if (st == SKP_OK)
		place_root(e, &e->sampled);
	return st;
}

skp_status play_sample_at(play_engine *e, double clip_time, skp_error *err)
{
	if (!e->started)
		return skp_fail(err, SKP_ERR_RANGE, 0, "no clip started");
	double d = play_duration(e);
	clip_time = clip_time > d ? d : clip_time > 0.0 ? clip_time : 0.0;
	skp_status st = sample(e, clip_time, err);
	if (st != SKP_OK)
		return st;
	e->local = e->sampled;
	fk_from_local(e->s, &e->local, &e->pose);
	e->clip_time = clip_time;
	return SKP_OK;
}

/* Over the sampled pose, the pose a crossfade started from, fading out. */
static void fade(play_engine *e, uint64_t t)
{
	e->local = e->sampled;
	if (!e->fading)
		return;
	int64_t since = (int64_t)(t - e->fade_start);
	double x = since > 0 ? (double)since / ((double)e->cfg.blend_ms * 1e6) : 0.0;
	if (x >= 1.0) {
		e->fading = 0;
		return;
	}
	play_blend(e->s, &e->from, &e->sampled, play_fade_weight(x), &e->local);
	/* the root's way over the ground is not faded: in place it is held,
	 * travelling the new pass goes on from where the old one ended */
	e->local.trans[0].x = e->sampled.trans[0].x;
	e->local.trans[0].z = e->sampled.trans[0].z;
}

skp_status play_update(play_engine *e, uint64_t now, skp_error *err)
{
	if (!e->started)
		return skp_fail(err, SKP_ERR_RANGE, 0, "no clip started");
	uint64_t t = play_clock_active(&e->clock, now);
	double clip_time = clip_time_at(e, t), d = play_duration(e);
	if (e->cfg.loop && clip_time >= 2.0 * d) {
		/* passes nobody saw (a process stopped for an hour): by time alone */
		double k = floor(clip_time / d) - 1.0;
		e->clip_start += (uint64_t)llround(k * d / e->cfg.speed * 1e9);
		e->pass += (long)k;
		clip_time = clip_time_at(e, t);
	}
	while (e->cfg.loop && clip_time >= d) {
		skp_status st = wrap(e, &clip_time, err);
		if (st != SKP_OK)
			return st;
		d = play_duration(e);
	}
	if (clip_time > d)
		clip_time = d;
	skp_status st = sample(e, clip_time, err);
	if (st != SKP_OK)
		return st;
	fade(e, t);
	fk_from_local(e->s, &e->local, &e->pose);
	e->clip_time = clip_time;
	e->shown = 1;
	return SKP_OK;
}

void play_set_clip_time(play_engine *e, double clip_time, uint64_t now)
{
	uint64_t t = play_clock_active(&e->clock, now), back = (uint64_t)llround(clip_time / e->cfg.speed * 1e9);
	e->clip_start = t - back; /* unsigned: clip_time_at() sees t - clip_start */
}

void play_pause(play_engine *e, int paused, uint64_t now)
{
	play_clock_pause(&e->clock, paused, now);
}

void play_rejoin(play_engine *e, double clip_time, uint64_t now)
{
	begin_fade(e, &e->local, play_clock_active(&e->clock, now));
	play_set_clip_time(e, clip_time, now);
}
