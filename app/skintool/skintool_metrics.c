/* skintool metrics SKELETON.asf MOTION.amc MESH.obj [bind options] [--algo LIST]
 * skintool metrics --scene twist|bend --angle DEG [--algo LIST]
 * Skinning artifacts as CSV, one row per frame and algorithm:
 *   frame,algo,volume_ratio,min_radius_ratio,max_radius_ratio
 * volume_ratio: enclosed volume over that of the mesh as bound; the radius
 * ratios: range over vertices of the distance to the nearest posed bone
 * over the same distance as bound (metrics.h). The scene (scene.h)
 * prints one row per algorithm, frame 0. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "clock.h"
#include "cli_bind_args.h"
#include "cli_error.h"
#include "cli_progress.h"
#include "measure.h"
#include "motion_file.h"
#include "runtime_body.h"
#include "runtime_skin.h"
#include "metrics.h"
#include "scene.h"
#include "rig_load.h"
#include "setup_bind.h"
#include "skintool_cmds.h"
#include "tool_args.h"
#include "text_tokens.h"
#include "tool_state.h"

typedef struct metrics_args {
	tool_common c;
	int scene;                        /* scene_kind, -1: a clip */
	double angle_deg;
	int have_angle;
	int algo_count;
	skin_algo algo[SKIN_ALGO_COUNT];
} metrics_args;

/* The bound body and the per-frame scratch. */
typedef struct metrics_run {
	runtime_skin sk;
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
	if ((a->scene = scene_parse(name)) < 0) {
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

enum { OPT_ALGO = 1, OPT_SCENE, OPT_ANGLE };

static const cli_opt metrics_cmd_opts[] = {
	{ "algo", 0, "LIST", OPT_ALGO, "comma-separated lbs,dqbs,dqbs-fixed (default all three)" },
	{ "scene", 0, "twist|bend", OPT_SCENE, "a synthetic scene instead of a clip (no files; needs --angle)" },
	{ "angle", 0, "DEG", OPT_ANGLE, "the scene's twist or bend angle in degrees" },
	{ NULL, 0, NULL, 0, NULL },
};

static int metrics_take(void *ctx, int id, const char *v)
{
	metrics_args *a = ctx;
	int r = tool_common_take(&a->c, id, v);
	if (r <= 0)
		return r;
	return id == OPT_ALGO ? parse_algos(a, v) : id == OPT_SCENE ? parse_scene(a, v) : parse_angle(a, v);
}

static const cli_command metrics_command = {
	.prog = "skintool metrics",
	.usage = "SKELETON MOTION MESH [OPTION]...\n  or:  skintool metrics --scene=twist|bend --angle=DEG [--algo=LIST]",
	.about = "Skinning artifacts as CSV on stdout, one row per frame and algorithm:\n"
		 "frame,algo,volume_ratio,min_radius_ratio,max_radius_ratio. volume_ratio: the enclosed volume\n"
		 "over the volume as bound; the radius ratios: the range over vertices of the distance to the\n"
		 "nearest posed bone over the same distance as bound. A scene prints one row per algorithm.",
	.opts = { tool_opt_skeleton, tool_opt_motion, tool_opt_mesh, metrics_cmd_opts, bind_opts },
	.take = metrics_take,
	.positional = tool_files_skel_motion_mesh,
	.examples = (const cli_example[]){
		{ "Volume and radius ratios of every frame, LBS and DQBS",
		  "skintool metrics 02.asf 02_01.amc body.obj --algo=lbs,dqbs" },
		{ "The twist scene at 90 degrees",
		  "skintool metrics --scene=twist --angle=90" },
		{ NULL, NULL },
	},
};

static int check_args(metrics_args *a)
{
	motion_bvh_slots(&a->c.asf, &a->c.amc, &a->c.mesh);
	int clip = a->c.asf || a->c.amc || a->c.mesh;
	if (a->scene >= 0 && (clip || !a->have_angle)) {
		fprintf(stderr, "skintool metrics: --scene takes --angle DEG and no files\n");
		return -1;
	}
	if (a->scene < 0 && (!a->c.asf || !a->c.amc || !a->c.mesh || a->have_angle))
		return -tool_missing(&a->c, "SKELETON MOTION MESH, or --scene with --angle");
	return 0;
}

static int parse_args(metrics_args *a, int argc, char **argv)
{
	tool_common_init(&a->c, metrics_command.prog);
	a->scene = -1;
	a->have_angle = 0;
	a->algo_count = SKIN_ALGO_COUNT;
	for (int k = 0; k < SKIN_ALGO_COUNT; k++)
		a->algo[k] = (skin_algo)k;
	int rc = cli_parse(&metrics_command, a, argc, argv, 0);
	return rc != 0 ? rc : check_args(a);
}

static int start(metrics_run *r, const skel *s, const skel_pose *bind, const mesh *m,
		 const skin_weights *w, const char *what)
{
	if (runtime_skin_init(&r->sk, s, bind, m, w, what) < 0 ||
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
		runtime_skin_run(&r->sk, a->algo[k], r->pos, r->nrm);
		measure_row row = measure_skinned(&r->meas, r->pos, NULL);
		printf("%ld,%s,%.6f,%.6f,%.6f\n", frame, skin_algo_name(a->algo[k]),
		       row.volume_ratio, (double)row.radius.min, (double)row.radius.max);
	}
}

static int run_scene(metrics_run *r, const metrics_args *a)
{
	TOOL_STATE(scene_rig, sc);
	static skel_pose pose;
	scene_build(sc);
	if (start(r, &sc->skel, &sc->bind, &sc->mesh, &sc->weights, "scene") < 0)
		return -1;
	float rad = (float)(a->angle_deg * (3.14159265358979323846 / 180.0));
	scene_pose(sc, (scene_kind)a->scene, rad, &pose);
	runtime_skin_pose(&r->sk, &pose);
	metrics_pose(r, a, 0);
	return 0;
}

static int run_clip(metrics_run *r, metrics_args *a)
{
	TOOL_STATE(bound_body, body);
	static motion_file mo;
	static amc_frame f;
	a->c.bind.gate_motion = &a->c.amc;
	a->c.bind.gate_motion_count = 1;
	if (rig_bind_load(&a->c.bind, a->c.asf, a->c.mesh, body) < 0 ||
	    start(r, &body->skel, &body->pose, &body->mesh, &body->weights, a->c.mesh) < 0 ||
	    motion_file_open(&mo, a->c.amc, &body->skel) < 0)
		return -1;
	static cli_progress pr;
	static char what[300], extra[96];
	long total = motion_file_count(a->c.amc, &body->skel);
	if (total < 0)
		return -1;
	snprintf(what, sizeof what, "metrics %s", cli_basename(a->c.amc));
	cli_progress_start(&pr, what, "frames", total);
	long frames = 0;
	int rc;
	while ((rc = motion_file_next(&mo, &f)) > 0) {
		runtime_skin_frame(&r->sk, f.value);
		metrics_pose(r, a, f.number);
		cli_progress_step(&pr, ++frames);
	}
	motion_file_close(&mo);
	snprintf(extra, sizeof extra, ", %d algorithms, %d vertices", a->algo_count, body->mesh.vert_count);
	cli_progress_end(&pr, extra);
	return rc < 0 ? -1 : 0;
}

int cmd_metrics(int argc, char **argv)
{
	static metrics_args a;
	TOOL_STATE(metrics_run, r);

	int rc = parse_args(&a, argc, argv);
	if (rc != 0)
		return rc < 0;
	rc = a.scene >= 0 ? run_scene(r, &a) : run_clip(r, &a);
	return rc < 0 ? 1 : 0;
}
