/* The kiosk's shell on Linux (kiosk_shell.h). */
#include "kiosk_shell.h"

#include <poll.h>
#include <string.h>

#include "cli_error.h"
#include "cli_say.h"
#include "clock.h"
#include "display.h"
#include "file_reader.h"
#include "render.h"
#include "skp_format.h"
#include "signals.h"

void kiosk_shell_init(kiosk_shell *k, const char *prog)
{
	memset(k, 0, sizeof *k);
	k->prog = prog;
	k->sig_fd = -1;
	k->sd.fd = -1;
	board_config_defaults(&k->board);
}

/* Says each of the board file's problems once (the key keeps its
 * default), and keeps the first for the engineer HUD. */
static void report_board(kiosk_shell *k, const char *path)
{
	const board_config *b = &k->board;
	int listed = b->problem_count < BOARD_MAX_PROBLEMS ? b->problem_count : BOARD_MAX_PROBLEMS;
	for (int i = 0; i < listed; i++) {
		if (b->problem[i].line > 0)
			cli_warn("%s:%ld: %s; ignored, the default stays\n", path, b->problem[i].line, b->problem[i].msg);
		else
			cli_warn("%s: %s\n", path, b->problem[i].msg);
	}
	if (b->problem_count > listed)
		cli_warn("%s: %d more problems not listed\n", path, b->problem_count - listed);
	if (b->problem_count) {
		char file[25], first[73];   /* what fits the HUD's line */
		skp_escape_name(file, sizeof file, cli_basename(path));
		skp_escape_name(first, sizeof first, b->problem[0].msg);
		skp_format(k->board_note, sizeof k->board_note, "%s: %s%s", file, first,
			   b->problem_count > 1 ? " (MORE IN THE LOG)" : "");
	}
}

void kiosk_shell_load_board(kiosk_shell *k, const char *path)
{
	file_reader fr;
	skp_error err;
	int rc = file_reader_open(&fr, path);
	if (rc < 0) {
		char msg[160];
		skp_format(msg, sizeof msg, "cannot open: %s; running with the defaults", strerror(-rc));
		board_config_problem(&k->board, 0, msg);
	} else {
		if (board_config_read(&k->board, file_reader_as_reader(&fr), &err) != SKP_OK)
			board_config_problem(&k->board, err.line, err.msg);
		file_reader_close(&fr);
		k->have_board = 1;
	}
	report_board(k, path);
}

int kiosk_shell_prepare(kiosk_shell *k, const char *input)
{
	k->input_spec = input ? input : k->have_board && k->board.input[0] ? k->board.input : "none";
	const char *arg;
	if (!input_find(k->input_spec, &arg)) {
		cli_warn("%s: --input expects gpio, keyboard, script:FILE or none, got '%s'\n", k->prog,
			k->input_spec);
		return -1;
	}
	/* before the display and the worker threads start: a SIGTERM during a
	 * long setup is then not lost, and the handler serves every thread */
	k->sig_fd = signals_init();
	if (k->sig_fd < 0) {
		cli_warn("%s: signals: %s\n", k->prog, strerror(-k->sig_fd));
		return -1;
	}
	return 0;
}


static uint64_t now_ms(const kiosk_shell *k, long n)
{
	/* headless: display frame n is at n * 1000 / display rate ms exactly
	 * (the epsilon keeps 100.0 from rounding down to 99), so scripted runs
	 * are reproducible */
	if (k->headless)
		return (uint64_t)((double)n * 1000.0 / k->fps + 1e-6);
	return (clock_now_ns() - k->t0_ns) / 1000000u;
}

int kiosk_shell_start(kiosk_shell *k, const kiosk_start *s)
{
	skp_error err;
	const char *arg;
	k->headless = s->headless;
	k->fps = s->display_rate > 0 ? s->display_rate : 60.0;
	k->t0_ns = k->last_ns = clock_now_ns();
	controls_init(&k->ps, s->algo, s->view, s->gpu, s->clip_count);
	k->in = input_find(k->input_spec, &arg);
	if (k->in->init(&k->board, arg, now_ms(k, 0), &err) != 0) {
		/* a batch run fails; on a display no buttons is no reason to go dark */
		cli_warn("%s: input %s: %s%s\n", k->prog, k->in->name, err.msg,
			s->headless ? "" : "; running without buttons");
		if (s->headless)
			return -1;
		k->in = &input_none;
		k->in->init(&k->board, NULL, now_ms(k, 0), &err);
	}
	k->in_started = 1;
	if (k->in != &input_none)
		cli_say("input: %s%s%s\n", k->in->name, arg ? " " : "", arg ? arg : "");
	int rc = sdnotify_init(&k->sd);
	if (rc < 0)
		cli_warn("%s: $NOTIFY_SOCKET: %s\n", k->prog, strerror(-rc));
	sdnotify_send(&k->sd, "READY=1");
	return 0;
}

static unsigned act_bit(control_action a)
{
	static const unsigned bits[] = { 0, KIOSK_ACT_ALGO, KIOSK_ACT_PLAY, KIOSK_ACT_RESTART, KIOSK_ACT_CLIP, KIOSK_ACT_VIEW, KIOSK_ACT_GPU };
	return bits[a];
}

static unsigned take_signals(kiosk_shell *k)
{
	unsigned s = signals_take(), act = 0;
	if (s & SIGNALS_RELOAD) {
		cli_say("signal: SIGHUP -> reopen the show\n");
		sdnotify_send(&k->sd, "RELOADING=1");
		act |= KIOSK_ACT_RELOAD;
	}
	if (s & SIGNALS_QUIT) {
		cli_say("signal: quit -> clean exit\n");
		act |= KIOSK_ACT_QUIT;
	}
	return act;
}

/* Frame-rate cap on a display (the board's max_fps). */
static void pace(kiosk_shell *k)
{
	if (k->headless || k->board.max_fps <= 0)
		return;
	uint64_t next = k->last_ns + 1000000000u / (uint64_t)k->board.max_fps;
	if (clock_now_ns() < next)
		clock_sleep_until_ns(next);
	k->last_ns = clock_now_ns();
}

unsigned kiosk_shell_frame(kiosk_shell *k, long n)
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
		cli_warn("%s: input %s: %s; input off\n", k->prog, k->in->name, err.msg);
		k->in->shutdown();
		k->in = &input_none;
		got = 0;
	}
	for (int i = 0; i < got; i++) {
		char line[96];
		control_action a = controls_handle(&k->ps, &ev[i], line, sizeof line);
		if (a != CONTROL_ACT_NONE)
			cli_say("%s\n", line);
		if (a == CONTROL_ACT_PLAY)
			k->play_ms = ev[i].t_ms;
		act |= act_bit(a);
	}
	sdnotify_watchdog(&k->sd, clock_now_ns());
	return act;
}

/* A button pressed and released at once, through the state machine. */
static unsigned tap(kiosk_shell *k, int button, uint64_t t)
{
	static const uint8_t kinds[2] = { CONTROL_PRESS, CONTROL_RELEASE };
	unsigned act = 0;
	for (int i = 0; i < 2; i++) {
		control_event ev = { .button = (uint8_t)button, .kind = kinds[i], .t_ms = t };
		char line[96];
		control_action a = controls_handle(&k->ps, &ev, line, sizeof line);
		if (a != CONTROL_ACT_NONE)
			cli_say("%s\n", line);
		if (a == CONTROL_ACT_PLAY)
			k->play_ms = t;
		act |= act_bit(a);
	}
	return act;
}

_Static_assert(DISPLAY_KEY_LEFT == INPUT_KEY_LEFT && DISPLAY_KEY_RIGHT == INPUT_KEY_RIGHT,
	       "a window's keys and a terminal's share one map");

/* A console's camera keys (kiosk_camera_step); 0 when key is none. */
static unsigned camera_step_key(kiosk_shell *k, int key)
{
	/* pairs, the first of each -1 and the second 1: h l turn left,
	 * right; j k tilt down, up; H L J K move the same ways; x farther,
	 * z nearer */
	static const char keys[] = "hljkHLJKxz";
	const char *at = key > 0 && key < 0x80 ? strchr(keys, key) : NULL;
	if (!at)
		return 0;
	int i = (int)(at - keys);
	int *axis[] = { &k->cam.turn, &k->cam.tilt, &k->cam.move_x, &k->cam.move_y, &k->cam.zoom };
	memset(&k->cam, 0, sizeof k->cam);
	*axis[i / 2] = i % 2 ? 1 : -1;
	k->camera = 3;
	return KIOSK_ACT_CAMERA;
}

/* Keys for time and the camera: an arrow, [ ], + -, f, r. 0 when key is
 * none of them. */
static unsigned time_key(kiosk_shell *k, int key)
{
	switch (key) {
	case INPUT_KEY_LEFT: case INPUT_KEY_RIGHT:
		k->step = key == INPUT_KEY_LEFT ? -1 : 1;
		return KIOSK_ACT_STEP;
	case '[': case ']':
		k->seek = key == '[' ? -1 : 1;
		return KIOSK_ACT_SEEK;
	case '+': case '=': case '-': case '_':
		k->speed_step = key == '+' || key == '=' ? 1 : -1;
		return KIOSK_ACT_SPEED;
	case 'f': case 'F': case 'r': case 'R':
		k->camera = key == 'f' || key == 'F' ? 1 : 2;
		return KIOSK_ACT_CAMERA;
	case 'q': case 'Q': case INPUT_KEY_ESCAPE:
		return KIOSK_ACT_QUIT;
	default:
		return camera_step_key(k, key);
	}
}

unsigned kiosk_shell_key(kiosk_shell *k, int key, long n)
{
	static const char buttons[] = { ' ', 'n', 'v' };
	static const int taps[] = { CONTROL_BTN_PLAY, CONTROL_BTN_NEXT, CONTROL_BTN_VIEW };
	unsigned act = time_key(k, key);
	if (act)
		return act;
	if (key >= '1' && key <= '4') {
		k->ps.algo = key - '1';
		cli_say("input: key %c -> %s\n", key, skin_algo_name(k->ps.algo));
		return KIOSK_ACT_ALGO;
	}
	for (int i = 0; i < 3; i++)
		if (key == buttons[i] || key == (buttons[i] & ~0x20))
			return tap(k, taps[i], now_ms(k, n));
	if (key != 'd' && key != 'D')
		return 0;
	k->ps.view = k->ps.view == RENDER_VIEW_DIFFERENCE ? RENDER_VIEW_BODY : RENDER_VIEW_DIFFERENCE;
	cli_say("input: key d -> %s\n", render_view_name(k->ps.view));
	return KIOSK_ACT_VIEW;
}

void kiosk_shell_shutdown(kiosk_shell *k)
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
