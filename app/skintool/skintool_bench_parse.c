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
#include "cli_common.h"
#include "clock.h"
#include "skintool_cmds.h"

#define BENCH_PARSE_USAGE "usage: skintool bench-parse [SKELETON.asf] MOTION.amc|MOTION.bvh ... [--runs N]\n"

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
		if ((out->frames = cli_motion_count(path, s)) < 0)
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
	long runs = 5;
	int have_asf = 0, measured = 0;
	parse_figure base = { 0, 0, 0 };
	for (int i = 0; i < argc; i++)
		if (!strcmp(argv[i], "--runs") && (i + 1 >= argc || cli_parse_long("--runs", argv[++i], &runs) < 0 || runs < 1))
			return fprintf(stderr, "%s", BENCH_PARSE_USAGE), 1;
	printf("file,format,bytes,frames,MB_per_s,frames_per_s,vs_first\n");
	for (int i = 0; i < argc; i++) {
		const char *p = argv[i];
		size_t n = strlen(p);
		if (!strcmp(p, "--runs")) {
			i++;
			continue;
		}
		if (n > 4 && !strcmp(p + n - 4, ".asf")) {
			if (cli_load_skel(p, &asf) < 0)
				return 1;
			have_asf = 1;
			continue;
		}
		int bvh = bvh_is_path(p);
		if (!bvh && !have_asf)
			return fprintf(stderr, "skintool bench-parse: %s: give its ASF before it\n", p), 1;
		if (bvh && cli_load_skel(p, &own) < 0)
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
		return fprintf(stderr, "%s", BENCH_PARSE_USAGE), 1;
	return 0;
}
