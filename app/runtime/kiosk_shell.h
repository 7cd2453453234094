/* The kiosk's shell on Linux, beside its core (app/kiosk: the board's
 * keys, the buttons' state machine, debounce): the board file read and its
 * problems said, the buttons (an input backend: gpio, keyboard, script)
 * driving the state machine, signals (SIGTERM and SIGINT quit, SIGHUP
 * reloads), systemd's readiness and watchdog, and the frame-rate cap. A
 * program calls these and applies the KIOSK_ACT_* bits to what it shows
 * (skinplay: app/skinplay/skinplay_board.c merges the board into its
 * options). */
#ifndef KIOSK_SHELL_H
#define KIOSK_SHELL_H

#include <stdint.h>

#include "board_config.h"
#include "controls.h"
#include "input.h"
#include "sd_notify.h"

/* kiosk_shell_frame's result bits. */
enum {
	KIOSK_ACT_ALGO = 1 << 0,      /* ps.algo changed */
	KIOSK_ACT_VIEW = 1 << 1,      /* ps.view changed */
	KIOSK_ACT_GPU = 1 << 2,       /* ps.gpu changed */
	KIOSK_ACT_PLAY = 1 << 3,      /* ps.playing changed */
	KIOSK_ACT_RESTART = 1 << 4,   /* start the clip again */
	KIOSK_ACT_CLIP = 1 << 5,      /* open clip ps.clip from its start */
	KIOSK_ACT_RELOAD = 1 << 6,    /* SIGHUP: re-open the show (image slots) */
	KIOSK_ACT_QUIT = 1 << 7,      /* SIGTERM / SIGINT */
	KIOSK_ACT_STEP = 1 << 8,      /* a window's arrow: one captured frame (k->step) while paused */
	KIOSK_ACT_SEEK = 1 << 9,      /* [ or ]: k->seek seconds */
	KIOSK_ACT_SPEED = 1 << 10,    /* + or -: k->speed_step speeds faster or slower */
	KIOSK_ACT_CAMERA = 1 << 11    /* f frames the body again, r resets the camera (k->camera 1, 2) */
};

/* A camera key's step on a console (no pointer there; a window takes them
 * too): h l turn it round the body, j k tilt it, H J K L move the point it
 * looks at, z x bring it nearer or farther. */
typedef struct kiosk_camera_step {
	int turn, tilt, move_x, move_y, zoom;
} kiosk_camera_step;

typedef struct kiosk_shell {
	const char *prog;        /* the program's name, for its messages */
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
	int step, seek, speed_step; /* the last STEP, SEEK, SPEED key's: -1 back or slower, 1 on or faster */
	int camera;              /* the last CAMERA key's: 1 frame the body, 2 reset, 3 a step (cam) */
	kiosk_camera_step cam;   /* camera 3: the step, each -1, 0 or 1 */
} kiosk_shell;

/* What the shell starts with: the controls' first state, the frame clock. */
typedef struct kiosk_start {
	int algo, view, gpu;
	int headless;
	double display_rate;     /* headless: frame n at n / display_rate s */
	int clip_count;          /* clips NEXT cycles through */
} kiosk_start;

/* Clears k and sets the board's defaults; prog names the program. */
void kiosk_shell_init(kiosk_shell *k, const char *prog);

/* Reads the board file: a kiosk goes on with the defaults over any
 * problem in it, even a file it cannot open; each is said once and the
 * first kept in board_note. k->have_board when it was read. */
void kiosk_shell_load_board(kiosk_shell *k, const char *path);

/* Picks the input (input, else the board's, else none) and installs the
 * signal handlers, before the display and the worker threads start. 0, or
 * -1 after reporting. */
int kiosk_shell_prepare(kiosk_shell *k, const char *input);

/* When the program is ready to show frames: starts the input on the
 * frame clock, sends READY=1. 0, or -1 after reporting (headless only: on
 * a screen a failing input leaves the show without buttons). */
int kiosk_shell_start(kiosk_shell *k, const kiosk_start *s);

/* Before frame n (0-based) is drawn: polls the input and the signals,
 * runs the state machine (printing its "input: BUTTON -> action" lines),
 * feeds the watchdog, caps the frame rate. Returns KIOSK_ACT_* bits; the
 * new state is k->ps. */
unsigned kiosk_shell_frame(kiosk_shell *k, long n);

/* A key pressed in the window (display_backend.key; q and Escape quit
 * there): 1-4 pick the method (LBS, DQBS, DQBS fixed-point, LBS beside
 * DQBS), v the view (VIEW), d the difference view and back, space pauses
 * (PLAY), n the next clip (NEXT), the left and right arrows step one
 * captured frame while paused, [ and ] seek a second, + and - (= and _)
 * the speed, f frames the body again and r resets the camera (drags and
 * the wheel move it: display_backend.pointer). Returns KIOSK_ACT_* bits
 * like kiosk_shell_frame. */
#define KIOSK_KEYS_LEGEND "KEYS: 1-4 METHOD  V VIEW  SPACE PAUSE  N NEXT  ARROWS STEP  [ ] SEEK  + - SPEED  Q QUIT"
#define KIOSK_MOUSE_LEGEND "CAMERA: DRAG TURNS  RIGHT-DRAG MOVES  WHEEL ZOOMS  F FRAMES  R RESETS"
#define KIOSK_CAMERA_LEGEND "CAMERA: H L TURN  J K TILT  SHIFT+H J K L MOVE  Z X ZOOM  F FRAMES  R RESETS"
unsigned kiosk_shell_key(kiosk_shell *k, int key, long n);

/* Releases the input (terminal restored), signals; sends STOPPING=1. */
void kiosk_shell_shutdown(kiosk_shell *k);

#endif
