/* skinplay's state, shared by its files: skinplay.c (setup, the display,
 * the frame loop) and skinplay_clips.c (which clip plays: an AMC or BVH
 * file, or an image's clips, skipping a clip that cannot play and holding
 * the bind pose when none can). The pose of each frame comes from the
 * playback engine (app/play) at the frame's time. */
#ifndef SKINPLAY_H
#define SKINPLAY_H

#include "clip_file.h"
#include "show_source.h"
#include "show_watch.h"
#include "runtime_skin.h"
#include "display.h"
#include "play_engine.h"
#include "play_extent.h"
#include "skinplay_board.h"
#include "skel_joints.h"
#include "skin_diff.h"
#include "skp_ratelimit.h"
#include "skinplay_opts.h"
#include "skinplay_timing.h"
#include "skinplay_sheet.h"
#include "video_writer.h"

typedef struct skinplay {
	play_opts o;
	long budget, shown;  /* frames to show (-1: until closed) and shown so far */
	stage_times stages;  /* --report-timing */
	bound_body body;
	runtime_skin skin;
	workers *pool;           /* skinning threads (--threads), NULL: one */
	int threads_logged;      /* what measuring them chose is in the log */
	play_engine eng;   /* clock in, pose out */
	clip_file text; /* --asf/--amc, --bvh: the file as the engine's source */
	show_source show;  /* --image: the clips of a packed image instead */
	show_watch watch;  /* the image slots' files, while the show plays */
	play_source src;   /* the clip playing */
	play_extent extent; /* its length, facing and extent (one pass at its start) */
	skel_pose scratch_pose; /* the extent pass's */
	amc_frame scratch_frame;
	uint64_t now;      /* the frame's time (ns): the monotonic clock, or frame n / display rate */
	uint64_t wall0;    /* the monotonic clock when the first frame was drawn */
	double drift;      /* the frame's time less the wall clock's since the first frame, s */
	int engine_failed; /* a source error was logged for this clip: hold, say it once */
	double start_time; /* --start: the clip time the first frame shows */
	float yaw;         /* the camera's turn for this clip (radians) */
	float flesh;       /* how far the body reaches past its joints (first frame) */
	int render_ready;  /* the renderer is up: clip changes turn its camera */
	renderer r;
	gl_api gl;
	const display_backend *disp;
	display_info info;
	int headless;
	int hold;          /* no clip can play: the bind pose, with a message */
	uint64_t digest;       /* --pose-digest: FNV-1a of the poses shown */
	uint64_t status_at;    /* when the last status line was said (wall clock) */
	int status_hourly;     /* past the first minute: status lines once an hour */
	skp_ratelimit skip_said;  /* "clip X cannot play: showing Y" */
	skp_ratelimit fail_said;  /* "clip X cannot be read on" */
	char notice[96];   /* shown on screen until notice_until (ns) */
	uint64_t notice_until;
	int panel_count;
	skin_algo algo[RENDER_MAX_PANELS];
	int gpu[RENDER_MAX_PANELS];
	float pos[RENDER_MAX_PANELS][3 * SKP_MAX_VERTS];
	float nrm[RENDER_MAX_PANELS][3 * SKP_MAX_VERTS];
	int16_t nrm16[RENDER_MAX_PANELS][3 * SKP_MAX_VERTS]; /* --streams compact */
	uint8_t rgba[SKP_DISPLAY_MAX_W * SKP_DISPLAY_MAX_H * 4]; /* one frame read back for --out */
	video_writer *video;     /* --out F.mp4 or F.webm (skinplay_output.c), NULL: none or PNG frames */
	char clip[64];
	char first_clip[64];     /* and the first, of clips_started, for the summary line */
	int clips_started;
	sheet contact;
	kiosk_shell kiosk;       /* --board, --input, signals, systemd */
	skin_diff diff;          /* where the panels part, where the skin left its bone */
	skel_joints joints;      /* the joints' names */
	closeup_pick pick;       /* the compare view's close-up */
	skin_focus focus;        /* where on its joint, as last measured */
	int focus_joint;         /* the joint of focus (-1: none yet) */
	float diff_value[SKP_MAX_VERTS]; /* the difference view's, per vertex */
	char closeup_title[32], closeup_note[48];
	char closeup_apart[48];
	/* --sync=clock (skinplay_sync.c) */
	int64_t sync_frame0;     /* headless: the display frame, counted from the epoch, of frame 0 */
	int sync_started;        /* the first frame took the clock's clip and time */
	int sync_unsynced;       /* the kernel says the wall clock is not synchronised */
	double sync_last;        /* the clip time set last, at sync_last_now */
	uint64_t sync_last_now;
	uint64_t sync_detour_until; /* a local NEXT plays off the clock until then */
	int sync_detour;         /* a local NEXT was pressed: the detour starts */
	unsigned long sync_joins;   /* joins of the clock after a start, pause or stall */
	skp_ratelimit sync_said;
	float cam_yaw;           /* the engineer's turn of the camera, added to the clip's yaw */
	render_view_cam view_home; /* the camera as it began (the board's): r goes back to it */
	int reload;        /* SIGHUP, or a slot changed while waiting: start over (main re-executes) */
	int no_show;       /* no image slot holds a show that can play */
} skinplay;

/* --sync=clock: the show's position from the wall clock (app/play/
 * play_sync.h). sync_begin once before the first frame (says what it
 * follows, and whether the kernel says the clock is synchronised);
 * sync_frame each frame before the pose: the clock's clip and time, a
 * crossfade when the device was off the clock; sync_button: the button
 * actions left to do (PLAY and NEXT taken out when the board's [show]
 * buttons = off keeps the clock; else a NEXT is a local detour). */
void sync_begin(skinplay *p);
void sync_frame(skinplay *p, long n);
unsigned sync_button(skinplay *p, unsigned act);

/* Frame n's time: headless, n / display rate exactly (reproducible); on a
 * screen, the monotonic clock since the first frame. */
uint64_t skinplay_frame_time(skinplay *p, long n);

/* A window's time keys (skinplay_keys.c): KIOSK_ACT_STEP, _SEEK, _SPEED
 * applied to the engine; and the keys' legend for the visitor's HUD (0)
 * or the engineer's (1, a window's first seconds), NULL for none. */
void keys_time(skinplay *p, unsigned act);

/* The engineer's camera in a window (skinplay_camera.c): the pointer's
 * drags and wheel each frame, and the f and r keys (KIOSK_ACT_CAMERA). */
void camera_pointer(skinplay *p);
void camera_key(skinplay *p, unsigned act);
const char *keys_legend(const skinplay *p, int engineer);

/* skinplay_hud.c: the captured frame on screen (its number in the file,
 * the clip time; 0 while the bind pose is held), and the HUD's text for
 * this frame in f, the engineer's lines written into lines. */
long shown_number(const skinplay *p);
double shown_time(const skinplay *p);
void hud_text(skinplay *p, render_frame *f, double fps, char lines[3][128]);

/* Selects clip c of the image as the show does (the next that can play
 * when it cannot), crossfading from the pose shown. */
void clips_select(skinplay *p, int c);

/* Opens the first clip (--clip, --start) and computes its first pose into
 * p->skin.pose; returns the lowest point of the body in it (the floor), or
 * NAN after reporting when the clip cannot be read at all. */
float clips_first(skinplay *p);

/* The pose at p->now into p->skin.pose (the engine's; the bind pose when
 * no clip can play). A source that fails mid-clip (an AMC read error) is
 * logged once and the last pose held: a kiosk never stops on bad data.
 * Headless, that is an error instead: -1 after reporting, else 0. */
int clips_pose(skinplay *p);

/* PLAY long (clip < 0: this clip from its start) or NEXT (clip i, or the
 * next one that can play), crossfading from the pose on screen. */
void clips_restart(skinplay *p, int clip);

/* Display frames that play the clip once from where it starts; with loop
 * = show, every playable clip of the image once. */
long clips_pass_frames(skinplay *p);

/* loop = show and an image with more than one clip that can play: its
 * clips play in turn (a pass's end starts the next). */
int clips_show_loops(const skinplay *p);

/* Tells the renderer the space the body takes over the clip playing (the
 * extent's joints, grown by p->flesh), so the camera frames all of it. */
void clips_frame(skinplay *p, int immediate);

/* Opens the display --platform names (auto: what display_auto picks; where
 * headless EGL is missing, OSMesa). 0, or -1 after reporting. */
int open_display(skinplay *p);

/* No image slot holds a show that can play. On a screen, says so there and
 * waits, feeding the watchdog, until a slot file changes (a new show copied
 * in: p->reload, main starts over) or SIGHUP or SIGTERM; headless, and with
 * no display at all, it is an error. Returns the exit status. */
int wait_for_show(skinplay *p);

/* While the show plays: KIOSK_ACT_RELOAD when a slot changed and now
 * holds a whole image (said, and RELOADING=1 to systemd), else 0. Not in a
 * run writing frames. */
unsigned slots_news(skinplay *p);

/* The close-up and the difference view (skinplay_closeup.c): set up once
 * the body is bound (and the renderer up); each frame after skinning, the
 * joint shown and the values coloured into f. */
void closeup_setup(skinplay *p);
void closeup_frame(skinplay *p, render_frame *f);

/* --output (skinplay_output.c). output_open once the display is up: the
 * PNG frames' directory made, or the video opened; output_frame: frame n
 * (from 1) read back into it, and into the contact sheet; output_close
 * at the end: the video finished and made its file (keep), or dropped
 * with nothing left (a run that failed). Each 0, or -1 after reporting. */
int output_open(skinplay *p);
int output_frame(skinplay *p, long n);
int output_close(skinplay *p, int keep);

/* Shows text on screen for about seconds. */
void clips_notice(skinplay *p, const char *text, double seconds);

#endif
