/* A board's runtime configuration (board/NAME/board.ini): display, buttons,
 * storage slots and limits. Compile-time limits stay in board_limits.h;
 * this is what an installer may change on the device without a rebuild.
 *
 *   [display]  platform = kms   device = /dev/dri/card1   rotation = 0   size = 1920x1080
 *              hud = visitor | engineer | off   (skinplay --hud)
 *              algo = lbs | dqbs | dqbs-fixed | compare   (skinplay --algo: the
 *              method the kiosk starts with; compare: LBS beside DQBS)
 *              view = body | skeleton | weights | difference   (skinplay --view:
 *              the view it starts with; the names are modes.h's)
 *   [input]    backend = gpio   chip = gpiochip0   debounce_ms = 30   long_press_ms = 800
 *   [button.algo]  line = 17   active = low   bias = pull-up   (debounce_ms, long_press_ms)
 *   [storage]  slot = PATH   (one line per image slot)
 *   [limits]   max_fps = 60   (frame-rate cap on a display; the watchdog
 *              period is the unit's WatchdogSec)
 *   [skin]     threads = auto | N   split_verts = 50000 | auto   (skinplay
 *              --threads: CPU skinning on N threads, auto one per core, for
 *              meshes of split_verts vertices or more; auto: the threads
 *              are tried against one and kept if they are faster)
 *              streams = float | compact   (skinplay --streams)
 *   [display]  yaw = auto | DEG   (the camera faces the clip's mean facing,
 *              or DEG degrees about the vertical from the usual view)
 *   [show]     speed = 1   (0.1..4: clip seconds a second)
 *              blend_ms = 300   (crossfade at a loop or a clip change; 0: cut)
 *              root = in-place | travel   (in place: the root's horizontal
 *              travel taken out; travel: kept, the camera follows)
 *              loop = show | clip   (show: an image's clips play in turn,
 *              the show loops; clip: a clip loops until NEXT)
 *              sync = off | clock   (clock: the show's position is the
 *              wall clock's, so that devices on synchronised clocks play
 *              in lock-step; skinplay --sync)
 *              epoch = 2026-01-01T00:00:00Z   (ISO 8601 UTC: the show's
 *              start; default the Unix epoch; skinplay --epoch)
 *              buttons = on | off   (off: PLAY and NEXT do nothing, for a
 *              synced installation; ALGO and VIEW still switch)
 *   [wall]     columns = 3, rows = 1   (a video wall of screens, each
 *              drawing its tile of one picture; skinplay --wall)
 *              column = 0, row = 0   (this screen's, from the top left)
 *              bezel = 0   (pixels of the picture behind two neighbouring
 *              screens' frames; skinplay --bezel)
 *   [camera]   yaw = auto | DEG   (as [display] yaw)
 *              pitch = 6.3   (degrees from above; -30..80)
 *              distance = 1   (times the distance that frames the body; 0.2..10)
 *              target = 0, 0, 0   (the point looked at, from the body's
 *              centre: x, y (up), z of the skeleton's space, in body
 *              heights; -5..5 each)
 *
 * A kiosk never stops over its config: a mistake (an unknown section or
 * key, a bad value, a line that is not `key = value`, a UTF-8 byte order
 * mark from a Windows editor is none) is a problem recorded with its line
 * and what was expected, and the key keeps its default; the front end says
 * each problem once and shows the first on the engineer HUD. */
#ifndef BOARD_CONFIG_H
#define BOARD_CONFIG_H

#include <stdint.h>

#include "board_limits.h"
#include "debounce.h"
#include "controls.h"
#include "skp_error.h"
#include "skp_reader.h"

#ifndef SKP_MAX_PATH
#define SKP_MAX_PATH 256     /* device and file paths in a board config */
#endif
/* Boards without a display (Cortex-M) read board configs all the same. */
#ifndef SKP_DISPLAY_MAX_W
#define SKP_DISPLAY_MAX_W 3840
#define SKP_DISPLAY_MAX_H 2160
#endif
#ifndef SKP_MAX_SLOTS
#define SKP_MAX_SLOTS 3      /* image slots: A/B update, and the demo as the last resort */
#endif

typedef enum board_bias {
	BOARD_BIAS_AS_IS,        /* leave the line's bias as firmware set it */
	BOARD_BIAS_DISABLE,
	BOARD_BIAS_PULL_UP,
	BOARD_BIAS_PULL_DOWN
} board_bias;

/* What the screen shows over the body (skinplay --hud). */
typedef enum board_hud { BOARD_HUD_OFF, BOARD_HUD_ENGINEER, BOARD_HUD_VISITOR } board_hud;

/* What the CPU kernels read (skinplay --streams; app/skin/skin_compact.h). */
typedef enum board_streams { BOARD_STREAMS_FLOAT, BOARD_STREAMS_COMPACT } board_streams;

/* "auto" (0: one thread per core) or a count of 1..BOARD_MAX_THREADS;
 * -1 for anything else. */
int board_threads_parse(const char *word);

/* The words of board_streams and of the HUD modes, in enum order; each
 * parse returns the word's index (any case), -1 for another word. */
#define BOARD_STREAMS_KINDS 2
#define BOARD_HUD_MODES 3
extern const char *const board_streams_names[BOARD_STREAMS_KINDS]; /* "float", "compact" */
extern const char *const board_hud_names[BOARD_HUD_MODES];         /* "off", "engineer", "visitor" */
int board_streams_parse(const char *word);
int board_hud_parse(const char *word);

/* [show] root: the words in enum order, and their parse (-1: another). */
typedef enum board_root { BOARD_ROOT_IN_PLACE, BOARD_ROOT_TRAVEL } board_root;
#define BOARD_ROOT_MODES 2
extern const char *const board_root_names[BOARD_ROOT_MODES]; /* "in-place", "travel" */
int board_root_parse(const char *word);

/* [show] loop: the words in enum order, and their parse (-1: another). */
typedef enum board_loop { BOARD_LOOP_SHOW, BOARD_LOOP_CLIP } board_loop;
#define BOARD_LOOP_MODES 2
extern const char *const board_loop_names[BOARD_LOOP_MODES]; /* "show", "clip" */
int board_loop_parse(const char *word);

/* [show] speed: 0 with *out in [BOARD_SPEED_MIN, BOARD_SPEED_MAX], else -1. */
#define BOARD_SPEED_MIN 0.1
#define BOARD_SPEED_MAX 4.0
int board_speed_parse(const char *word, double *out);

/* [display] yaw: 0 for auto, 1 with *deg for degrees (-360..360), -1 else. */
int board_yaw_parse(const char *word, float *deg);

typedef struct board_button {
	int present;             /* its [button.NAME] section gives a line */
	unsigned int line;       /* line offset on the chip (BCM GPIO on a Pi) */
	int active_low;          /* pressed = low (a button to ground) */
	int bias;                /* board_bias */
	debounce_config deb;
} board_button;

/* A mistake in the file: its line (0: none) and what is wrong, the key's
 * default kept. */
#define BOARD_MAX_PROBLEMS 8
typedef struct board_problem {
	long line;
	char msg[200];
} board_problem;

typedef struct board_config {
	char platform[16];       /* "" = auto */
	char device[SKP_MAX_PATH];
	int rotation;            /* -1: not given */
	int width, height;       /* 0: not given */
	int hud;                 /* board_hud, -1: not given */
	int algo;                /* skin_algo (compare included), -1: not given */
	int view;                /* render_view, -1: not given */
	char input[SKP_MAX_PATH]; /* gpio | keyboard | none | script:FILE; "" = none */
	char chip[SKP_MAX_PATH]; /* gpiochip name, path, label or number */
	board_button button[CONTROL_BTN_COUNT];
	char slot[SKP_MAX_SLOTS][SKP_MAX_PATH];
	int slot_count;
	int max_fps;             /* 0: no cap beyond the display's */
	int threads;             /* skinning threads; 0: one per core */
	int split_verts;         /* meshes this big or bigger use them; BOARD_SPLIT_AUTO: measured */
	int streams;             /* board_streams */
	int yaw_mode;            /* -1 not given, 0 auto, 1 yaw_deg */
	float yaw_deg;
	double speed;            /* [show] speed */
	int blend_ms;            /* [show] blend_ms */
	int root;                /* board_root */
	int loop;                /* board_loop */
	int sync;                /* [show] sync: 1 clock, 0 off */
	int64_t epoch_ns;        /* [show] epoch, ns since the Unix epoch */
	int show_buttons;        /* [show] buttons: 0 off (PLAY and NEXT do nothing) */
	int wall_columns, wall_rows; /* [wall]: screens across and down; 0: no wall */
	int wall_column, wall_row;   /* this screen's, from 0 at the top left */
	int wall_bezel;          /* [wall] bezel: pixels behind two screens' frames */
	float cam_pitch_deg;     /* [camera] pitch: degrees from above */
	float cam_distance;      /* [camera] distance: times the framing one */
	float cam_aim[3];        /* [camera] target: the point looked at from the body's centre, in body heights */
	int problem_count;       /* all the mistakes found, also past the list */
	board_problem problem[BOARD_MAX_PROBLEMS];
} board_config;

#define CAMERA_PITCH_DEFAULT_DEG 6.3f /* app/render/camera.h's CAMERA_PITCH */
#define BOARD_WALL_MAX 16        /* screens across or down */
#define BOARD_DEBOUNCE_MS 30
#define BOARD_LONG_PRESS_MS 800
#define BOARD_MAX_THREADS 16
/* Below this many vertices one thread skins: waking the others costs
 * more than they save (skintool bench --verts=N --threads=2 on the
 * development machine: two threads win from about 50,000). */
#define BOARD_SPLIT_VERTS 50000
#define BOARD_SPLIT_AUTO 0
#define BOARD_BLEND_MS 300
#define BOARD_BLEND_MS_MAX 10000

void board_config_defaults(board_config *c);

/* Parses a board.ini. Mistakes are recorded in c->problem (each naming
 * the line, the key or section, and what was expected; the key keeps its
 * default) and reading goes on; a line too long or a NUL byte ends the
 * reading there (a problem too). Returns SKP_OK, or SKP_ERR_IO with err
 * when the reader fails. */
skp_status board_config_read(board_config *c, skp_reader rd, skp_error *err);

/* Records a problem (the front end's: a config file that cannot be
 * opened). */
void board_config_problem(board_config *c, long line, const char *msg);

#endif
