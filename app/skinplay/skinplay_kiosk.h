/* skinplay's kiosk side: the board config (--board), the buttons (--input)
 * driving the kiosk's controls (app/kiosk/controls.h), signals (SIGTERM and
 * SIGINT quit, SIGHUP reloads) and systemd's readiness and watchdog.
 * skinplay.c calls these four functions and applies the returned
 * SKINPLAY_ACT_* bits to what it renders. */
#ifndef SKINPLAY_KIOSK_H
#define SKINPLAY_KIOSK_H

#include <stdint.h>

#include "board_config.h"
#include "input.h"
#include "controls.h"
#include "sd_notify.h"
#include "skinplay_opts.h"

/* skinplay_kiosk_frame's result bits. */
enum {
	SKINPLAY_ACT_ALGO = 1 << 0,      /* ps.algo changed */
	SKINPLAY_ACT_VIEW = 1 << 1,      /* ps.view changed */
	SKINPLAY_ACT_GPU = 1 << 2,       /* ps.gpu changed */
	SKINPLAY_ACT_PLAY = 1 << 3,      /* ps.playing changed */
	SKINPLAY_ACT_RESTART = 1 << 4,   /* start the clip again */
	SKINPLAY_ACT_CLIP = 1 << 5,      /* open clip ps.clip from its start */
	SKINPLAY_ACT_RELOAD = 1 << 6,    /* SIGHUP: re-open the show (image slots) */
	SKINPLAY_ACT_QUIT = 1 << 7       /* SIGTERM / SIGINT */
};

typedef struct skinplay_kiosk {
	board_config board;
	int have_board;
	const char *input_spec;
	const input_backend *in;
	int in_started;
	controls_state ps;
	sdnotify sd;
	int sig_fd;
	int headless;
	double fps;              /* headless display rate: frame n at n * 1000 / fps ms */
	uint64_t t0_ns, last_ns;
	uint64_t play_ms;        /* when PLAY last paused or resumed (the input's clock) */
	char board_note[128];    /* the board file's first problem, for the engineer HUD; "" none */
} skinplay_kiosk;

/* After play_parse: loads --board (display settings not given on the
 * command line come from it; its problems are said and the defaults kept,
 * the first in board_note), picks the input (--input, else the board's,
 * else none) and installs the signal handlers. 0, or -1 after reporting. */
int skinplay_kiosk_setup(skinplay_kiosk *k, play_opts *o, int argc, char **argv);

/* When skinplay is ready to show frames: starts the input on the frame
 * clock, sends READY=1. clip_count: clips NEXT cycles through. */
int skinplay_kiosk_start(skinplay_kiosk *k, const play_opts *o, int headless, int clip_count);

/* Before frame n (0-based) is drawn: polls the input and the signals,
 * runs the state machine (printing its "input: BUTTON -> action" lines),
 * feeds the watchdog, caps the frame rate. Returns KIOSK_* bits; the new
 * state is k->ps. */
unsigned skinplay_kiosk_frame(skinplay_kiosk *k, long n);

/* A key pressed in the window (display_backend.key): 1-4 as the buttons
 * ALGO, PLAY, NEXT and VIEW (v too), d the difference view and back.
 * Returns SKINPLAY_ACT_* bits like skinplay_kiosk_frame. */
unsigned skinplay_kiosk_key(skinplay_kiosk *k, int key, long n);

/* Releases the input (terminal restored), signals; sends STOPPING=1. */
void skinplay_kiosk_shutdown(skinplay_kiosk *k);

#endif
