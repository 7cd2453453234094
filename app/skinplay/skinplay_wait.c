/* A kiosk with no show it can play (every image slot missing, damaged
 * beyond use or refused): it does not exit into a restart loop and a dark
 * screen. It says so on the screen, keeps feeding the watchdog and answers
 * signals, and watches the slot files: once one has changed and then stood
 * still for a moment (a new show copied in), it starts over. */
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "clock.h"
#include "skinplay.h"

#define WAIT_POLL_NS 250000000ull   /* a look at the slots and the screen four times a second */
#define WAIT_SETTLE_NS 2000000000ull /* a changed slot must stand still this long (a copy in progress) */

/* What a slot file is now: enough to see that it changed. */
typedef struct slot_state {
	int exists;
	dev_t dev;
	ino_t ino;
	off_t size;
	struct timespec mtime;
} slot_state;

static slot_state slot_now(const char *path)
{
	struct stat st;
	slot_state s;
	memset(&s, 0, sizeof s);
	if (stat(path, &st) == 0) {
		s.exists = 1;
		s.dev = st.st_dev;
		s.ino = st.st_ino;
		s.size = st.st_size;
		s.mtime = st.st_mtim;
	}
	return s;
}

static int same(const slot_state *a, const slot_state *b)
{
	return a->exists == b->exists && a->dev == b->dev && a->ino == b->ino && a->size == b->size &&
	       a->mtime.tv_sec == b->mtime.tv_sec && a->mtime.tv_nsec == b->mtime.tv_nsec;
}

typedef struct slot_watch {
	slot_state seen[SHOW_MAX_SLOTS], last[SHOW_MAX_SLOTS];
	uint64_t changed_at;     /* when a slot last changed; 0: none since the start */
} slot_watch;

/* 1 when a slot has changed since the start and has not changed for
 * WAIT_SETTLE_NS. */
static int slots_settled(slot_watch *w, const play_opts *o, uint64_t now)
{
	for (int i = 0; i < o->image_count && i < SHOW_MAX_SLOTS; i++) {
		slot_state s = slot_now(o->image[i]);
		if (!same(&s, &w->last[i])) {
			w->last[i] = s;
			w->changed_at = now;
		}
	}
	if (!w->changed_at || now - w->changed_at < WAIT_SETTLE_NS)
		return 0;
	for (int i = 0; i < o->image_count && i < SHOW_MAX_SLOTS; i++)
		if (!same(&w->seen[i], &w->last[i]))
			return 1;
	return 0;
}

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

static int wait_loop(skinplay *p, slot_watch *w)
{
	char slots[160];
	const char *lines[5];
	int n = notice_lines(&p->o, slots, lines), quit = 0;
	for (long frame = 0; !quit; frame++) {
		unsigned act = skinplay_kiosk_frame(&p->kiosk, frame);
		if (act & (SKINPLAY_ACT_QUIT | SKINPLAY_ACT_RELOAD)) {
			p->reload = !(act & SKINPLAY_ACT_QUIT);
			return 0;
		}
		uint64_t now = clock_now_ns();
		if (slots_settled(w, &p->o, now)) {
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
	slot_watch w;
	memset(&w, 0, sizeof w);
	for (int i = 0; i < p->o.image_count && i < SHOW_MAX_SLOTS; i++)
		w.seen[i] = w.last[i] = slot_now(p->o.image[i]);
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
