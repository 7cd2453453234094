/* The image slots watched (show_watch.h). A kiosk with no show it can
 * play (every image slot missing, damaged beyond use or refused) does not
 * exit into a restart loop and a dark screen: it says so on the screen,
 * keeps feeding the watchdog and answers signals, and once a slot file has
 * changed and then stood still for a moment (a new show copied in), it
 * starts over. While a show plays, a slot that changed and holds a whole
 * image starts it over too. */
#include <stdio.h>
#include <string.h>

#include "cli_error.h"
#include "cli_quiet.h"
#include "clock.h"
#include "show_watch.h"
#include "skinplay.h"

#define WAIT_POLL_NS SHOW_WATCH_POLL_NS /* the screen redrawn as often as the slots are looked at */

/* The notice's lines: what is wrong, the slots, where to read more. */
static int notice_lines(const play_opts *o, char slots[160], const char *lines[5])
{
	int at = snprintf(slots, 160, "SLOTS:");
	for (int i = 0; i < o->image_count && at < 150; i++)
		at += snprintf(slots + at, 160 - (size_t)at, " %s", cli_basename(o->image[i]));
	lines[0] = "NO SHOW TO PLAY";
	lines[1] = "NO IMAGE SLOT HOLDS A SHOW THAT CAN PLAY";
	lines[2] = slots;
	lines[3] = "THE LOG SAYS WHY: JOURNALCTL -U SKINPLAY";
	lines[4] = "A NEW SHOW COPIED INTO A SLOT STARTS BY ITSELF";
	return 5;
}

static int show_notice(skinplay *p, const char *const *lines, int n)
{
	skp_error err;
	render_draw_notice(&p->r, lines, n);
	p->gl.Finish();
	if (p->disp->present(&err) != 0) {
		fprintf(stderr, "skinplay: %s: %s\n", p->disp->name, err.msg);
		return -1;
	}
	return 0;
}

static int wait_loop(skinplay *p, show_watch *w)
{
	char slots[160];
	const char *lines[5];
	int n = notice_lines(&p->o, slots, lines), quit = 0;
	for (long frame = 0; !quit; frame++) {
		unsigned act = kiosk_shell_frame(&p->kiosk, frame);
		if (act & (KIOSK_ACT_QUIT | KIOSK_ACT_RELOAD)) {
			p->reload = !(act & KIOSK_ACT_QUIT);
			return 0;
		}
		uint64_t now = clock_now_ns();
		if (show_watch_poll(w, now, 0)) {
			fprintf(stderr, "skinplay: an image slot changed: starting over\n");
			p->reload = 1;
			return 0;
		}
		if (show_notice(p, lines, n) < 0)
			return 1;
		if (p->disp->handle_events)
			p->disp->handle_events(&quit);
		clock_sleep_until_ns(now + WAIT_POLL_NS);
	}
	return 0;
}

int wait_for_show(skinplay *p)
{
	skp_error err;
	show_watch w;
	show_watch_init(&w, p->o.image, p->o.image_count);
	/* a batch run, or nowhere to say it: the error stands */
	if ((p->o.platform && !strcmp(p->o.platform, "none")) || open_display(p) < 0 || p->headless)
		return 1;
	if (render_init_notice(&p->r, &p->gl, p->info.width, p->info.height, p->info.rotation, &err) != SKP_OK) {
		fprintf(stderr, "skinplay: renderer: %s\n", err.msg);
		return 1;
	}
	if (skinplay_kiosk_start(&p->kiosk, &p->o, 0, 1) < 0)
		return 1;
	fprintf(stderr, "skinplay: no image slot holds a show that can play: saying so on the screen, waiting for one\n");
	return wait_loop(p, &w);
}

/* A slot changed under the show and now holds a whole image (a new show
 * copied in, or one written over the playing one): the show opens again,
 * as for SIGHUP. Not in a run writing frames: its output is the frames
 * of what it started with. */
unsigned slots_news(skinplay *p)
{
	if (!p->o.image_count || p->o.out_dir || !show_watch_poll(&p->watch, clock_now_ns(), 1))
		return 0;
	fprintf(cli_note(), "image: a slot changed and holds a whole image -> reopen the show\n");
	sdnotify_send(&p->kiosk.sd, "RELOADING=1");
	return KIOSK_ACT_RELOAD;
}
