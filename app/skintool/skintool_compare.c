/* skintool compare SKELETON.asf MOTION.amc [--mesh MESH.obj [bind options]] -o DIR
 *     [--renders N]
 * The paper's experiment on any clip: skins every frame with LBS, DQBS and
 * fixed-point DQBS, measures them as `skintool metrics` does (measure.h)
 * plus per joint region (compare_measure.c), and writes DIR/index.html (a
 * static page), DIR/metrics.csv, charts of the series over time, the
 * synthetic twist and bend scenes next to their analytic values, and LBS |
 * DQBS renders of the frames where LBS collapses most compared with DQBS
 * (compare_output.c, report/). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli_common.h"
#include "clock.h"
#include "compare.h"
#include "skintool_cmds.h"

#define COMPARE_USAGE "usage: skintool compare SKELETON.asf MOTION.amc [--mesh MESH.obj " \
	BIND_ARGS_USAGE "] -o DIR [--renders N]\n"

const char *const compare_algo_label[NALGO] = { "LBS", "DQBS", "DQBS fixed" };

static int parse_one(compare_args *a, int argc, char **argv, int *i)
{
	const char *opt = argv[*i];
	int r = bind_args_parse(&a->bind, argc, argv, i);
	if (r != 0)
		return r < 0 ? -1 : 0;
	if (!strcmp(opt, "--mesh") || !strcmp(opt, "-o") || !strcmp(opt, "--renders")) {
		if (*i + 1 >= argc) {
			fprintf(stderr, "skintool compare: %s needs a value\n", opt);
			return -1;
		}
		const char *val = argv[++*i];
		if (!strcmp(opt, "--mesh"))
			a->mesh = val;
		else if (!strcmp(opt, "-o"))
			a->out = val;
		else if (cli_parse_long(opt, val, &a->renders) < 0)
			return -1;
		return 0;
	}
	if (opt[0] == '-' && opt[1]) {
		fprintf(stderr, "skintool compare: unknown option '%s'\n", opt);
		return -1;
	}
	const char **slot = !a->asf ? &a->asf : !a->amc ? &a->amc : NULL;
	if (!slot) {
		fprintf(stderr, "skintool compare: unexpected argument '%s'\n", opt);
		return -1;
	}
	*slot = opt;
	return 0;
}

static int parse_args(compare_args *a, int argc, char **argv)
{
	memset(a, 0, sizeof *a);
	bind_args_init(&a->bind);
	a->renders = 4;
	for (int i = 0; i < argc; i++)
		if (parse_one(a, argc, argv, &i) < 0)
			return -1;
	cli_bvh_slots(&a->asf, &a->amc, NULL);
	if (!a->asf || !a->amc || !a->out) {
		fputs(COMPARE_USAGE, stderr);
		return -1;
	}
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

static int make_dir(const char *dir)
{
	if (mkdir(dir, 0755) != 0 && errno != EEXIST) {
		fprintf(stderr, "skintool compare: %s: %s\n", dir, strerror(errno));
		return -1;
	}
	return 0;
}

int cmd_compare(int argc, char **argv)
{
	static compare_args a;
	static compare_run c;
	static char clip[256];
	if (parse_args(&a, argc, argv) < 0 || make_dir(a.out) < 0)
		return 1;
	uint64_t t0 = clock_now_ns();
	memset(&c.rep, 0, sizeof c.rep);
	snprintf(clip, sizeof clip, "%s", cli_basename(a.amc));
	char *dot = strrchr(clip, '.');
	if (dot)
		*dot = '\0';
	c.rep.asf = a.asf;
	c.rep.amc = a.amc;
	c.rep.clip = clip;
	if (compare_measure_scenes(&c) < 0 || compare_load_clip(&c, &a) < 0 || compare_measure_clip(&c, &a) < 0 ||
	    compare_other_weights(&c, &a) < 0)
		return 1;
	uint64_t t1 = clock_now_ns();
	compare_pick_stills(&c, (int)a.renders);
	if (compare_explain_volume(&c, &a) < 0 || compare_render_stills(&c, &a) < 0 ||
	    compare_write_charts(&c, a.out) < 0 || report_write_html(&c.rep, a.out) < 0)
		return 1;
	uint64_t t2 = clock_now_ns();
	fprintf(stderr, "%s: %ld frames x 3 algorithms, %d vertices: measured in %.2f s, renders, "
		"charts and page %.2f s, total %.2f s -> %s/index.html\n", a.amc, c.rep.frames,
		c.rep.vert_count, (double)(t1 - t0) * 1e-9, (double)(t2 - t1) * 1e-9,
		(double)(t2 - t0) * 1e-9, a.out);
	return 0;
}
