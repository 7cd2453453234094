/* skintool fk SKELETON.asf MOTION.amc [--frame N | --time T...]: joint
 * positions as CSV, at captured frames or, through the playback engine's
 * sampler (app/play), at any time between them. skintool fk SHOW.skn
 * [--clip NAME]: the same of a packed clip, as the image decodes it (so the
 * two CSVs measure what packing costs). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "clip_file.h"
#include "cli_args.h"
#include "cli_error.h"
#include "cli_opts.h"
#include "motion_file.h"
#include "show_source.h"
#include "fk.h"
#include "play_engine.h"
#include "play_image_source.h"
#include "skintool_cmds.h"

#define FK_MAX_TIMES 256

/* Prints the pose's rows; -1 after saying so when a value is not finite
 * (the parsers refuse what could make one: never a NaN row). */
static int print_pose(const skel *s, const char *when, const skel_pose *p)
{
	for (int b = 0; b < s->count; b++) {
		quat q = p->rot[b];
		if (!isfinite(p->tip[b].x + p->tip[b].y + p->tip[b].z + q.w + q.x + q.y + q.z)) {
			fprintf(stderr, "skintool fk: %s: bone '%s': the pose is not finite\n", when, s->bone[b].name);
			return -1;
		}
		if (q.w < 0.0f)
			q = (quat){ -q.w, -q.x, -q.y, -q.z };
		printf("%s,%s,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g\n", when, s->bone[b].name,
		       p->tip[b].x, p->tip[b].y, p->tip[b].z, q.w, q.x, q.y, q.z);
	}
	return 0;
}

typedef struct fk_args {
	const char *asf, *amc, *clip;
	long only;
	double fps;
	const char *time[FK_MAX_TIMES];  /* as given: the CSV's first column */
	double seconds[FK_MAX_TIMES];
	int times;
} fk_args;

enum { OPT_SKELETON = 1, OPT_MOTION, OPT_FRAME, OPT_TIME, OPT_FPS, OPT_CLIP };

static const cli_opt fk_opts[] = {
	{ "skeleton", 0, "S.asf", OPT_SKELETON, "the skeleton (or the first file named)" },
	{ "motion", 0, "M.amc", OPT_MOTION, "the motion (or the second file; a BVH alone is both)" },
	{ "frame", 0, "N", OPT_FRAME, "only the frame numbered N in the file (default: every frame)" },
	{ "time", 0, "SECONDS", OPT_TIME, "the pose at SECONDS from the first frame, interpolated between the "
	  "captured frames (repeatable; past the last frame: the last frame)" },
	{ "fps", 0, "F", OPT_FPS, "an AMC's capture rate in Hz for --time (default 120; a BVH says its own)" },
	{ "clip", 0, "NAME", OPT_CLIP, "of an image: the clip (default: its first)" },
	{ NULL, 0, NULL, 0, NULL },
};

static int take_time(fk_args *a, const char *v)
{
	char *end;
	double t = strtod(v, &end);
	if (end == v || *end || !(t >= 0.0 && t < 1e9))
		return fprintf(stderr, "skintool fk: --time expects seconds (0 or more), got '%s'\n", v), -1;
	if (a->times >= FK_MAX_TIMES)
		return fprintf(stderr, "skintool fk: at most %d --time options\n", FK_MAX_TIMES), -1;
	a->time[a->times] = v;
	a->seconds[a->times++] = t;
	return 0;
}

static int fk_take(void *ctx, int id, const char *v)
{
	fk_args *a = ctx;
	char *end;
	switch (id) {
	case OPT_SKELETON: a->asf = v; return 0;
	case OPT_MOTION: a->amc = v; return 0;
	case OPT_TIME: return take_time(a, v);
	case OPT_CLIP: a->clip = v; return 0;
	case OPT_FPS:
		a->fps = strtod(v, &end);
		if (end == v || *end || !(a->fps >= 1.0 && a->fps <= 10000.0))
			return fprintf(stderr, "skintool fk: --fps expects a rate from 1 to 10000 Hz, got '%s'\n", v), -1;
		return 0;
	}
	if (cli_parse_long("--frame", v, &a->only) < 0)
		return -1;
	if (a->only < 0)
		return fprintf(stderr, "skintool fk: --frame expects a frame number (0 or more), got %ld\n", a->only), -1;
	return 0;
}

static int fk_file(void *ctx, const char *arg)
{
	fk_args *a = ctx;
	const char **slots[] = { &a->asf, &a->amc };
	return cli_take_positional("skintool fk", slots, 2, arg);
}

static const cli_command fk_command = {
	.prog = "skintool fk",
	.usage = "SKELETON.asf MOTION.amc [--frame=N | --time=SECONDS...]\n"
		 "  or:  skintool fk MOTION.bvh [--frame=N | --time=SECONDS...]\n"
		 "  or:  skintool fk SHOW.skn [--clip=NAME] [--frame=N | --time=SECONDS...]",
	.about = "Forward kinematics: prints CSV, a header then one row per bone per frame: frame,bone,x,y,z\n"
		 "(the bone's tip in world space, the skeleton's length unit) and qw,qx,qy,qz (its global\n"
		 "rotation, qw >= 0). The root comes first, then the bones in file order. With --time the first\n"
		 "column is time (as given) and the pose is the one skinplay shows at that clip time: each bone's\n"
		 "local rotation slerped on the shortest arc between the captured frames around it, translations\n"
		 "and `l` linear, then FK. Time 0 is the first frame; the rate is the BVH's Frame Time, or --fps.\n"
		 "Of an image (SHOW.skn), the same CSV of a packed clip as skinplay decodes it (its skeleton and\n"
		 "rate from the image): against the source's CSV it shows what packing changed.",
	.opts = { fk_opts },
	.take = fk_take,
	.positional = fk_file,
	.examples = (const cli_example[]){
		{ "The joints of frame 1 of a CMU walk",
		  "skintool fk 02.asf 02_01.amc --frame=1" },
		{ "The pose skinplay shows 0.5 s and 1 s into a BVH clip",
		  "skintool fk 131_01.bvh --time=0.5 --time=1" },
		{ "The same frame as packed in an image",
		  "skintool fk show.skn --clip=02_01 --frame=1" },
		{ NULL, NULL },
	},
};

/* A clip's frames one by one: from a motion file, or from an image. */
typedef struct fk_frames {
	motion_file m;
	play_image_source img;
	int is_image;
	const char *path;
} fk_frames;

static int frames_next(fk_frames *fr, amc_frame *f)
{
	if (!fr->is_image)
		return motion_file_next(&fr->m, f);
	skp_error err;
	int r = skp_clip_stream_next(&fr->img.stream, f, &err);
	if (r == SKP_CLIP_LOST) {
		cli_error(fr->path, &err);
		return -1;
	}
	return r;
}

static int print_frames(const skel *s, fk_frames *fr, long only)
{
	static amc_frame f;
	static skel_pose pose;
	char when[32];
	int r, found = 0;
	long first = -1, last = -1;
	while ((r = frames_next(fr, &f)) > 0) {
		if (first < 0) {
			first = f.number;
			printf("frame,bone,x,y,z,qw,qx,qy,qz\n"); /* not before a frame: no frames is an error */
		}
		last = f.number;
		if (only >= 0 && f.number != only)
			continue;
		fk_pose(s, f.value, &pose);
		snprintf(when, sizeof when, "%ld", f.number);
		if (print_pose(s, when, &pose) < 0) {
			r = -1;
			break;
		}
		found = 1;
		if (only >= 0)
			break;
	}
	if (r < 0)
		return 1;
	if (first < 0) {
		fprintf(stderr, "%s: no frames (a motion needs at least one frame after its header)\n", cli_shown(fr->path));
		return 1;
	}
	if (only >= 0 && !found) {
		fprintf(stderr, "%s: no frame %ld (the file has frames %ld..%ld)\n", fr->path, only, first, last);
		return 1;
	}
	return 0;
}

static int print_times(const skel *s, const char *path, play_source *src, const fk_args *a)
{
	static play_engine e;
	play_config cfg = { 1.0, 0, PLAY_ROOT_TRAVEL, 0 };
	skp_error err;
	play_init(&e, s, &cfg);
	if (play_start(&e, src, 0, &err) != SKP_OK) {
		cli_error(path, &err);
		return 1;
	}
	printf("time,bone,x,y,z,qw,qx,qy,qz\n");
	for (int i = 0; i < a->times; i++) {
		if (play_sample_at(&e, a->seconds[i], &err) != SKP_OK) {
			cli_error(path, &err);
			return 1;
		}
		if (print_pose(s, a->time[i], &e.pose) < 0)
			return 1;
	}
	return 0;
}

static int fk_motion(const skel *s, const char *amc, const fk_args *a)
{
	static clip_file clip;
	static fk_frames fr;
	play_source src;
	int rc;
	if (a->times) {
		if (clip_file_open(&clip, amc, s, a->fps, &src) < 0)
			return 1;
		rc = print_times(s, amc, &src, a);
		clip_file_close(&clip);
		return rc;
	}
	fr.is_image = 0;
	fr.path = amc;
	if (motion_file_open(&fr.m, amc, s) < 0)
		return 1;
	rc = print_frames(s, &fr, a->only);
	motion_file_close(&fr.m);
	return rc;
}

/* An image: by its name, or by the magic of its header block. */
static int is_image(const char *path)
{
	size_t n = strlen(path);
	if (n > 4 && !strcmp(path + n - 4, ".skn"))
		return 1;
	/* a FIFO (a pipe, <(...)) is read once, as motion: sniffing it would
	 * eat the bytes its reader needs */
	struct stat st;
	if (stat(path, &st) != 0 || !(S_ISREG(st.st_mode) || S_ISBLK(st.st_mode)))
		return 0;
	char head[SKP_IMAGE_BLOCK_HDR + 8];
	FILE *f = fopen(path, "rb");
	int yes = f && fread(head, 1, sizeof head, f) == sizeof head && !memcmp(head + SKP_IMAGE_BLOCK_HDR, SKP_IMAGE_MAGIC, 8);
	if (f)
		fclose(f);
	return yes;
}

static int fk_image(const char *path, const fk_args *a)
{
	static show_image img;
	static skel s;
	static fk_frames fr;
	skp_error err;
	if (a->fps > 0) {
		fprintf(stderr, "skintool fk: --fps: an image's clip has its own rate\n");
		return 1;
	}
	if (show_image_open(&img, path, &err) < 0 || skp_image_load_skel(&img.im, &s, &err) != SKP_OK) {
		cli_error(path, &err);
		show_image_close(&img);
		return 1;
	}
	int clip = a->clip ? skp_image_find_clip(&img.im, a->clip) : 0;
	int rc = 1;
	if (clip < 0 || img.im.clip_count == 0)
		fprintf(stderr, "%s: no clip %s\n", path, a->clip ? a->clip : "(the image holds none)");
	else if (play_image_source_open(&fr.img, &img.im, clip, &err) != SKP_OK)
		cli_error(path, &err);
	else if (a->times) {
		play_source src = play_image_source_get(&fr.img);
		rc = print_times(&s, path, &src, a);
	} else {
		fr.is_image = 1;
		fr.path = path;
		rc = print_frames(&s, &fr, a->only);
	}
	show_image_close(&img);
	return rc;
}

int cmd_fk(int argc, char **argv)
{
	static skel s;
	static fk_args args;
	memset(&args, 0, sizeof args);
	args.only = -1;
	int rc = cli_parse(&fk_command, &args, argc, argv, 0);
	if (rc != 0)
		return rc < 0;
	if (args.times && args.only >= 0) {
		fprintf(stderr, "skintool fk: --frame and --time: give one of them\n");
		return 1;
	}
	if (args.asf && !args.amc && is_image(args.asf))
		return fk_image(args.asf, &args);
	if (args.clip) {
		fprintf(stderr, "skintool fk: --clip is for an image (SHOW.skn)\n");
		return 1;
	}
	const char *asf = args.asf, *amc = args.amc;
	motion_bvh_slots(&asf, &amc, NULL);
	if (!asf || !amc)
		return -cli_missing(fk_command.prog, "SKELETON.asf MOTION.amc, MOTION.bvh or SHOW.skn");
	if (motion_load_skel(asf, &s) < 0)
		return 1;
	return fk_motion(&s, amc, &args);
}
