/* skinplay's command line. */
#ifndef SKINPLAY_OPTS_H
#define SKINPLAY_OPTS_H

#include "cli_bind_args.h"
#include "render.h"

typedef struct play_opts {
	const char *asf, *amc, *mesh;
	const char *bvh;                /* skeleton and motion in one: sets asf and amc */
	const char *image[4];    /* --image slots (repeatable): the newest valid plays */
	int image_count;
	const char *clip;        /* --clip NAME of an image (default its first) */
	int report_memory;       /* --report-memory: VmHWM/VmRSS at the end */
	int report_timing;       /* --report-timing: per stage mean and worst at the end */
	int pose_digest;         /* --pose-digest: a digest of every pose shown, at the end */
	const char *input;       /* --input gpio|keyboard|script:FILE|none (app/runtime/kiosk_shell.h) */
	const char *board;       /* --board board/NAME/board.ini */
	bind_args bind;
	skin_algo algo;
	int algo_given;          /* --algo given: it wins over the board's [display] algo */
	int gpu;                 /* --skin gpu */
	int threads;             /* --threads: 0 auto (one per core), -1 the board's */
	int streams;             /* --streams: board_streams, -1 the board's */
	const char *platform;    /* NULL or "auto" */
	const char *device;
	int rotation;
	int width, height;
	long frames;             /* -1: the clip once headless, forever on a display */
	long start;              /* first frame number to show, -1: the clip's first */
	const char *out_dir;     /* --output: PNG frames' directory, or the video file (video) */
	int video;               /* --output names a video: F.mp4 or F.webm (skinplay_output.c) */
	const char *sheet_path;  /* --sheet: contact sheet of the frames written */
	int transparent;         /* --background=transparent: the character alone, PNG alpha */
	int texture;             /* --texture: 0 auto (ETC1 where sampled), 1 rgb565, 2 off */
	int print_platform;      /* --print-platform: say what auto picks, exit */
	long every;
	render_view view;
	int view_given;          /* --view given: it wins over the board's [display] view */
	int hud_fps;             /* 0: leave the measured fps out (reproducible images) */
	int hud;                 /* board_hud; -1: the board's, else engineer */
	double fps;              /* an AMC's capture rate (a BVH and an image say theirs) */
	double display_rate;     /* headless: display frame n is at n / display_rate s */
	double speed;            /* clip seconds a second; 0: the board's (else 1) */
	int blend_ms;            /* crossfade at loops and clip changes; -1: the board's */
	int root;                /* board_root; -1: the board's (else in place) */
	int loop;                /* board_loop; -1: the board's (else show) */
	int sync;                /* 1: the show follows the wall clock; 0 off; -1 the board's (else off) */
	int64_t epoch_ns;        /* --sync=clock: the show's start, ns since the Unix epoch */
	int epoch_given;         /* --epoch given: it wins over the board's */
	int show_buttons;        /* the board's [show] buttons: 0, PLAY and NEXT do nothing */
	render_wall wall;        /* --wall, else the board's [wall]: this screen's tile (columns 0: none) */
	int wall_given;
	int bezel;               /* --bezel; -1: the board's (else 0) */
	render_view_cam view_cam; /* the board's [camera] */
	int yaw_mode;            /* -1: the board's (else auto), 0 auto, 1 yaw_deg */
	float yaw_deg;
} play_opts;

/* Returns 0, 1 after printing help, or -1 after reporting an error. */
int play_parse(play_opts *o, int argc, char **argv);


#endif
