#include "skinplay_kiosk.h"

#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cli_quiet.h"
#include "clock.h"
#include "file_reader.h"
#include "signals.h"

static int given(int argc, char **argv, const char *opt)
{
	for (int i = 1; i < argc; i++)
		if (!strcmp(argv[i], opt))
			return 1;
	return 0;
}

/* Says each of the board file's problems once (the key keeps its
 * default), and keeps the first for the engineer HUD. */
static void report_board(skinplay_kiosk *k, const char *path)
{
	const board_config *b = &k->board;
	int listed = b->problem_count < BOARD_MAX_PROBLEMS ? b->problem_count : BOARD_MAX_PROBLEMS;
	for (int i = 0; i < listed; i++) {
		if (b->problem[i].line > 0)
			fprintf(stderr, "%s:%ld: %s; ignored, the default stays\n", path, b->problem[i].line, b->problem[i].msg);
		else
			fprintf(stderr, "%s: %s\n", path, b->problem[i].msg);
	}
	if (b->problem_count > listed)
		fprintf(stderr, "%s: %d more problems not listed\n", path, b->problem_count - listed);
	if (b->problem_count)
		snprintf(k->board_note, sizeof k->board_note, "%.24s: %.72s%s", cli_basename(path), b->problem[0].msg,
			 b->problem_count > 1 ? " (MORE IN THE LOG)" : "");
}

/* The board file: a kiosk goes on with the defaults over any problem in
 * it, even a file it cannot open, and says so. */
static void load_board(skinplay_kiosk *k, const char *path)
{
	file_reader fr;
	skp_error err;
	int rc = file_reader_open(&fr, path);
	if (rc < 0) {
		char msg[160];
		snprintf(msg, sizeof msg, "cannot open: %s; running with the defaults", strerror(-rc));
		board_config_problem(&k->board, 0, msg);
	} else {
		if (board_config_read(&k->board, file_reader_as_reader(&fr), &err) != SKP_OK)
			board_config_problem(&k->board, err.line, err.msg);
		file_reader_close(&fr);
		k->have_board = 1;
	}
	report_board(k, path);
}

/* The command line wins; the board fills in what it did not say. */
static void apply_board(const board_config *b, play_opts *o, int argc, char **argv)
{
	if (b->platform[0] && !given(argc, argv, "--platform"))
		o->platform = b->platform;
	if (b->device[0] && !given(argc, argv, "--device"))
		o->device = b->device;
	if (b->rotation >= 0 && !given(argc, argv, "--rotation"))
		o->rotation = b->rotation;
	if (b->hud >= 0 && o->hud < 0)
		o->hud = b->hud;
	if (b->algo >= 0 && !o->algo_given)
		o->algo = (skin_algo)b->algo;
	if (b->view >= 0 && !o->view_given)
		o->view = (render_view)b->view;
	if (b->width && !given(argc, argv, "--size")) {
		o->width = b->width;
		o->height = b->height;
	}
	if (o->yaw_mode < 0 && b->yaw_mode >= 0) {
		o->yaw_mode = b->yaw_mode;
		o->yaw_deg = b->yaw_deg;
	}
	if (o->speed <= 0)
		o->speed = b->speed;
	if (o->blend_ms < 0)
		o->blend_ms = b->blend_ms;
	if (o->root < 0)
		o->root = b->root;
	if (o->loop < 0)
		o->loop = b->loop;
	if (o->sync < 0)
		o->sync = b->sync;
	if (!o->epoch_given)
		o->epoch_ns = b->epoch_ns;
}

/* What neither the command line nor a board said. */
static void playback_defaults(play_opts *o)
{
	if (o->speed <= 0)
		o->speed = 1.0;
	if (o->blend_ms < 0)
		o->blend_ms = BOARD_BLEND_MS;
	if (o->root < 0)
		o->root = BOARD_ROOT_IN_PLACE;
	if (o->loop < 0)
		o->loop = BOARD_LOOP_SHOW;
	if (o->sync < 0)
		o->sync = 0;
	if (o->yaw_mode < 0)
		o->yaw_mode = 0;
}

/* The screen's part in an installation: its tile of a wall (--wall wins
 * over [wall]; a column or row outside the wall is said, and the whole
 * picture shown), its own camera ([camera]). */
static void screen_part(play_opts *o, const board_config *b)
{
	if (!o->wall_given && b->wall_columns > 0) {
		render_wall w = { b->wall_columns, b->wall_rows > 0 ? b->wall_rows : 1, b->wall_column, b->wall_row, 0 };
		if (w.column < w.columns && w.row < w.rows)
			o->wall = w;
		else
			fprintf(stderr, "skinplay: board.ini [wall]: column %d, row %d is not on a wall of %d x %d screens "
				"(from 0): the whole picture shown\n", w.column, w.row, w.columns, w.rows);
	}
	o->wall.bezel = o->bezel >= 0 ? o->bezel : b->wall_bezel;
	o->view_cam.pitch = b->cam_pitch_deg * (float)(M_PI / 180.0);
	o->view_cam.distance = b->cam_distance;
	o->view_cam.aim = vec3_make(b->cam_aim[0], b->cam_aim[1], b->cam_aim[2]);
}

int skinplay_kiosk_setup(skinplay_kiosk *k, play_opts *o, int argc, char **argv)
{
	memset(k, 0, sizeof *k);
	k->sig_fd = -1;
	k->sd.fd = -1;
	board_config_defaults(&k->board);
	if (o->board)
		load_board(k, o->board);
	if (k->have_board)
		apply_board(&k->board, o, argc, argv);
	playback_defaults(o);
	o->show_buttons = k->board.show_buttons;
	screen_part(o, &k->board);
	if (o->hud < 0)
		o->hud = BOARD_HUD_ENGINEER;
	if (o->threads < 0)
		o->threads = k->board.threads; /* the default: auto */
	if (o->streams < 0)
		o->streams = k->board.streams; /* the default: float */
	/* no show on the command line: the board's image slots (A/B update) */
	if (!o->image_count && (!o->asf || !o->amc)) {
		for (int i = 0; i < k->board.slot_count && o->image_count < 4; i++)
			o->image[o->image_count++] = k->board.slot[i];
		if (!o->image_count) {
			fprintf(stderr, "skinplay: give --asf and --amc, --bvh, --image, or [storage] slots in %s\n", o->board);
			return -1;
		}
	}
	k->input_spec = o->input ? o->input : k->have_board && k->board.input[0] ? k->board.input : "none";
	const char *arg;
	if (!input_find(k->input_spec, &arg)) {
		fprintf(stderr, "skinplay: --input expects gpio, keyboard, script:FILE or none, got '%s'\n",
			k->input_spec);
		return -1;
	}
	/* before the display and the worker threads start: a SIGTERM during a
	 * long setup is then not lost, and the handler serves every thread */
	k->sig_fd = signals_init();
	if (k->sig_fd < 0) {
		fprintf(stderr, "skinplay: signals: %s\n", strerror(-k->sig_fd));
		return -1;
	}
	return 0;
}

static uint64_t now_ms(const skinplay_kiosk *k, long n)
{
	/* headless: display frame n is at n * 1000 / display rate ms exactly
	 * (the epsilon keeps 100.0 from rounding down to 99), so scripted runs
	 * are reproducible */
	if (k->headless)
		return (uint64_t)((double)n * 1000.0 / k->fps + 1e-6);
	return (clock_now_ns() - k->t0_ns) / 1000000u;
}

int skinplay_kiosk_start(skinplay_kiosk *k, const play_opts *o, int headless, int clip_count)
{
	skp_error err;
	const char *arg;
	k->headless = headless;
	k->fps = o->display_rate > 0 ? o->display_rate : 60.0;
	k->t0_ns = k->last_ns = clock_now_ns();
	controls_init(&k->ps, o->algo, o->view, o->gpu, clip_count);
	k->in = input_find(k->input_spec, &arg);
	if (k->in->init(&k->board, arg, now_ms(k, 0), &err) != 0) {
		/* a batch run fails; on a display no buttons is no reason to go dark */
		fprintf(stderr, "skinplay: input %s: %s%s\n", k->in->name, err.msg, headless ? "" : "; running without buttons");
		if (headless)
			return -1;
		k->in = &input_none;
		k->in->init(&k->board, NULL, now_ms(k, 0), &err);
	}
	k->in_started = 1;
	if (k->in != &input_none)
		fprintf(cli_note(), "input: %s%s%s\n", k->in->name, arg ? " " : "", arg ? arg : "");
	int rc = sdnotify_init(&k->sd);
	if (rc < 0)
		fprintf(stderr, "skinplay: $NOTIFY_SOCKET: %s\n", strerror(-rc));
	sdnotify_send(&k->sd, "READY=1");
	return 0;
}

static unsigned act_bit(control_action a)
{
	static const unsigned bits[] = { 0, SKINPLAY_ACT_ALGO, SKINPLAY_ACT_PLAY, SKINPLAY_ACT_RESTART, SKINPLAY_ACT_CLIP, SKINPLAY_ACT_VIEW, SKINPLAY_ACT_GPU };
	return bits[a];
}

static unsigned take_signals(skinplay_kiosk *k)
{
	unsigned s = signals_take(), act = 0;
	if (s & SIGNALS_RELOAD) {
		fprintf(cli_note(), "signal: SIGHUP -> reopen the show\n");
		sdnotify_send(&k->sd, "RELOADING=1");
		act |= SKINPLAY_ACT_RELOAD;
	}
	if (s & SIGNALS_QUIT) {
		fprintf(cli_note(), "signal: quit -> clean exit\n");
		act |= SKINPLAY_ACT_QUIT;
	}
	return act;
}

/* Frame-rate cap on a display (the board's max_fps). */
static void pace(skinplay_kiosk *k)
{
	if (k->headless || k->board.max_fps <= 0)
		return;
	uint64_t next = k->last_ns + 1000000000u / (uint64_t)k->board.max_fps;
	if (clock_now_ns() < next)
		clock_sleep_until_ns(next);
	k->last_ns = clock_now_ns();
}

unsigned skinplay_kiosk_frame(skinplay_kiosk *k, long n)
{
	control_event ev[INPUT_MAX_EVENTS];
	skp_error err;
	unsigned act = 0;
	pace(k);
	/* the buttons need no poll: read() never blocks and runs every frame */
	struct pollfd sig = { .fd = k->sig_fd, .events = POLLIN };
	if (poll(&sig, 1, 0) > 0 && (sig.revents & POLLIN))
		act |= take_signals(k);
	/* read() also fires the debounce and long-press timers: every frame */
	int got = k->in->read(now_ms(k, n), ev, INPUT_MAX_EVENTS, &err);
	if (got < 0) {
		/* once, not every frame for months: the show goes on without buttons */
		fprintf(stderr, "skinplay: input %s: %s; input off\n", k->in->name, err.msg);
		k->in->shutdown();
		k->in = &input_none;
		got = 0;
	}
	for (int i = 0; i < got; i++) {
		char line[96];
		control_action a = controls_handle(&k->ps, &ev[i], line, sizeof line);
		if (a != CONTROL_ACT_NONE)
			fprintf(cli_note(), "%s\n", line);
		if (a == CONTROL_ACT_PLAY)
			k->play_ms = ev[i].t_ms;
		act |= act_bit(a);
	}
	sdnotify_watchdog(&k->sd, clock_now_ns());
	return act;
}

/* A button pressed and released at once, through the state machine. */
static unsigned tap(skinplay_kiosk *k, int button, uint64_t t)
{
	static const uint8_t kinds[2] = { CONTROL_PRESS, CONTROL_RELEASE };
	unsigned act = 0;
	for (int i = 0; i < 2; i++) {
		control_event ev = { .button = (uint8_t)button, .kind = kinds[i], .t_ms = t };
		char line[96];
		control_action a = controls_handle(&k->ps, &ev, line, sizeof line);
		if (a != CONTROL_ACT_NONE)
			fprintf(cli_note(), "%s\n", line);
		if (a == CONTROL_ACT_PLAY)
			k->play_ms = t;
		act |= act_bit(a);
	}
	return act;
}

unsigned skinplay_kiosk_key(skinplay_kiosk *k, int key, long n)
{
	static const char buttons[] = "1234";
	const char *b = key > 0 ? strchr(buttons, key) : NULL;
	if (b)
		return tap(k, (int)(b - buttons), now_ms(k, n));
	if (key == 'v')
		return tap(k, CONTROL_BTN_VIEW, now_ms(k, n));
	if (key != 'd')
		return 0;
	k->ps.view = k->ps.view == RENDER_VIEW_DIFFERENCE ? RENDER_VIEW_BODY : RENDER_VIEW_DIFFERENCE;
	fprintf(cli_note(), "input: key d -> %s\n", render_view_name(k->ps.view));
	return SKINPLAY_ACT_VIEW;
}

void skinplay_kiosk_shutdown(skinplay_kiosk *k)
{
	if (k->in_started)
		k->in->shutdown();
	k->in_started = 0;
	if (k->sd.fd >= 0)
		sdnotify_send(&k->sd, "STOPPING=1");
	sdnotify_close(&k->sd);
	if (k->sig_fd >= 0)
		signals_shutdown();
	k->sig_fd = -1;
}
