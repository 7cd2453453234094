#include "skinplay_opts.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_common.h"

static const char usage_text[] =
	"usage: skinplay [--image show.skn [--image slot2.skn] [--clip NAME] | --asf A.asf --amc M.amc | --bvh M.bvh\n"
	"                [--mesh M.obj]\n"
	"                [--group G] [--fit|--no-fit] [--bind-pose P.amc[:F]|rest] [--weights W.csv] [--balance on|off]]\n"
	"                [--algo lbs|dqbs|dqbs-fixed|compare] [--skin cpu|gpu]\n"
	"                [--platform auto|surfaceless|osmesa|kms|x11] [--device DEV] [--rotation 0|90|180|270]\n"
	"                [--size WxH] [--frames N] [--start FRAME] [--out DIR [--every K] [--sheet F.png]]\n"
	"                [--view body|skeleton|weights] [--fps F] [--hud-fps on|off] [--report-memory]\n"
	"                [--board board/NAME/board.ini] [--input gpio|keyboard|script:FILE|none]\n"
	"Without --mesh the generated body is used. Headless, the clip plays once;\n"
	"on a display it loops until closed.\n";

static int unknown(const char *opt, const char *v)
{
	fprintf(stderr, "skinplay: %s: unknown value '%s'\n", opt, v ? v : "");
	return -1;
}

static int pick(const char *opt, const char *v, const char *const *names, int n)
{
	for (int i = 0; v && i < n; i++)
		if (strcmp(v, names[i]) == 0)
			return i;
	return unknown(opt, v);
}

static int parse_size(const char *v, play_opts *o)
{
	char *x;
	long w = v ? strtol(v, &x, 10) : 0, h = 0;
	if (v && *x == 'x')
		h = strtol(x + 1, &x, 10);
	if (!v || *x || w < 16 || h < 16 || w > SKP_DISPLAY_MAX_W || h > SKP_DISPLAY_MAX_H) {
		fprintf(stderr, "skinplay: --size expects WxH between 16x16 and %dx%d (board limit), got '%s'\n",
			SKP_DISPLAY_MAX_W, SKP_DISPLAY_MAX_H, v ? v : "");
		return -1;
	}
	o->width = (int)w;
	o->height = (int)h;
	return 0;
}

static int value_opt(play_opts *o, const char *a, const char *v)
{
	static const char *const skins[] = { "cpu", "gpu" };
	static const char *const onoff[] = { "off", "on" };
	long n;
	int k;
	if (!strcmp(a, "--asf")) o->asf = v;
	else if (!strcmp(a, "--amc")) o->amc = v;
	else if (!strcmp(a, "--bvh")) o->bvh = v;
	else if (!strcmp(a, "--mesh")) o->mesh = v;
	else if (!strcmp(a, "--image")) {
		if (o->image_count >= 4)
			return fprintf(stderr, "skinplay: at most 4 --image slots\n"), -1;
		o->image[o->image_count++] = v;
	} else if (!strcmp(a, "--clip")) o->clip = v;
	else if (!strcmp(a, "--input")) o->input = v;
	else if (!strcmp(a, "--board")) o->board = v;
	else if (!strcmp(a, "--platform")) o->platform = v;
	else if (!strcmp(a, "--device")) o->device = v;
	else if (!strcmp(a, "--out")) o->out_dir = v;
	else if (!strcmp(a, "--sheet")) o->sheet_path = v;
	else if (!strcmp(a, "--algo")) return (k = skin_algo_parse(v)) < 0 ? unknown(a, v) : (o->algo = k, 0);
	else if (!strcmp(a, "--skin")) return (k = pick(a, v, skins, 2)) < 0 ? -1 : (o->gpu = k, 0);
	else if (!strcmp(a, "--view")) return (k = render_view_parse(v)) < 0 ? unknown(a, v) : (o->view = k, 0);
	else if (!strcmp(a, "--hud-fps")) return (k = pick(a, v, onoff, 2)) < 0 ? -1 : (o->hud_fps = k, 0);
	else if (!strcmp(a, "--size")) return parse_size(v, o);
	else if (!strcmp(a, "--frames")) return cli_parse_long(a, v, &o->frames);
	else if (!strcmp(a, "--start")) return cli_parse_long(a, v, &o->start);
	else if (!strcmp(a, "--every")) return cli_parse_long(a, v, &o->every) < 0 || o->every < 1 ? -1 : 0;
	else if (!strcmp(a, "--rotation")) {
		if (cli_parse_long(a, v, &n) < 0 || n % 90 || n < 0 || n > 270)
			return fprintf(stderr, "skinplay: --rotation expects 0, 90, 180 or 270\n"), -1;
		o->rotation = (int)n;
	} else if (!strcmp(a, "--fps")) {
		o->fps = v ? atof(v) : 0;
		if (!(o->fps > 0 && o->fps < 10000))
			return fprintf(stderr, "skinplay: --fps expects a rate in Hz\n"), -1;
	} else
		return 1;
	return 0;
}

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
	o->fps = 120.0;
	for (int i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))
			return fputs(usage_text, stdout), 1;
		if (!strcmp(argv[i], "--print-platform")) {
			o->print_platform = 1;
			return 0;
		}
		if (!strcmp(argv[i], "--report-memory")) {
			o->report_memory = 1;
			continue;
		}
		int r = bind_args_parse(&o->bind, argc, argv, &i);
		if (r < 0)
			return -1;
		if (r > 0)
			continue;
		if (argv[i][0] != '-' || i + 1 >= argc || (r = value_opt(o, argv[i], argv[i + 1])) > 0) {
			fprintf(stderr, "skinplay: unknown option or missing value: '%s'\n%s", argv[i], usage_text);
			return -1;
		}
		if (r < 0)
			return -1;
		i++;
	}
	if (o->sheet_path && !o->out_dir) {
		fprintf(stderr, "skinplay: --sheet collects the frames --out writes: give --out too\n");
		return -1;
	}
	/* a BVH is the skeleton and the motion in one file */
	if (o->bvh && (o->asf || o->amc)) {
		fprintf(stderr, "skinplay: --bvh carries its skeleton: give it without --asf and --amc\n");
		return -1;
	}
	if (o->bvh)
		o->asf = o->amc = o->bvh;
	if (o->image_count && (o->asf || o->amc || o->mesh || o->bind.group || o->bind.fit || o->bind.no_fit ||
			       o->bind.rest_pose || o->bind.pose_path ||
			       o->bind.weights_path || o->bind.balance >= 0)) {
		fprintf(stderr, "skinplay: --image carries the skeleton, the bound body and the clips: "
			"give it without --asf, --amc, --bvh, --mesh and the bind options\n");
		return -1;
	}
	/* with --board the show may come from its [storage] slots (skinplay_kiosk.c) */
	if (!o->image_count && !o->board && (!o->asf || !o->amc)) {
		fprintf(stderr, "skinplay: give --asf and --amc, or --bvh\n%s", usage_text);
		return -1;
	}
	return 0;
}
