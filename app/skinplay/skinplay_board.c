/* skinplay's board: what board.ini sets of skinplay's options (the
 * command line wins), the defaults neither says, the screen's part in an
 * installation; the kiosk's shell (app/runtime/kiosk_shell.h) does the
 * rest. */
#include "skinplay_board.h"

#include <math.h>
#include <stdio.h>
#include <string.h>


static int given(int argc, char **argv, const char *opt)
{
	for (int i = 1; i < argc; i++)
		if (!strcmp(argv[i], opt))
			return 1;
	return 0;
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

int skinplay_board_setup(kiosk_shell *k, play_opts *o, int argc, char **argv)
{
	kiosk_shell_init(k, "skinplay");
	if (o->board)
		kiosk_shell_load_board(k, o->board);
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
	return kiosk_shell_prepare(k, o->input);
}

int skinplay_kiosk_start(kiosk_shell *k, const play_opts *o, int headless, int clip_count)
{
	kiosk_start s = { o->algo, o->view, o->gpu, headless, o->display_rate, clip_count };
	return kiosk_shell_start(k, &s);
}
