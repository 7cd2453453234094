/* skintool metrics SKELETON.asf MOTION.amc MESH.obj [bind options] [--algo LIST]
 * skintool metrics --scene twist|bend --angle DEG [--algo LIST]
 * Skinning artifacts as CSV, one row per frame and algorithm:
 *   frame,algo,volume_ratio,min_radius_ratio,max_radius_ratio
 * volume_ratio: enclosed volume over that of the mesh as bound; the radius
 * ratios: range over vertices of the distance to the nearest posed bone
 * over the same distance as bound (skin_metrics.h). The scene (skin_scene.h)
 * prints one row per algorithm, frame 0. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "clock.h"
#include "cli_bind_args.h"
#include "cli_common.h"
#include "measure.h"
#include "cli_skin.h"
#include "skin_metrics.h"
#include "skin_scene.h"
#include "skintool_cmds.h"
#include "text_tokens.h"

#define METRICS_USAGE "usage: skintool metrics SKELETON.asf MOTION.amc MESH.obj " BIND_ARGS_USAGE \
	" [--algo LIST]\n       skintool metrics --scene twist|bend --angle DEG [--algo LIST]\n" \
	"LIST: comma-separated lbs,dqbs,dqbs-fixed (default all three)\n"

typedef struct metrics_args {
	bind_args bind;
	const char *asf, *amc, *obj;
	int scene;                        /* skin_scene_kind, -1: a clip */
	double angle_deg;
	int have_angle;
	int algo_count;
	skin_algo algo[SKIN_ALGO_COUNT];
} metrics_args;

/* The bound body and the per-frame scratch. */
typedef struct metrics_run {
	cli_skin sk;
	measure_state meas;
	float pos[3 * SKP_MAX_VERTS], nrm[3 * SKP_MAX_VERTS];
} metrics_run;

static int parse_algos(metrics_args *a, const char *list)
{
	char buf[128];
	if (strlen(list) >= sizeof buf) {
		fprintf(stderr, "skintool metrics: --algo list too long\n");
		return -1;
	}
	strcpy(buf, list);
	a->algo_count = 0;
	for (char *name = buf, *end; name; name = end) {
		if ((end = strchr(name, ',')))
			*end++ = '\0';
		int k = skin_algo_parse(name);
		if (k < 0 || k >= SKIN_ALGO_COUNT) {
			fprintf(stderr, "skintool metrics: --algo: '%s' is not lbs, dqbs or dqbs-fixed\n", name);
			return -1;
		}
		if (a->algo_count == SKIN_ALGO_COUNT) {
			fprintf(stderr, "skintool metrics: --algo: at most %d algorithms\n", SKIN_ALGO_COUNT);
			return -1;
		}
		a->algo[a->algo_count++] = (skin_algo)k;
	}
	return 0;
}

static int parse_scene(metrics_args *a, const char *name)
{
	if ((a->scene = skin_scene_parse(name)) < 0) {
		fprintf(stderr, "skintool metrics: unknown --scene '%s' (twist or bend)\n", name);
		return -1;
	}
	return 0;
}

static int parse_angle(metrics_args *a, const char *text)
{
	if (tok_parse_double(text, &a->angle_deg) != 0 || !isfinite(a->angle_deg)) {
		fprintf(stderr, "skintool metrics: --angle expects a number of degrees, got '%s'\n", text);
		return -1;
	}
	a->have_angle = 1;
	return 0;
}

static int parse_one(metrics_args *a, int argc, char **argv, int *i)
{
	const char *opt = argv[*i], *val;
	int r = bind_args_parse(&a->bind, argc, argv, i);
	if (r != 0)
		return r < 0 ? -1 : 0;
	if (strcmp(opt, "--algo") == 0)
		return (val = cli_option_value("skintool metrics", opt, argc, argv, i)) ? parse_algos(a, val) : -1;
	if (strcmp(opt, "--scene") == 0)
		return (val = cli_option_value("skintool metrics", opt, argc, argv, i)) ? parse_scene(a, val) : -1;
	if (strcmp(opt, "--angle") == 0)
		return (val = cli_option_value("skintool metrics", opt, argc, argv, i)) ? parse_angle(a, val) : -1;
	if (opt[0] == '-' && opt[1]) {
		fprintf(stderr, "skintool metrics: unknown option '%s'\n", opt);
		return -1;
	}
	const char **const slots[] = { &a->asf, &a->amc, &a->obj };
	return cli_take_positional("skintool metrics", slots, 3, opt);
}

static int check_args(metrics_args *a)
{
	cli_bvh_slots(&a->asf, &a->amc, &a->obj);
	int clip = a->asf || a->amc || a->obj;
	if (a->scene >= 0 && (clip || !a->have_angle)) {
		fprintf(stderr, "skintool metrics: --scene takes --angle DEG and no files\n");
		return -1;
	}
	if (a->scene < 0 && (!a->asf || !a->amc || !a->obj || a->have_angle)) {
		fputs(METRICS_USAGE, stderr);
		return -1;
	}
	return 0;
}

static int parse_args(metrics_args *a, int argc, char **argv)
{
	memset(a, 0, sizeof *a);
	bind_args_init(&a->bind);
	a->scene = -1;
	a->algo_count = SKIN_ALGO_COUNT;
	for (int k = 0; k < SKIN_ALGO_COUNT; k++)
		a->algo[k] = (skin_algo)k;
	for (int i = 0; i < argc; i++)
		if (parse_one(a, argc, argv, &i) < 0)
			return -1;
	return check_args(a);
}

static int start(metrics_run *r, const skel *s, const skel_pose *bind, const mesh *m,
		 const skin_weights *w, const char *what)
{
	if (cli_skin_init(&r->sk, s, bind, m, w, what) < 0 ||
	    measure_init(&r->meas, m, bind, s->count, what) < 0)
		return -1;
	printf("frame,algo,volume_ratio,min_radius_ratio,max_radius_ratio\n");
	return 0;
}

/* One row per algorithm for the pose r->sk holds. */
static void metrics_pose(metrics_run *r, const metrics_args *a, long frame)
{
	measure_pose(&r->meas, &r->sk.pose);
	for (int k = 0; k < a->algo_count; k++) {
		cli_skin_run(&r->sk, a->algo[k], r->pos, r->nrm);
		measure_row row = measure_skinned(&r->meas, r->pos, NULL);
		printf("%ld,%s,%.6f,%.6f,%.6f\n", frame, skin_algo_name(a->algo[k]),
		       row.volume_ratio, (double)row.radius.min, (double)row.radius.max);
	}
}

static int run_scene(metrics_run *r, const metrics_args *a)
{
	static skin_scene sc;
	static skel_pose pose;
	skin_scene_build(&sc);
	if (start(r, &sc.skel, &sc.bind, &sc.mesh, &sc.weights, "scene") < 0)
		return -1;
	float rad = (float)(a->angle_deg * (3.14159265358979323846 / 180.0));
	skin_scene_pose(&sc, (skin_scene_kind)a->scene, rad, &pose);
	cli_skin_pose(&r->sk, &pose);
	metrics_pose(r, a, 0);
	return 0;
}

static int run_clip(metrics_run *r, const metrics_args *a)
{
	static bound_body body;
	static cli_motion mo;
	static amc_frame f;
	if (bind_args_load(&a->bind, a->asf, a->obj, &body) < 0 ||
	    start(r, &body.skel, &body.pose, &body.mesh, &body.weights, a->obj) < 0 ||
	    cli_motion_open(&mo, a->amc, &body.skel) < 0)
		return -1;
	uint64_t t0 = clock_now_ns();
	long frames = 0;
	int rc;
	while ((rc = cli_motion_next(&mo, &f)) > 0) {
		cli_skin_frame(&r->sk, f.value);
		metrics_pose(r, a, f.number);
		frames++;
	}
	cli_motion_close(&mo);
	fprintf(stderr, "%s: %ld frames x %d algorithms, %d vertices: %.3f s\n", a->amc, frames,
		a->algo_count, body.mesh.vert_count, (double)(clock_now_ns() - t0) / 1e9);
	return rc < 0 ? -1 : 0;
}

int cmd_metrics(int argc, char **argv)
{
	static metrics_args a;
	static metrics_run r;

	if (parse_args(&a, argc, argv) < 0)
		return 1;
	int rc = a.scene >= 0 ? run_scene(&r, &a) : run_clip(&r, &a);
	return rc < 0 ? 1 : 0;
}
