/* The frame's clocks: its time on the monotonic clock (or the virtual
 * display's), and the show on the wall clock (--sync=clock, board.ini
 * [show] sync):
 * each frame the clock says which clip and how far into it
 * (app/play/play_sync.h); the engine is set there, so every device
 * playing the same image on a synchronised clock shows the same pose at
 * the same instant. A device that was off the clock (started late, paused,
 * stopped, stalled) joins it with a crossfade, never a jump of the show.
 * Headless, the virtual display's frames lie on the clock's grid from the
 * epoch, so two runs started at different times render the same poses at
 * the same wall times. */
#include <math.h>
#include <stdio.h>
#include <time.h>

#include "cli_quiet.h"
#include "clock.h"
#include "play_sync.h"
#include "skinplay.h"

/* Off the clock by more than this: a join (crossfaded), not a correction;
 * a picture that stood still this long (a stop, a stall) joins too. */
#define SYNC_TOLERANCE_S 0.1
#define SYNC_STALL_S 0.5

/* The show's clips in display time at the speed (0: one that cannot play). */
static int show_lengths(const skinplay *p, uint64_t *len)
{
	double speed = p->o.speed;
	if (!p->o.image_count) {
		len[0] = (uint64_t)llround(play_duration(&p->eng) / speed * 1e9);
		return 1;
	}
	int n = show_clip_count(&p->show);
	for (int i = 0; i < n; i++) {
		const skp_image_clip *c = show_clip(&p->show, i);
		len[i] = p->show.playable[i] && c->fps > 0 ? (uint64_t)llround(c->frame_count / c->fps / speed * 1e9) : 0;
	}
	return n;
}

static int64_t frame_wall(const skinplay *p, long n)
{
	if (!p->headless)
		return clock_wall_ns();
	return p->o.epoch_ns + (int64_t)llround((double)(p->sync_frame0 + n) * (1e9 / p->o.display_rate));
}

static const char *utc(int64_t ns, char *buf, size_t n)
{
	time_t t = (time_t)(ns / 1000000000);
	struct tm tm;
	if (!gmtime_r(&t, &tm) || !strftime(buf, n, "%Y-%m-%dT%H:%M:%SZ", &tm))
		snprintf(buf, n, "%lld ns", (long long)ns);
	return buf;
}

void sync_begin(skinplay *p)
{
	char epoch[40], start[40];
	uint64_t len[SKP_IMAGE_MAX_CLIPS];
	if (p->o.sync != 1)
		return;
	skp_ratelimit_init(&p->sync_said, SKP_RATELIMIT_HOUR);
	int64_t wall = clock_wall_ns(), since = wall - p->o.epoch_ns;
	double period = 1e9 / p->o.display_rate;
	/* headless: the first frame on the clock's grid at or after now */
	p->sync_frame0 = (int64_t)ceil((double)since / period);
	uint64_t show = 0;
	int clips = show_lengths(p, len);
	for (int i = 0; i < clips; i++)
		show += len[i];
	fprintf(cli_note(), "sync: the show follows the wall clock from %s: %.2f s a show, %d clip%s", utc(p->o.epoch_ns, epoch, sizeof epoch),
		(double)show * 1e-9, clips, clips == 1 ? "" : "s");
	if (p->headless)
		fprintf(cli_note(), "; frame 1 shows %s, display frame %lld since then", utc(frame_wall(p, 0), start, sizeof start),
			(long long)p->sync_frame0);
	fprintf(cli_note(), "\n");
	p->sync_unsynced = clock_synchronised() == 0;
	if (p->sync_unsynced)
		fprintf(stderr, "sync: the kernel says this device's clock is not synchronised (no NTP or PTP daemon "
			"disciplines it: chrony, linuxptp): the show plays on this device's own clock\n");
}

/* The clock's clip, first or changed: as the show would change it. */
static void take_clip(skinplay *p, int clip)
{
	if (!p->sync_started)
		p->eng.shown = 0; /* the first pose is the clock's: nothing to fade from */
	clips_select(p, clip);
	if (!p->sync_started && p->render_ready) {
		render_set_yaw(&p->r, p->yaw + p->cam_yaw, 1);
		clips_frame(p, 1);
	}
}

/* Once an hour at most: how far off the clock the device was. */
static void say_join(skinplay *p, int stood, double still_s, double off_s)
{
	unsigned long held;
	p->sync_joins++;
	/* a stop of a second or more is always said; pauses once an hour */
	if (!(stood && still_s >= 1.0) && !skp_ratelimit_take(&p->sync_said, p->now, &held))
		return;
	if (stood)
		fprintf(stderr, "sync: %.2f s without a frame (a stop or a stall): joined the show's clock, crossfading "
			"over %d ms\n", still_s, p->o.blend_ms);
	else
		fprintf(stderr, "sync: %.2f s %s the show's clock (after a pause): joined it, crossfading over %d ms\n",
			fabs(off_s), off_s < 0 ? "behind" : "ahead of", p->o.blend_ms);
}

void sync_frame(skinplay *p, long n)
{
	uint64_t len[SKP_IMAGE_MAX_CLIPS];
	play_sync_at at;
	if (p->sync_detour) {
		/* a local NEXT: this clip from its start, then the clock again */
		p->sync_detour_until = p->now + (uint64_t)llround(play_duration(&p->eng) / p->o.speed * 1e9);
		p->sync_detour = 0;
	}
	if (p->o.sync != 1)
		return;
	if (p->hold || !p->kiosk.ps.playing || p->now < p->sync_detour_until) {
		/* off the clock: what is shown is the engine's */
		p->sync_last = p->eng.clip_time;
		p->sync_last_now = p->now;
		return;
	}
	if (play_sync_locate(frame_wall(p, n), p->o.epoch_ns, len, show_lengths(p, len), &at) < 0)
		return;
	double target = (double)at.into_ns * 1e-9 * p->o.speed;
	int changed = p->o.image_count && at.clip != p->show.clip;
	if (changed || !p->sync_started)
		take_clip(p, p->o.image_count ? at.clip : 0);
	/* the clip time the picture has moved on to; a picture that stood
	 * still (a stop, a stall) is off the clock however far the clock went */
	double dt = (double)(p->now - p->sync_last_now) * 1e-9, expect = p->sync_last + dt * p->o.speed;
	int stood = p->sync_started && dt > SYNC_STALL_S;
	int off = p->sync_started && !changed && (stood || play_sync_off(expect, target, SYNC_TOLERANCE_S));
	if (off)
		play_rejoin(&p->eng, target, p->now);
	else
		play_set_clip_time(&p->eng, target, p->now); /* a clip changed: select_clip crossfades */
	if (stood || off)
		say_join(p, stood, dt, p->sync_last - target);
	p->eng.travel = vec3_make(0.0f, 0.0f, 0.0f); /* travelling: the clip's own way, the same on every device */
	p->sync_last = target;
	p->sync_last_now = p->now;
	p->sync_started = 1;
}

unsigned sync_button(skinplay *p, unsigned act)
{
	const unsigned show_acts = KIOSK_ACT_PLAY | KIOSK_ACT_RESTART | KIOSK_ACT_CLIP;
	if (p->o.sync != 1 || !(act & show_acts))
		return act;
	if (!p->o.show_buttons) {
		/* [show] buttons = off: the clock keeps the show */
		p->kiosk.ps.playing = 1;
		p->kiosk.ps.clip = p->show.clip;
		return act & ~show_acts;
	}
	p->sync_detour = (act & (KIOSK_ACT_RESTART | KIOSK_ACT_CLIP)) != 0;
	return act;
}

uint64_t skinplay_frame_time(skinplay *p, long n)
{
	uint64_t mono = clock_now_ns();
	if (n == 0)
		p->wall0 = mono;
	return p->headless ? play_display_time(n, p->o.display_rate) : mono - p->wall0;
}
