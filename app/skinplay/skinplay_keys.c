/* A window's time keys (app/runtime/kiosk_shell.h): one captured frame
 * back or on while paused, a second back or on, the speed halved or
 * doubled; and the keys' legend, shown where they work. The pose moves at
 * once (a cut: the engineer asked for that frame), and the motion goes on
 * from there at its speed. A synchronised show keeps its clock: the keys
 * say so and do nothing. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli_quiet.h"
#include "skinplay.h"

static const double speeds[] = { 0.125, 0.25, 0.5, 1.0, 2.0, 4.0 };

/* The clip time asked for, kept on the clip: its first frame to its last. */
static double on_clip(const skinplay *p, double t)
{
	double last = (double)p->eng.cur.last / p->src.rate;
	return t < 0.0 ? 0.0 : t > last ? last : t;
}

static void step(skinplay *p)
{
	if (p->kiosk.ps.playing) {
		clips_notice(p, "PAUSE (SPACE) TO STEP FRAME BY FRAME", 2.0);
		return;
	}
	double frame = floor(p->eng.clip_time * p->src.rate + 0.5) + p->kiosk.step;
	play_set_clip_time(&p->eng, on_clip(p, frame / p->src.rate), p->now);
	fprintf(cli_note(), "input: key %s -> frame %ld\n", p->kiosk.step < 0 ? "left" : "right",
		p->eng.cur.number_a + (long)floor(p->eng.clip_time * p->src.rate + 0.5) + p->kiosk.step);
}

static void seek(skinplay *p)
{
	double t = on_clip(p, p->eng.clip_time + p->kiosk.seek);
	play_set_clip_time(&p->eng, t, p->now);
	fprintf(cli_note(), "input: key %c -> %.2f s\n", p->kiosk.seek < 0 ? '[' : ']', t);
}

/* The next speed of the list either way; the clip time kept. */
static void speed(skinplay *p)
{
	int i = 0, n = (int)(sizeof speeds / sizeof speeds[0]);
	while (i < n - 1 && speeds[i] < p->o.speed - 1e-9)
		i++;
	i += p->kiosk.speed_step;
	i = i < 0 ? 0 : i >= n ? n - 1 : i;
	double t = p->eng.clip_time;
	p->o.speed = p->eng.cfg.speed = speeds[i];
	play_set_clip_time(&p->eng, t, p->now);
	char text[32];
	snprintf(text, sizeof text, "SPEED %gX", speeds[i]);
	clips_notice(p, text, 2.0);
	fprintf(cli_note(), "input: key %c -> speed %g\n", p->kiosk.speed_step < 0 ? '-' : '+', speeds[i]);
}

void keys_time(skinplay *p, unsigned act)
{
	if (!(act & (KIOSK_ACT_STEP | KIOSK_ACT_SEEK | KIOSK_ACT_SPEED)) || p->hold)
		return;
	if (p->o.sync == 1) {
		clips_notice(p, "THE SHOW FOLLOWS THE CLOCK (--sync)", 2.0);
		return;
	}
	if (act & KIOSK_ACT_STEP)
		step(p);
	if (act & KIOSK_ACT_SEEK)
		seek(p);
	if (act & KIOSK_ACT_SPEED)
		speed(p);
}

const char *keys_legend(const skinplay *p, int engineer)
{
	const kiosk_shell *k = &p->kiosk;
	int window = p->disp && p->disp->key, terminal = k->in && k->in->key;
	if (window || terminal) {
		/* the engineer's: the keys 5 s, then the camera's 5 s (a window's
		 * pointer, else a console's keys), then the figures alone */
		if (!engineer || p->now < 5000000000ull)
			return KIOSK_KEYS_LEGEND;
		return p->now < 10000000000ull ? (window ? KIOSK_MOUSE_LEGEND : KIOSK_CAMERA_LEGEND) : NULL;
	}
	if (engineer)
		return NULL;
	if (k->in && !strcmp(k->in->name, "gpio"))
		return "BUTTONS: ALGO CHANGES THE METHOD   PLAY PAUSES   NEXT CLIP   VIEW";
	return NULL;
}
