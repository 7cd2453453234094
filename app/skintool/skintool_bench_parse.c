/* skintool bench-parse [SKELETON.asf] MOTION.amc|MOTION.bvh ... [--runs N]
 * Parse throughput of motion files through the streaming readers the
 * programs use (file reader, line reader, AMC or BVH frames; no FK): MB/s
 * and frames/s, best of N runs, each file against the first one measured
 * in the same run. An ASF applies to the AMC files after it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bvh.h"
#include "cli_args.h"
#include "cli_error.h"
#include "cli_opts.h"
#include "clock.h"
#include "motion_file.h"
#include "skintool_cmds.h"

#define MAX_FILES 64

typedef struct bench_parse_args {
	long runs;
	int count;
	const char *file[MAX_FILES];
} bench_parse_args;

static const cli_opt bench_parse_opts[] = {
	{ "runs", 0, "N", 1, "time each file N times and keep the best (default 5)" },
	{ NULL, 0, NULL, 0, NULL },
};

static int bp_take(void *ctx, int id, const char *v)
{
	bench_parse_args *a = ctx;
	(void)id;
	if (cli_parse_long("--runs", v, &a->runs) < 0)
		return -1;
	if (a->runs < 1)
		return fprintf(stderr, "skintool bench-parse: --runs expects 1 or more, got %ld\n", a->runs), -1;
	return 0;
}

static int bp_file(void *ctx, const char *arg)
{
	bench_parse_args *a = ctx;
	if (a->count == MAX_FILES)
		return fprintf(stderr, "skintool bench-parse: more than %d files\n", MAX_FILES), -1;
	a->file[a->count++] = arg;
	return 0;
}

static const cli_command bench_parse_command = {
	.prog = "skintool bench-parse",
	.usage = "[SKELETON.asf] MOTION.amc|MOTION.bvh... [--runs=N]",
	.about = "Motion parse throughput: streams each motion file through the parser (an AMC against the\n"
		 "ASF named before it, a BVH on its own) and prints CSV file,format,bytes,frames,MB_per_s,\n"
		 "frames_per_s,vs_first (the ratio to the first file measured, in the same run).",
	.opts = { bench_parse_opts },
	.take = bp_take,
	.positional = bp_file,
	.examples = (const cli_example[]){
		{ "AMC against the same motion as BVH",
		  "skintool bench-parse 135.asf 135_06.amc 135_06.bvh --runs=15" },
		{ NULL, NULL },
	},
};

typedef struct parse_figure {
	double mb_s, frames_s;
	long frames;
} parse_figure;

static int measure(const char *path, const skel *s, long runs, parse_figure *out)
{
	struct stat st;
	if (stat(path, &st) != 0) {
		fprintf(stderr, "%s: cannot open\n", path);
		return -1;
	}
	uint64_t best = UINT64_MAX;
	for (long i = 0; i < runs; i++) {
		uint64_t t0 = clock_now_ns();
		if ((out->frames = motion_file_count(path, s)) < 0)
			return -1;
		uint64_t ns = clock_now_ns() - t0;
		best = ns < best ? ns : best;
	}
	double secs = (double)best * 1e-9;
	out->mb_s = (double)st.st_size / 1e6 / secs;
	out->frames_s = (double)out->frames / secs;
	return 0;
}

int cmd_bench_parse(int argc, char **argv)
{
	static skel asf, own;
	static bench_parse_args a;
	a.runs = 5;
	a.count = 0;
	int rc = cli_parse(&bench_parse_command, &a, argc, argv, 0);
	if (rc != 0)
		return rc < 0;
	long runs = a.runs;
	int have_asf = 0, measured = 0;
	parse_figure base = { 0, 0, 0 };
	printf("file,format,bytes,frames,MB_per_s,frames_per_s,vs_first\n");
	for (int i = 0; i < a.count; i++) {
		const char *p = a.file[i];
		size_t n = strlen(p);
		if (n > 4 && !strcmp(p + n - 4, ".asf")) {
			if (motion_load_skel(p, &asf) < 0)
				return 1;
			have_asf = 1;
			continue;
		}
		int bvh = bvh_is_path(p);
		if (!bvh && !have_asf)
			return fprintf(stderr, "skintool bench-parse: %s: give its ASF before it\n", p), 1;
		if (bvh && motion_load_skel(p, &own) < 0)
			return 1;
		parse_figure f = { 0, 0, 0 };
		struct stat st;
		if (measure(p, bvh ? &own : &asf, runs, &f) < 0 || stat(p, &st) != 0)
			return 1;
		if (!measured++)
			base = f;
		printf("%s,%s,%lld,%ld,%.1f,%.0f,%.2f\n", cli_basename(p), bvh ? "bvh" : "amc", (long long)st.st_size,
		       f.frames, f.mb_s, f.frames_s, f.mb_s / base.mb_s);
	}
	if (!measured)
		return -cli_missing(bench_parse_command.prog, "a motion file");
	return 0;
}
