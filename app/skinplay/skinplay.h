/* skinplay's state, shared by its files: skinplay.c (setup, the display,
 * the frame loop) and skinplay_frames.c (where frames come from: an AMC
 * stream or an image's clips, skipping a clip that cannot play and holding
 * the bind pose when none can). */
#ifndef SKINPLAY_H
#define SKINPLAY_H

#include "cli_common.h"
#include "cli_show.h"
#include "cli_skin.h"
#include "display.h"
#include "skinplay_kiosk.h"
#include "skinplay_opts.h"
#include "skinplay_timing.h"
#include "skinplay_sheet.h"

typedef struct player {
	play_opts o;
	long budget, shown;  /* frames to show (-1: until closed) and shown so far */
	stage_times stages;  /* --report-timing */
	bound_body body;
	cli_skin skin;
	workers *pool;           /* skinning threads (--threads), NULL: one */
	int threads_logged;      /* what measuring them chose is in the log */
	cli_motion motion;
	show_source show;  /* --image: frames from a packed image instead */
	amc_frame frame;
	renderer r;
	gl_api gl;
	const display_backend *disp;
	display_info info;
	int headless;
	int pending;       /* p->frame was read ahead by --start */
	int hold;          /* no clip can play: the bind pose, with a message */
	char notice[96];   /* shown on screen for notice_frames more frames */
	long notice_frames;
	int panel_count;
	skin_algo algo[RENDER_MAX_PANELS];
	int gpu[RENDER_MAX_PANELS];
	float pos[RENDER_MAX_PANELS][3 * SKP_MAX_VERTS];
	float nrm[RENDER_MAX_PANELS][3 * SKP_MAX_VERTS];
	int16_t nrm16[RENDER_MAX_PANELS][3 * SKP_MAX_VERTS]; /* --streams compact */
	uint8_t rgba[SKP_DISPLAY_MAX_W * SKP_DISPLAY_MAX_H * 4]; /* one frame read back for --out */
	char clip[64];
	sheet contact;
	kiosk kiosk;       /* --board, --input, signals, systemd */
	int reload;        /* SIGHUP: start over (main re-executes) */
} player;

/* The clip's first frame (read into p->frame, to be shown first) and the
 * lowest point of the body in it: the floor. NAN after reporting when the
 * clip cannot be read at all. */
float frames_first(player *p);

/* Opens the AMC stream (images were opened by frames_first). 0 or -1. */
int frames_open(player *p);

/* The next frame into p->frame: 1, 0 at the end of the clip (headless,
 * once), -1 after reporting a read error of an AMC file. Loops on a
 * display; an image's frames never fail (bad blocks hold, the bind pose
 * holds when no clip can play). */
int frames_next(player *p);

/* PLAY long (clip < 0: this clip from its start) or NEXT (clip i, or the
 * next one that can play). 0, or -1 after reporting (AMC files only). */
int frames_restart(player *p, int clip);
/* Frames in the clip playing (an image's header; an AMC or BVH counted). */
long frames_clip_length(player *p);

/* Shows text on screen for about seconds at the frame rate. */
void frames_notice(player *p, const char *text, double seconds);

#endif
