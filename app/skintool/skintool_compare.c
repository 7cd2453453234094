/* skintool compare SKELETON.asf MOTION.amc [--mesh MESH.obj [bind options]] -o DIR
 *     [--renders N]
 * The paper's experiment on any clip: skins every frame with LBS, DQBS and
 * fixed-point DQBS, measures them as `skintool metrics` does (measure.h)
 * plus per joint region (compare_measure.c), and writes DIR/index.html (a
 * static page), DIR/metrics.csv, charts of the series over time, the
 * synthetic twist and bend scenes next to their analytic values with their
 * pictures, and LBS | DQBS pictures of the frames where LBS collapses most
 * compared with DQBS: the whole body, the close-up of where the two part
 * most, the difference view (compare_output.c, report/). */
#define _GNU_SOURCE /* nftw */
#include <errno.h>
#include <ftw.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli_args.h"
#include "cli_error.h"
#include "motion_file.h"
#include "cli_progress.h"
#include "cli_quiet.h"
#include "clock.h"
#include "compare.h"
#include "skintool_cmds.h"
#include "tool_args.h"
#include "tool_state.h"

enum { OPT_RENDERS = 1 };

static const cli_opt compare_cmd_opts[] = {
	{ "renders", 0, "N", OPT_RENDERS, "LBS | DQBS pictures of each joint region's worst frame, then the worst left (0..8, default 4; 0: no pictures at all, the scenes' neither)" },
	{ NULL, 0, NULL, 0, NULL },
};

static const cli_opt compare_out_opt[] = {
	{ "output", 'o', "DIR", TOOL_OPT_OUTPUT, "the report's folder (created; removed again when the command fails)" },
	{ NULL, 0, NULL, 0, NULL },
};

static int compare_take(void *ctx, int id, const char *v)
{
	compare_args *a = ctx;
	if (BIND_OPT_ID(id))
		return bind_args_take(&a->bind, "skintool compare", id, v);
	switch (id) {
	case TOOL_OPT_SKELETON: a->asf = v; return 0;
	case TOOL_OPT_MOTION: a->amc = v; return 0;
	case TOOL_OPT_MESH: a->mesh = v; return 0;
	case TOOL_OPT_OUTPUT: a->out = v; return 0;
	}
	return cli_parse_long("--renders", v, &a->renders);
}

static int compare_file(void *ctx, const char *arg)
{
	compare_args *a = ctx;
	const char **slots[] = { &a->asf, &a->amc };
	return cli_take_positional("skintool compare", slots, 2, arg);
}

static const cli_command compare_command = {
	.prog = "skintool compare",
	.usage = "SKELETON MOTION [--mesh=MESH [OPTION]...] -o DIR",
	.about = "The paper's experiment on any clip: skins every frame with LBS, DQBS and fixed-point DQBS,\n"
		 "measures volume and radius ratios overall and per joint region, and writes DIR/index.html\n"
		 "(a static page), DIR/metrics.csv, charts, the twist and bend scenes with their pictures, and\n"
		 "pictures of the frames where LBS keeps least of a joint region against DQBS: the whole body,\n"
		 "a close-up of where LBS and DQBS part most, and the difference view. A rigged mesh is measured\n"
		 "with its own and with computed weights, side by side.",
	.opts = { tool_opt_skeleton, tool_opt_motion, tool_opt_mesh, compare_out_opt, compare_cmd_opts, bind_opts },
	.take = compare_take,
	.positional = compare_file,
	.examples = (const cli_example[]){
		{ "The LBS | DQBS report of a clip on the generated body",
		  "skintool compare 02.asf 02_01.amc -o report" },
		{ "The same on a rigged body, its own weights beside computed ones",
		  "skintool compare 02.asf 02_01.amc --mesh=male_base_mesh.glb --weights=mesh -o report" },
		{ NULL, NULL },
	},
};

static int parse_args(compare_args *a, int argc, char **argv)
{
	memset(a, 0, sizeof *a);
	bind_args_init(&a->bind);
	a->renders = 4;
	int rc = cli_parse(&compare_command, a, argc, argv, 0);
	if (rc != 0)
		return rc;
	motion_bvh_slots(&a->asf, &a->amc, NULL);
	if (!a->asf || !a->amc || !a->out) {
		return cli_missing(compare_command.prog, "SKELETON MOTION and -o DIR");
	}
	a->bind.gate_motion = &a->amc;
	a->bind.gate_motion_count = 1;
	if (a->renders < 0 || a->renders > REPORT_MAX_STILLS) {
		fprintf(stderr, "skintool compare: --renders takes 0 to %d, got %ld\n", REPORT_MAX_STILLS,
			a->renders);
		return -1;
	}
	if (!a->mesh && (a->bind.group || a->bind.fit || a->bind.pose_path)) {
		fprintf(stderr, "skintool compare: --group, --fit and --bind-pose need --mesh\n");
		return -1;
	}
	return 0;
}

/* 1 when the folder was made here (and goes again if the command fails),
 * 0 when it was there, -1 after reporting. */
static int make_dir(const char *dir)
{
	if (mkdir(dir, 0755) == 0)
		return 1;
	if (errno == EEXIST)
		return 0;
	fprintf(stderr, "skintool compare: %s: %s\n", dir, strerror(errno));
	return -1;
}

static int remove_entry(const char *path, const struct stat *st, int type, struct FTW *ftw)
{
	(void)st, (void)type, (void)ftw;
	return remove(path);
}

/* A failed run leaves no half-written report behind in a folder it made. */
static int fail(const char *dir, int made)
{
	if (made && nftw(dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS) == 0)
		fprintf(stderr, "skintool compare: %s removed (the report was not finished)\n", dir);
	return 1;
}

int cmd_compare(int argc, char **argv)
{
	static compare_args a;
	TOOL_STATE(compare_run, c);
	static char clip[256];
	uint64_t t_start = clock_now_ns();
	int rc = parse_args(&a, argc, argv);
	if (rc != 0)
		return rc < 0;
	int made = make_dir(a.out);
	if (made < 0)
		return 1;
	memset(&c->rep, 0, sizeof c->rep);
	snprintf(clip, sizeof clip, "%s", cli_basename(a.amc));
	char *dot = strrchr(clip, '.');
	if (dot)
		*dot = '\0';
	c->rep.asf = a.asf;
	c->rep.amc = a.amc;
	c->rep.clip = clip;
	if (compare_load_clip(c, &a) < 0 || compare_measure_clip(c, &a) < 0 || compare_other_weights(c, &a) < 0)
		return fail(a.out, made);
	uint64_t t1 = clock_now_ns();
	compare_pick_stills(c, (int)a.renders);
	/* the scenes last (bad input is refused before any work), pictured
	 * while c->sk still holds them */
	if (compare_explain_volume(c, &a) < 0 || compare_render_stills(c, &a) < 0 ||
	    compare_write_charts(c, a.out) < 0 || compare_measure_scenes(c) < 0 || compare_render_scenes(c, &a) < 0)
		return fail(a.out, made);
	/* the page and the last line give the same total: taken once, before
	 * the page (which takes a millisecond) */
	uint64_t t2 = clock_now_ns();
	c->rep.total_seconds = (double)(t2 - t_start) * 1e-9;
	if (report_write_html(&c->rep, a.out) < 0)
		return fail(a.out, made);
	fprintf(cli_note(), "%s: %ld frames x 3 algorithms, %d vertices: measured in %.2f s, renders, "
		"charts and page %.2f s, total %.2f s -> %s/index.html\n", a.amc, c->rep.frames, c->rep.vert_count,
		c->rep.seconds, (double)(t2 - t1) * 1e-9, c->rep.total_seconds, a.out);
	return 0;
}
