#include "skinplay_opts.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "board_config.h"
#include "cli_args.h"
#include "cli_error.h"
#include "utc_time.h"

enum {
	OPT_IMAGE = 1, OPT_CLIP, OPT_ASF, OPT_AMC, OPT_BVH, OPT_MESH, OPT_ALGO, OPT_SKIN, OPT_PLATFORM, OPT_DEVICE,
	OPT_ROTATION, OPT_SIZE, OPT_FRAMES, OPT_START, OPT_OUT, OPT_EVERY, OPT_SHEET, OPT_VIEW, OPT_FPS,
	OPT_HUD_FPS, OPT_REPORT_MEMORY, OPT_BOARD, OPT_INPUT, OPT_PRINT_PLATFORM, OPT_HUD, OPT_REPORT_TIMING,
	OPT_THREADS, OPT_STREAMS, OPT_DISPLAY_RATE, OPT_SPEED, OPT_BLEND, OPT_ROOT, OPT_YAW, OPT_LOOP, OPT_POSE_DIGEST,
	OPT_BACKGROUND, OPT_SYNC, OPT_EPOCH, OPT_WALL, OPT_BEZEL, OPT_TEXTURE
};

#ifdef SKP_VIDEO
#define VIDEO_NOTE ""
#else
#define VIDEO_NOTE "; this build writes no video"
#endif

static const cli_opt play_opts_table[] = {
	{ "image", 0, "SHOW.skn", OPT_IMAGE, "play a packed image (repeat for slots: the newest valid one plays)" },
	{ "clip", 0, "NAME", OPT_CLIP, "the image's clip to start with (default: its first)" },
	{ "skeleton", 0, "S.asf", OPT_ASF, "the skeleton (also --asf)" },
	{ "asf", 0, "S.asf", OPT_ASF, "the skeleton" },
	{ "motion", 0, "M.amc|M.bvh", OPT_AMC, "the motion (also --amc; a BVH carries its skeleton)" },
	{ "amc", 0, "M.amc", OPT_AMC, "the motion" },
	{ "bvh", 0, "M.bvh", OPT_BVH, "skeleton and motion from one BVH file" },
	{ "mesh", 0, "MESH.obj", OPT_MESH, "the body to skin, or 'generated': the mannequin made around the skeleton "
	  "(the default)" },
	{ "algo", 0, "ALGO", OPT_ALGO, "lbs, dqbs, dqbs-fixed or compare (side by side; default: the board's "
	  "[display] algo, else dqbs)" },
	{ "skin", 0, "cpu|gpu", OPT_SKIN, "skin on the CPU (default) or in the vertex shader" },
	{ "threads", 0, "N|auto", OPT_THREADS, "CPU skinning on N threads, auto: one per core, for meshes of the "
	  "board's [skin] split_verts vertices or more (default: the board's, else auto)" },
	{ "streams", 0, "KIND", OPT_STREAMS, "float, or compact: LBS and DQBS read 16-bit vertex streams (38 bytes a "
	  "vertex, not 72; default: the board's, else float)" },
	{ "platform", 0, "NAME", OPT_PLATFORM, "auto, a display this build has (--version lists them), or none: nothing "
	  "drawn, the show's clock, images and logs run as headless (soak runs of days of frames; default auto)" },
	{ "device", 0, "DEV", OPT_DEVICE, "the DRM device for kms (default: the first with a screen)" },
	{ "rotation", 0, "DEG", OPT_ROTATION, "turn the picture 0, 90, 180 or 270 degrees (portrait screens)" },
	{ "size", 0, "WxH", OPT_SIZE, "the picture's size headless or in a window (default 1280x720)" },
	{ "frames", 0, "N", OPT_FRAMES, "play N frames (default: the clip once headless, for ever on a screen)" },
	{ "start", 0, "FRAME", OPT_START, "start at the frame numbered FRAME" },
	{ "output", 'o', "DIR|F.mp4|F.webm", OPT_OUT, "write every K-th frame as DIR/frame_NNNNNN.png (compressed for speed), or headless "
	  "into one video, F.mp4 (H.264) or F.webm (VP9), of --display-rate/K frames a second that lasts as long as "
	  "the frames it shows (the clip's duration; an even --size; also --out)" VIDEO_NOTE },
	{ "out", 0, "DIR|F.mp4|F.webm", OPT_OUT, "the same as --output" },
	{ "every", 0, "K", OPT_EVERY, "with --output: every K-th frame (default 1; a video then has 1/K the frame rate)" },
	{ "sheet", 0, "F.png", OPT_SHEET, "with --output: also a contact sheet of the frames written (PNG or video)" },
	{ "texture", 0, "auto|rgb565|off", OPT_TEXTURE, "the body's texture (an image packed from a textured rig): "
	  "auto hands its ETC1 blocks to a GPU that samples them (the Pi's) and decodes them to RGB565 for one that "
	  "does not; rgb565 decodes them always; off draws the body in its colours alone (default auto)" },
	{ "background", 0, "scene|transparent", OPT_BACKGROUND, "with --output DIR: transparent writes the character "
	  "alone on a see-through background (PNG alpha: no floor, grid, shadow, close-up or HUD; default scene)" },
	{ "view", 0, "VIEW", OPT_VIEW, "body, skeleton, weights or difference (the body coloured by how far LBS lies "
	  "from DQBS in the compare view, or the skin from its bone as bound with one method, in millimetres; "
	  "default: the board's [display] view, else body)" },
	{ "fps", 0, "F", OPT_FPS, "an AMC's capture rate in Hz (default 120, the CMU rate; a BVH's Frame Time and an "
	  "image's directory give theirs)" },
	{ "display-rate", 0, "HZ", OPT_DISPLAY_RATE, "headless: the virtual display's rate; frame n shows the motion at "
	  "n/HZ s (default 60; --frames, --every and the PNG numbers count these frames)" },
	{ "speed", 0, "F", OPT_SPEED, "play at F times the captured speed, 0.1 to 4 (default: the board's [show] speed, "
	  "else 1)" },
	{ "blend-ms", 0, "MS", OPT_BLEND, "crossfade over MS ms where a clip loops or changes, 0: cut (default: the "
	  "board's [show] blend_ms, else 300)" },
	{ "root", 0, "MODE", OPT_ROOT, "in-place: the root's horizontal travel taken out (a looping walk never jumps); "
	  "travel: kept, the camera follows (default: the board's [show] root, else in-place)" },
	{ "loop", 0, "show|clip", OPT_LOOP, "show: an image's clips play in turn and the show loops (headless: the show "
	  "once); clip: the clip loops until NEXT (default: the board's [show] loop, else show)" },
	{ "sync", 0, "off|clock", OPT_SYNC, "clock: the show's position is the wall clock's, (now - epoch) modulo the "
	  "show's length, so that devices on synchronised clocks (chrony, linuxptp) play in lock-step; headless, the "
	  "virtual display starts at the wall clock's time (default: the board's [show] sync, else off)" },
	{ "epoch", 0, "TIME", OPT_EPOCH, "with --sync=clock: when the show began, ISO 8601 UTC such as "
	  "2026-01-01T00:00:00Z (default: the board's [show] epoch, else 1970-01-01T00:00:00Z)" },
	{ "wall", 0, "CxR+X+Y", OPT_WALL, "a video wall of C screens across and R down, this one at column X and row Y "
	  "from 0 at the top left (3x1+2+0: the right one of three): it draws its tile of one picture the size of the "
	  "wall (default: the board's [wall], else none)" },
	{ "bezel", 0, "PX", OPT_BEZEL, "with --wall: the picture hidden behind two neighbouring screens' frames, in "
	  "pixels (default: the board's [wall] bezel, else 0)" },
	{ "yaw", 0, "DEG|auto", OPT_YAW, "turn the camera DEG degrees about the vertical from the usual view; auto: to "
	  "the clip's mean facing (default: the board's [display] yaw, else auto)" },
	{ "hud", 0, "MODE", OPT_HUD, "visitor, engineer or off (default: the board's [display] hud, else engineer)" },
	{ "hud-fps", 0, "on|off", OPT_HUD_FPS, "engineer HUD: show the measured frame rate (off: reproducible pictures)" },
	{ "report-memory", 0, NULL, OPT_REPORT_MEMORY, "print the peak and current resident memory at the end" },
	{ "pose-digest", 0, NULL, OPT_POSE_DIGEST, "print at the end a digest of every pose shown (FNV-1a of the joints): "
	  "two runs showing the same poses print the same" },
	{ "report-timing", 0, NULL, OPT_REPORT_TIMING, "print per stage (decode, FK, bones, skinning, upload, draw, "
	  "swap) the mean and worst time at the end" },
	{ "board", 0, "FILE", OPT_BOARD, "the board's runtime config (board/NAME/board.ini; default: none)" },
	{ "input", 0, "SPEC", OPT_INPUT, "buttons: gpio, keyboard (the terminal's keys), script:FILE or none (default: the board's)" },
	{ "print-platform", 0, NULL, OPT_PRINT_PLATFORM, "print the display backend auto would pick, and exit" },
	{ NULL, 0, NULL, 0, NULL },
};

#define PROG "skinplay"

static int parse_size(const char *v, play_opts *o)
{
	char *x;
	long w = v ? strtol(v, &x, 10) : 0, h = 0;
	if (v && *x == 'x')
		h = strtol(x + 1, &x, 10);
	if (!v || *x || w < 16 || h < 16 || w > SKP_DISPLAY_MAX_W || h > SKP_DISPLAY_MAX_H) {
		fprintf(stderr, PROG ": --size expects WxH between 16x16 and %dx%d (board limit), got '%s'\n",
			SKP_DISPLAY_MAX_W, SKP_DISPLAY_MAX_H, v ? v : "");
		return -1;
	}
	o->width = (int)w;
	o->height = (int)h;
	return 0;
}

static int take_image(play_opts *o, const char *v)
{
	if (o->image_count >= 4)
		return fprintf(stderr, PROG ": at most 4 --image slots\n"), -1;
	o->image[o->image_count++] = v;
	return 0;
}

static int take_motion(play_opts *o, const char *v)
{
	const char *dot = strrchr(v, '.');
	if (dot && !strcasecmp(dot, ".bvh"))
		o->bvh = v;
	else
		o->amc = v;
	return 0;
}

static int take_number(const char *opt, const char *v, long *out, long min)
{
	if (cli_parse_long(opt, v, out) < 0)
		return -1;
	if (*out < min)
		return fprintf(stderr, PROG ": %s expects %ld or more, got %ld\n", opt, min, *out), -1;
	return 0;
}

static int take_threads(play_opts *o, const char *v)
{
	if ((o->threads = board_threads_parse(v)) < 0)
		return fprintf(stderr, PROG ": --threads expects auto or 1..%d, got '%s'\n", BOARD_MAX_THREADS, v), -1;
	return 0;
}

static int take_rate(play_opts *o, const char *v)
{
	char *end;
	o->fps = strtod(v, &end);
	if (*end || !(o->fps >= 1.0 && o->fps <= 10000.0))
		return fprintf(stderr, PROG ": --fps expects a rate from 1 to 10000 Hz, got '%s'\n", v), -1;
	return 0;
}

/* --wall=CxR+X+Y: C screens across, R down, this one at X, Y. */
static int take_wall(play_opts *o, const char *v)
{
	int c, r, x, y, used = 0;
	if (sscanf(v, "%dx%d+%d+%d%n", &c, &r, &x, &y, &used) != 4 || v[used] || c < 1 || c > BOARD_WALL_MAX || r < 1 ||
	    r > BOARD_WALL_MAX || x < 0 || x >= c || y < 0 || y >= r)
		return fprintf(stderr, PROG ": --wall expects COLUMNSxROWS+COLUMN+ROW (1 to %d screens each way, this "
			       "screen's column and row from 0), such as 3x1+2+0; got '%s'\n", BOARD_WALL_MAX, cli_shown(v)), -1;
	o->wall = (render_wall){ c, r, x, y, 0 };
	o->wall_given = 1;
	return 0;
}

/* The playback options (--display-rate, --speed, --blend-ms, --root, --loop, --yaw). */
static int take_timing(play_opts *o, int id, const char *v)
{
	static const char *const roots[] = { "in-place", "travel" };
	char *end;
	long n;
	switch (id) {
	case OPT_DISPLAY_RATE:
		o->display_rate = strtod(v, &end);
		if (end == v || *end || !(o->display_rate >= 1.0 && o->display_rate <= 1000.0))
			return fprintf(stderr, PROG ": --display-rate expects 1 to 1000 Hz, got '%s'\n", v), -1;
		return 0;
	case OPT_SPEED:
		if (board_speed_parse(v, &o->speed) < 0)
			return fprintf(stderr, PROG ": --speed expects 0.1 to 4 (1: as captured), got '%s'\n", v), -1;
		return 0;
	case OPT_BLEND:
		if (cli_parse_long("--blend-ms", v, &n) < 0 || n < 0 || n > BOARD_BLEND_MS_MAX)
			return fprintf(stderr, PROG ": --blend-ms expects 0 to %d ms, got '%s'\n", BOARD_BLEND_MS_MAX, v), -1;
		o->blend_ms = (int)n;
		return 0;
	case OPT_ROOT:
		if ((o->root = board_root_parse(v)) < 0)
			return cli_bad_choice(PROG, "root", v, roots, 2);
		return 0;
	case OPT_LOOP:
		if ((o->loop = board_loop_parse(v)) < 0)
			return cli_bad_choice(PROG, "loop", v, board_loop_names, BOARD_LOOP_MODES);
		return 0;
	default:
		if ((o->yaw_mode = board_yaw_parse(v, &o->yaw_deg)) < 0)
			return fprintf(stderr, PROG ": --yaw expects auto or degrees from -360 to 360, got '%s'\n", v), -1;
		return 0;
	}
}

/* A name modes.h does not know: refused with the names it does, the
 * list the board file and the buttons use, so a new method or view is
 * listed without a second list here. */
#define MODE_NAMES_MAX ((int)SKIN_SHOW_COUNT > (int)RENDER_VIEW_COUNT ? (int)SKIN_SHOW_COUNT : (int)RENDER_VIEW_COUNT)

static int bad_mode(const char *opt, const char *v, const char *(*name)(int), int n)
{
	const char *names[MODE_NAMES_MAX];
	for (int i = 0; i < n; i++)
		names[i] = name(i);
	return cli_bad_choice(PROG, opt, v, names, n);
}

static int take_choice(play_opts *o, int id, const char *v)
{
	static const char *const skins[] = { "cpu", "gpu" }, *const onoff[] = { "off", "on" };
	static const char *const backgrounds[] = { "scene", "transparent" };
	static const char *const textures[] = { "auto", "rgb565", "off" };
	int k;
	switch (id) {
	case OPT_ALGO:
		if ((k = skin_algo_parse(v)) < 0)
			return bad_mode("algo", v, skin_algo_name, SKIN_SHOW_COUNT);
		o->algo = k;
		o->algo_given = 1;
		return 0;
	case OPT_VIEW:
		if ((k = render_view_parse(v)) < 0)
			return bad_mode("view", v, render_view_name, RENDER_VIEW_COUNT);
		o->view = k;
		o->view_given = 1;
		return 0;
	case OPT_SKIN:
		return (k = cli_choice(PROG, "skin", v, skins, 2)) < 0 ? -1 : (o->gpu = k, 0);
	case OPT_BACKGROUND:
		return (k = cli_choice(PROG, "background", v, backgrounds, 2)) < 0 ? -1 : (o->transparent = k, 0);
	case OPT_TEXTURE:
		return (k = cli_choice(PROG, "texture", v, textures, 3)) < 0 ? -1 : (o->texture = k, 0);
	default:
		return (k = cli_choice(PROG, "hud-fps", v, onoff, 2)) < 0 ? -1 : (o->hud_fps = k, 0);
	}
}

static int take(void *ctx, int id, const char *v)
{
	play_opts *o = ctx;
	long n;
	if (BIND_OPT_ID(id))
		return bind_args_take(&o->bind, PROG, id, v);
	switch (id) {
	case OPT_IMAGE: return take_image(o, v);
	case OPT_CLIP:
		if (!*v)
			return fprintf(stderr, PROG ": --clip expects a clip's name (skintool info SHOW.skn lists them)\n"), -1;
		o->clip = v;
		return 0;
	case OPT_ASF: o->asf = v; return 0;
	case OPT_AMC: return take_motion(o, v);
	case OPT_BVH: o->bvh = v; return 0;
	case OPT_MESH: o->mesh = v; return 0;
	case OPT_ALGO: case OPT_VIEW: case OPT_SKIN: case OPT_HUD_FPS: case OPT_BACKGROUND: case OPT_TEXTURE:
		return take_choice(o, id, v);
	case OPT_PLATFORM: o->platform = v; return 0;
	case OPT_DEVICE: o->device = v; return 0;
	case OPT_ROTATION:
		if (cli_parse_long("--rotation", v, &n) < 0 || n % 90 || n < 0 || n > 270)
			return fprintf(stderr, PROG ": --rotation expects 0, 90, 180 or 270, got '%s'\n", v), -1;
		o->rotation = (int)n;
		return 0;
	case OPT_SIZE: return parse_size(v, o);
	case OPT_FRAMES: return take_number("--frames", v, &o->frames, 1);
	case OPT_START: return take_number("--start", v, &o->start, 0);
	case OPT_OUT: o->out_dir = v; return 0;
	case OPT_EVERY: return take_number("--every", v, &o->every, 1);
	case OPT_SHEET: o->sheet_path = v; return 0;
	case OPT_FPS: return take_rate(o, v);
	case OPT_DISPLAY_RATE: case OPT_SPEED: case OPT_BLEND: case OPT_ROOT: case OPT_LOOP: case OPT_YAW:
		return take_timing(o, id, v);
	case OPT_SYNC:
		if (strcmp(v, "off") && strcmp(v, "clock"))
			return fprintf(stderr, PROG ": --sync expects off or clock, got '%s'\n", cli_shown(v)), -1;
		o->sync = !strcmp(v, "clock");
		return 0;
	case OPT_EPOCH:
		if (utc_time_parse(v, &o->epoch_ns) < 0)
			return fprintf(stderr, PROG ": --epoch expects an ISO 8601 UTC time such as 2026-01-01T00:00:00Z, "
				       "got '%s'\n", cli_shown(v)), -1;
		o->epoch_given = 1;
		return 0;
	case OPT_WALL: return take_wall(o, v);
	case OPT_BEZEL:
		if (cli_parse_long("--bezel", v, &n) < 0 || n < 0 || n > 2000)
			return fprintf(stderr, PROG ": --bezel expects 0 to 2000 pixels, got '%s'\n", cli_shown(v)), -1;
		o->bezel = (int)n;
		return 0;
	case OPT_REPORT_MEMORY: o->report_memory = 1; return 0;
	case OPT_REPORT_TIMING: o->report_timing = 1; return 0;
	case OPT_POSE_DIGEST: o->pose_digest = 1; return 0;
	case OPT_THREADS: return take_threads(o, v);
	case OPT_STREAMS:
		if ((o->streams = board_streams_parse(v)) < 0)
			return cli_bad_choice(PROG, "streams", v, board_streams_names, BOARD_STREAMS_KINDS);
		return 0;
	case OPT_BOARD: o->board = v; return 0;
	case OPT_INPUT: o->input = v; return 0;
	case OPT_PRINT_PLATFORM: o->print_platform = 1; return 0;
	case OPT_HUD:
		if ((o->hud = board_hud_parse(v)) < 0)
			return cli_bad_choice(PROG, "hud", v, board_hud_names, BOARD_HUD_MODES);
		return 0;
	}
	return -1;
}

/* --output: a directory of PNG frames (one that exists is one, whatever
 * its name), or a video by its name: F.mp4 or F.webm where the build has
 * video output; another video container's name is refused rather than
 * made a directory of frames the user did not mean. */
static int output_kind(play_opts *o)
{
	static const char *const videos[] = { ".mp4", ".webm" };
	static const char *const others[] = { ".avi", ".mkv", ".mov", ".m4v", ".gif", ".ogv", ".flv", ".wmv",
					      ".mpg", ".mpeg", ".ts", ".3gp", ".h264", ".264", ".ivf" };
	struct stat st;
	const char *slash = strrchr(o->out_dir, '/'), *dot = strrchr(slash ? slash + 1 : o->out_dir, '.');
	if (!dot || (stat(o->out_dir, &st) == 0 && S_ISDIR(st.st_mode)))
		return 0;
	for (size_t i = 0; i < sizeof videos / sizeof videos[0]; i++)
		if (!strcasecmp(dot, videos[i])) {
#ifdef SKP_VIDEO
			o->video = 1;
			return 0;
#else
			return fprintf(stderr, PROG ": -o %s: this build has no video output (built without libavcodec; "
				       "Debian: libavcodec-dev libavformat-dev libswscale-dev); write PNG frames with -o DIR\n",
				       cli_shown(o->out_dir)), -1;
#endif
		}
	for (size_t i = 0; i < sizeof others / sizeof others[0]; i++)
		if (!strcasecmp(dot, others[i]))
			return fprintf(stderr, PROG ": -o %s: a video is F.mp4 (H.264) or F.webm (VP9), not %s; PNG frames go "
				       "into a directory (-o DIR)\n", cli_shown(o->out_dir), dot), -1;
	return 0;
}

static const cli_command play_command = {
	.prog = PROG,
	.usage = "[OPTION]... --image SHOW.skn\n"
		 "  or:  skinplay [OPTION]... --asf S.asf --amc M.amc [--mesh MESH.obj]\n"
		 "  or:  skinplay [OPTION]... --bvh M.bvh [--mesh MESH.obj]",
	.about = "Plays motion capture on a skinned body with LBS, DQBS or fixed-point DQBS, on a screen (DRM/KMS\n"
		 "console or X11 window) or headless (EGL surfaceless, OSMesa). The motion plays at the speed it was\n"
		 "captured whatever the frame rate: each frame shows the pose at its time on the clock, interpolated\n"
		 "between the captured frames. Headless, a virtual display of --display-rate frames a second plays\n"
		 "the clip once (a scripted pause holds the frame, and the held frames count: the run always ends);\n"
		 "on a screen it loops until closed, crossfading at the loop, and buttons (--input) switch the\n"
		 "algorithm, pause, restart and change clips.",
	.opts = { play_opts_table, bind_opts },
	.take = take,
	.more = "Without --mesh the generated body is used; the bind options apply to --mesh.\n"
		"\n"
		"In the compare view each body stands beside a close-up of the joint where LBS and DQBS part most at\n"
		"the moment, held at least 2 s, named (LEFT WRIST), with how the joint turned and how far apart the two\n"
		"put its skin in millimetres.\n"
		"\n"
		"Keys in a window (x11) and on a terminal (--input keyboard: a console), the legend showing for the first\n"
		"10 s: 1 LBS, 2 DQBS, 3 fixed-point DQBS, 4 LBS\n"
		"beside DQBS; v the next view, d the difference view and back; space pauses and plays; the left and\n"
		"right arrows step one captured frame while paused; [ and ] seek a second back and on; + and - double\n"
		"and halve the speed (1/8 to 4); n the next clip; q or Escape quit. A drag turns the camera round the\n"
		"body and up or down, a right or middle drag (or shift and drag) moves the point it looks at, the wheel\n"
		"brings it nearer or farther, f frames the body again, r resets it. Without a pointer (a console), h and\n"
		"l turn the camera 15 degrees, j and k tilt it 10, H J K L move the point it looks at, z and x bring it\n"
		"nearer and farther. A --sync=clock show keeps its clock (space and n then act as the buttons do).\n",
	.exit2 = "headless, no clip of the show could play (the bind pose was rendered)",
	.examples = (const cli_example[]){
		{ "The packaged demo on the screen",
		  "skinplay --image /usr/share/skinplay/demo.skn" },
		{ "A kiosk: the board's config, its image slots and buttons",
		  "skinplay --board /etc/skinplay/board.ini" },
		{ "A BVH headless, LBS beside DQBS, every 60th frame into out/",
		  "skinplay --bvh 131_01.bvh --platform surfaceless --algo compare -o out --every 60" },
		{ "The same as an H.264 video of 30 frames a second, as long as the clip",
		  "skinplay --bvh 131_01.bvh --platform surfaceless --algo compare --size 960x540 --display-rate 30 -o walk.mp4" },
		{ NULL, NULL },
	},
};

int play_parse(play_opts *o, int argc, char **argv)
{
	memset(o, 0, sizeof *o);
	bind_args_init(&o->bind);
	o->algo = SKIN_DQBS;
	o->width = 1280;
	o->height = 720;
	o->frames = -1;
	o->start = -1;
	o->every = 1;
	o->hud_fps = 1;
	o->hud = -1;
	o->threads = -1;
	o->streams = -1;
	o->fps = 120.0;
	o->display_rate = 60.0;
	o->blend_ms = -1;
	o->root = -1;
	o->loop = -1;
	o->sync = -1;
	o->bezel = -1;
	o->yaw_mode = -1;
	int rc = cli_parse(&play_command, o, argc, argv, 1);
	if (rc != 0)
		return rc;
	if (o->print_platform)
		return 0;
	if (o->out_dir && output_kind(o) < 0)
		return -1;
	if (o->transparent && o->video) {
		fprintf(stderr, PROG ": -o %s: --background=transparent needs an alpha channel, which a video has not; "
			"write PNG frames with -o DIR\n", cli_shown(o->out_dir));
		return -1;
	}
	if (o->sheet_path && !o->out_dir) {
		fprintf(stderr, PROG ": --sheet collects the frames --out writes: give --out too\n");
		return -1;
	}
	if (o->transparent && !o->out_dir) {
		fprintf(stderr, PROG ": --background=transparent is for the frames --out writes (a screen shows no "
			"alpha): give --out too\n");
		return -1;
	}
	/* a BVH is the skeleton and the motion in one file */
	if (o->bvh && (o->asf || o->amc)) {
		fprintf(stderr, PROG ": --bvh carries its skeleton: give it without --asf and --amc\n");
		return -1;
	}
	if (o->bvh)
		o->asf = o->amc = o->bvh;
	if (o->image_count && (o->asf || o->amc || o->mesh || o->bind.group || o->bind.fit || o->bind.no_fit ||
			       o->bind.rest_pose || o->bind.pose_path ||
			       o->bind.weights_path || o->bind.weights_mesh || o->bind.joint_map || o->bind.balance >= 0)) {
		fprintf(stderr, PROG ": --image carries the skeleton, the bound body and the clips: "
			"give it without --asf, --amc, --bvh, --mesh and the bind options\n");
		return -1;
	}
	/* with --board the show may come from its [storage] slots (skinplay_board.c) */
	if (!o->image_count && !o->board && (!o->asf || !o->amc)) {
		return cli_missing(PROG, "--image, or --asf and --amc, or --bvh");
	}
	return 0;
}
