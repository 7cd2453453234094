/* skintool bench [--verts N] [--threads T] [--rounds R] [--ozz PROGRAM]: skinning throughput per
 * algorithm on a synthetic mesh, next to the memory-bandwidth bound for the
 * bytes each vertex reads and writes, measured in the same run. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_closeup.h"
#include "clock.h"
#include "cli_args.h"
#include "cli_opts.h"
#include "cli_progress.h"
#include "motion_file.h"
#include "runtime_body.h"
#include "runtime_skin.h"
#include "rig_load.h"
#include "setup_bind.h"
#include "skin.h"
#include "skin_compact.h"
#include "skintool_cmds.h"
#include "tool_anchor.h"
#include "tool_args.h"
#include "workers.h"
#include "tool_state.h"

#define BENCH_BONES 31

/* The kernels timed: each algorithm over the float streams (the fixed
 * one over its own), then LBS and DQBS over the compact streams. */
typedef struct kernel {
	const char *name;
	skin_algo algo;
	int compact;
	int bytes;               /* read and written per vertex */
} kernel;

/* bytes per vertex: positions, normals, 4 bone indices and 4 weights
 * read, positions and normals written (skin_compact.h for its own) */
#define BYTES_FLOAT (24 + 8 + 16 + 24)
#define BYTES_FIXED (24 + 8 + 8 + 24)

static const kernel kernels[] = {
	{ "lbs", SKIN_LBS, 0, BYTES_FLOAT },
	{ "dqbs", SKIN_DQBS, 0, BYTES_FLOAT },
	{ "dqbs-fixed", SKIN_DQBS_FIXED, 0, BYTES_FIXED },
	{ "lbs-compact", SKIN_LBS, 1, SKIN_COMPACT_BYTES_MOVED },
	{ "dqbs-compact", SKIN_DQBS, 1, SKIN_COMPACT_BYTES_MOVED },
};
enum { K_LBS, K_DQBS, K_FIXED, K_LBS_COMPACT, K_DQBS_COMPACT, K_COUNT };

typedef struct bench {
	skin_soa soa;
	skin_compact compact;
	skin_bones bones;
	skin_out out;
	const kernel *k;
} bench;

static unsigned long long rng = 0x9e3779b97f4a7c15ull;

static float frand(void)
{
	rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
	return (float)((rng >> 40) * (1.0 / 16777216.0));
}

static quat random_quat(void)
{
	quat q = { frand() - 0.5f, frand() - 0.5f, frand() - 0.5f, frand() - 0.5f };
	return quat_normalize(q);
}

static int by_weight_desc(const void *a, const void *b)
{
	float x = *(const float *)a, y = *(const float *)b;
	return (x < y) - (x > y);
}

static void *alloc_aligned(size_t bytes)
{
	return aligned_alloc(SKIN_ALIGN, (bytes + SKIN_ALIGN - 1) / SKIN_ALIGN * SKIN_ALIGN);
}

/* The kernels' outputs for n vertices in b->out (freed by free_streams). */
static int alloc_outputs(bench *b, int n)
{
	float *outp = alloc_aligned(sizeof(float) * 3 * (size_t)(n + SKIN_LANES) * 2);
	int32_t *outf = alloc_aligned(sizeof(int32_t) * 3 * (size_t)(n + SKIN_LANES) * 2);
	int16_t *out16 = alloc_aligned(sizeof(int16_t) * 3 * (size_t)(n + SKIN_LANES));
	b->out.pos = outp;
	b->out.nrm = outp ? outp + 3 * (size_t)(n + SKIN_LANES) : NULL;
	b->out.fpos = outf;
	b->out.fnrm = outf ? outf + 3 * (size_t)(n + SKIN_LANES) : NULL;
	b->out.nrm16 = out16;
	return outp && outf && out16 ? 0 : -1;
}

/* The float and compact streams of n vertices in blocks[0..1], and the
 * outputs (freed by free_streams). */
static int alloc_streams(bench *b, int n, void *block[2])
{
	block[0] = alloc_aligned(skin_soa_bytes(n));
	block[1] = alloc_aligned(skin_compact_bytes(n));
	if (alloc_outputs(b, n) < 0 || !block[0] || !block[1])
		return -1;
	skin_soa_attach(&b->soa, block[0], n);
	skin_compact_attach(&b->compact, block[1], n);
	return 0;
}

static void free_streams(bench *b, void *block[2])
{
	free(block[0]);
	free(block[1]);
	free(b->out.pos);
	free(b->out.fpos);
	free(b->out.nrm16);
}

/* A mesh of n vertices in a 2-unit box, 4 influences on random bones, in
 * float and compact streams. */
static void make_scene(bench *b)
{
	for (int v = 0; v < b->soa.padded; v++) {
		vec3 p = vec3_make(2 * frand() - 1, 2 * frand() - 1, 2 * frand() - 1);
		vec3 nn = vec3_normalize(vec3_make(frand() - 0.5f, frand() - 0.5f, frand() - 0.5f));
		float w[4], sum = 0;
		for (int k = 0; k < 4; k++)
			sum += w[k] = 0.05f + frand();
		/* largest first, as skin_soa_load leaves them (the DQBS pivot) */
		qsort(w, 4, sizeof w[0], by_weight_desc);
		for (int k = 0; k < 4; k++) {
			b->soa.bone[k][v] = (uint16_t)(frand() * BENCH_BONES) % BENCH_BONES;
			b->soa.weight[k][v] = w[k] / sum;
		}
		b->soa.px[v] = p.x; b->soa.py[v] = p.y; b->soa.pz[v] = p.z;
		b->soa.nx[v] = nn.x; b->soa.ny[v] = nn.y; b->soa.nz[v] = nn.z;
		b->soa.fpx[v] = (fx_pos)(p.x * FX_POS_ONE); b->soa.fpy[v] = (fx_pos)(p.y * FX_POS_ONE);
		b->soa.fpz[v] = (fx_pos)(p.z * FX_POS_ONE);
		b->soa.fnx[v] = (fx_q30)(nn.x * FX_Q30_ONE); b->soa.fny[v] = (fx_q30)(nn.y * FX_Q30_ONE);
		b->soa.fnz[v] = (fx_q30)(nn.z * FX_Q30_ONE);
		unsigned left = FX_W15_ONE;
		for (int k = 0; k < 3; k++) {
			b->soa.fweight[k][v] = (fx_w15)(b->soa.weight[k][v] * FX_W15_ONE);
			left -= b->soa.fweight[k][v];
		}
		b->soa.fweight[3][v] = (fx_w15)left;
	}
	skin_compact_load(&b->compact, &b->soa);
}

static void make_bones(skin_bones *bones)
{
	static skel s;
	static skel_pose bind, pose;
	s.count = BENCH_BONES;
	for (int i = 0; i < BENCH_BONES; i++) {
		bind.rot[i] = random_quat();
		pose.rot[i] = random_quat();
		bind.head[i] = vec3_make(frand(), frand(), frand());
		pose.head[i] = vec3_make(frand(), frand(), frand());
	}
	skin_bones_compute(bones, &s, &bind, &pose);
}

/* The user's body (SKELETON [MESH], bound as `skintool bind` binds it),
 * laid out and posed as the other commands do (runtime_skin), in the motion's
 * first frame, or in the skeleton's rest pose when no motion is given;
 * *pose_name says which. */
static int load_body(bench *b, const tool_common *c, const char **pose_name)
{
	TOOL_STATE(bound_body, body);
	static runtime_skin sk;
	static amc_frame f;
	if (rig_bind_load(&c->bind, c->asf, c->mesh, body) < 0 ||
	    (c->amc && motion_read_frame(c->amc, &body->skel, -1, &f) < 0) ||
	    runtime_skin_init(&sk, &body->skel, &body->pose, &body->mesh, &body->weights,
			  c->mesh ? c->mesh : "generated body") < 0)
		return -1;
	runtime_skin_use_compact(&sk);
	runtime_skin_frame(&sk, c->amc ? f.value : NULL);
	*pose_name = c->amc ? "the motion's first frame" : "the skeleton's rest pose";
	b->soa = sk.soa;
	b->compact = sk.compact;
	b->bones = sk.bones;
	if (alloc_outputs(b, sk.soa.count) < 0) {
		fprintf(stderr, "skintool bench: out of memory for %d vertices\n", sk.soa.count);
		return -1;
	}
	return 0;
}

static void run_slice(void *ctx, int slice, int slices)
{
	bench *b = ctx;
	int first, count;
	skin_slice(b->soa.padded, slice, slices, &first, &count);
	if (b->k->compact)
		skin_run_compact(b->k->algo, &b->compact, &b->bones, first, count, &b->out);
	else
		skin_run(b->k->algo, &b->soa, &b->bones, first, count, &b->out);
}

/* Seconds per pass of one timed round: passes for at least 50 ms, on the
 * pool's threads or (w NULL) on the caller's alone. */
static double round_seconds_per_pass(workers *w, bench *b)
{
	int passes = 0;
	uint64_t t0 = clock_now_ns(), t1;
	do {
		if (w)
			workers_run(w, run_slice, b);
		else
			run_slice(b, 0, 1);
		passes++;
		t1 = clock_now_ns();
	} while (t1 - t0 < 50000000u);
	return (double)(t1 - t0) * 1e-9 / passes;
}

/* Best of many short rounds per algorithm, the algorithms taking turns so
 * that a machine slowing down or speeding up (a shared VM) shifts all of
 * them alike and their ratios stay meaningful: short rounds give each
 * algorithm more chances to be timed in the machine's fast phases. With
 * more than one thread, each round times the caller's thread alone too
 * (best[1]), so that the scaling is a ratio within the run. */

static void best_seconds_per_pass(workers *w, bench *b, int rounds, double best[2][K_COUNT], const char *ozz,
				  double *ozz_best)
{
	static cli_progress pr;
	const int pools = workers_count(w) > 1 ? 2 : 1;
	for (int p = 0; p < 2; p++)
		for (int k = 0; k < K_COUNT; k++)
			best[p][k] = 1e30;
	cli_progress_start(&pr, "bench", "rounds", rounds);
	for (int round = 0; round < rounds; round++) {
		for (int k = 0; k < K_COUNT; k++) {
			b->k = &kernels[k];
			for (int p = 0; p < pools; p++) {
				double s = round_seconds_per_pass(p == 0 ? w : NULL, b);
				if (s < best[p][k])
					best[p][k] = s;
			}
		}
		if (ozz) /* the anchor takes its turn too: one round of its own */
			*ozz_best = fmax(*ozz_best, tool_anchor_ozz_rate(ozz, b->soa.count));
		cli_progress_step(&pr, round + 1);
	}
	cli_progress_end(&pr, " of the 5 kernels");
}

typedef struct copy_job {
	char *dst;
	const char *src;
	size_t bytes;
} copy_job;

static void copy_slice(void *ctx, int slice, int slices)
{
	const copy_job *j = ctx;
	size_t first = j->bytes / (size_t)slices * (size_t)slice;
	size_t end = slice == slices - 1 ? j->bytes : first + j->bytes / (size_t)slices;
	memcpy(j->dst + first, j->src + first, end - first);
}

/* Copy bandwidth (bytes read + written per second) over buffers the size
 * of the kernels' working set, on the kernels' threads, best of several
 * passes. */
static double copy_bandwidth(workers *w, size_t bytes)
{
	char *a = alloc_aligned(bytes), *c = alloc_aligned(bytes);
	if (!a || !c) {
		free(a);
		free(c);
		return 0;
	}
	memset(a, 1, bytes);
	memset(c, 2, bytes);
	copy_job job = { c, a, bytes };
	double best = 1e30;
	for (int round = 0; round < 5; round++) {
		uint64_t t0 = clock_now_ns();
		workers_run(w, copy_slice, &job);
		double s = (double)(clock_now_ns() - t0) * 1e-9;
		if (s < best)
			best = s;
		a[round] ^= c[bytes - 1 - (size_t)round];
	}
	free(a);
	free(c);
	return 2.0 * (double)bytes / best;
}

typedef struct bench_args {
	tool_common c; /* first: tool_files_skel_mesh reads it */
	long verts, threads, rounds;
	int verts_given;
	const char *ozz;  /* the anchor's program, or NULL */
} bench_args;

enum { OPT_VERTS = 1, OPT_THREADS, OPT_ROUNDS, OPT_OZZ };

static const cli_opt bench_opts[] = {
	{ "verts", 0, "N", OPT_VERTS, "vertices to skin (default 1000000)" },
	{ "threads", 0, "T", OPT_THREADS, "worker threads (default 1); above 1, one thread is timed too" },
	{ "rounds", 0, "R", OPT_ROUNDS, "timed rounds of 50 ms per kernel; the best counts (default 20)" },
	{ "ozz", 0, "PROGRAM", OPT_OZZ,
	  "also time ozz-animation's LBS (../shared/tools/ozz-bench, built) on the same case, a round after each of ours" },
	{ NULL, 0, NULL, 0, NULL },
};

static int bench_take(void *ctx, int id, const char *v)
{
	static const char *const names[] = { NULL, "--verts", "--threads", "--rounds" };
	bench_args *a = ctx;
	int r = tool_common_take(&a->c, id, v);
	if (r <= 0)
		return r;
	if (id == OPT_OZZ) {
		a->ozz = v;
		return 0;
	}
	long *const dst[] = { NULL, &a->verts, &a->threads, &a->rounds };
	a->verts_given |= id == OPT_VERTS;
	return cli_parse_long(names[id], v, dst[id]);
}

static const cli_command bench_command = {
	.prog = "skintool bench",
	.usage = "[--verts=N] [--threads=T] [--rounds=R]\n"
		 "  or:  skintool bench SKELETON [MESH] [--motion=M.amc] [OPTION]...",
	.about = "Skinning speed of every kernel (LBS, DQBS, fixed-point DQBS; scalar and SIMD) on a synthetic\n"
		 "mesh, against the memory-bandwidth bound measured in the same run on the same threads.\n"
		 "With --threads above 1, every round also times one thread, and each row ends with the speed-up.\n"
		 "Given SKELETON (and MESH: else the generated body), the body is bound as skintool bind binds\n"
		 "it and skinned in the motion's first frame (or the rest pose) instead of the synthetic mesh.",
	.opts = { bench_opts, tool_opt_skeleton, tool_opt_motion, tool_opt_mesh, bind_opts },
	.take = bench_take,
	.positional = tool_files_skel_mesh,
	.examples = (const cli_example[]){
		{ "Every kernel on 1M synthetic vertices, on two threads",
		  "skintool bench --threads=2" },
		{ "Against ozz-animation's LBS in the same run (the anchor built as ../shared/tools/README.md says)",
		  "skintool bench --ozz=anchors/ozz_bench" },
		{ "The kernels on your own body, posed in a clip's first frame",
		  "skintool bench 02.asf body.obj --motion=02_01.amc" },
		{ NULL, NULL },
	},
};

static int parse(int argc, char **argv, bench_args *a)
{
	tool_common_init(&a->c, bench_command.prog);
	int rc = cli_parse(&bench_command, a, argc, argv, 0);
	if (rc != 0)
		return rc;
	motion_bvh_slots(&a->c.asf, &a->c.amc, &a->c.mesh);
	if (!a->c.asf && (a->c.mesh || a->c.amc))
		return -tool_missing(&a->c, "SKELETON with MESH or --motion");
	if (a->c.asf && (a->verts_given || a->ozz)) {
		fprintf(stderr, "skintool bench: --verts and --ozz are for the synthetic mesh, not SKELETON [MESH]\n");
		return -1;
	}
	if (a->verts < SKIN_LANES || a->verts > 50000000 || a->threads < 1 || a->threads > WORKERS_MAX ||
	    a->rounds < 1 || a->rounds > 1000) {
		fprintf(stderr, "skintool bench: --verts must be 8..50000000, --threads 1..%d and --rounds 1..1000\n",
			WORKERS_MAX);
		return -1;
	}
	return 0;
}

/* Copy bandwidth per working-set size, measured once for each */
static double bandwidth_for(workers *w, long verts, int bytes)
{
	static int sizes[K_COUNT];
	static double bw[K_COUNT];
	for (int i = 0; i < K_COUNT; i++) {
		if (sizes[i] == bytes)
			return bw[i];
		if (!sizes[i]) {
			sizes[i] = bytes;
			return bw[i] = copy_bandwidth(w, (size_t)verts * (size_t)bytes / 2);
		}
	}
	return 0;
}

static void print_ratios(int k, const double best[K_COUNT], const double one_thread[K_COUNT])
{
	if (k == K_DQBS || k == K_FIXED)
		printf("   %.2fx LBS time", best[k] / best[K_LBS]);
	if (k == K_FIXED)
		printf(", %.2fx float DQBS speed", best[K_DQBS] / best[k]);
	if (k == K_LBS_COMPACT || k == K_DQBS_COMPACT)
		printf("   %.2fx float speed", best[k - K_LBS_COMPACT] / best[k]);
	if (k == K_DQBS_COMPACT)
		printf(", %.2fx compact LBS time", best[k] / best[K_LBS_COMPACT]);
	if (one_thread)
		printf("%s%.2fx one thread", k == K_LBS ? "   " : ", ", one_thread[k] / best[k]);
	printf("\n");
}

static void print_table(workers *w, const bench_args *a, const double best[2][K_COUNT])
{
	printf("%-13s %10s %9s %11s %16s %9s\n", "algo", "Mverts/s", "ns/vert", "bytes/vert",
	       "bw bound Mv/s", "of bound");
	for (int k = 0; k < K_COUNT; k++) {
		double rate = (double)a->verts / best[0][k];
		double bound = bandwidth_for(w, a->verts, kernels[k].bytes) / kernels[k].bytes;
		printf("%-13s %10.1f %9.2f %11d %16.1f %8.0f%%", kernels[k].name, rate * 1e-6,
		       best[0][k] * 1e9 / (double)a->verts, kernels[k].bytes, bound * 1e-6, 100.0 * rate / bound);
		print_ratios(k, best[0], workers_count(w) > 1 ? best[1] : NULL);
	}
}

/* The synthetic mesh (a->verts vertices) or the user's body; says which
 * on stdout. */
static int prepare(bench *b, bench_args *a, void *block[2], int threads)
{
	if (!a->c.asf) {
		if (alloc_streams(b, (int)a->verts, block) < 0) {
			fprintf(stderr, "skintool bench: out of memory for %ld vertices\n", a->verts);
			return -1;
		}
		make_scene(b);
		make_bones(&b->bones);
		printf("skinning %ld vertices, 4 influences, %d bones, %d thread(s), kernels: %s\n", a->verts,
		       BENCH_BONES, threads, skin_simd_name());
		return 0;
	}
	const char *pose;
	if (load_body(b, &a->c, &pose) < 0)
		return -1;
	a->verts = b->soa.count;
	printf("skinning %s: %d vertices, %d bones, in %s, %d thread(s), kernels: %s\n",
	       a->c.mesh ? a->c.mesh : "the generated body", b->soa.count, b->bones.count, pose, threads,
	       skin_simd_name());
	return 0;
}

/* The largest side of the box the compact positions are quantised over */
static double compact_box(const skin_compact *c)
{
	double side = 0;
	for (int i = 0; i < 3; i++)
		side = fmax(side, (double)c->step[i] * 65535.0);
	return side;
}

/* The anchor against LBS and float DQBS on one thread. */
static void print_ozz(const bench_args *a, double ozz, const double best[K_COUNT])
{
	if (!(ozz > 0))
		return;
	double lbs = (double)a->verts / best[K_LBS] * 1e-6, dqbs = (double)a->verts / best[K_DQBS] * 1e-6;
	printf("ozz-animation LBS (%s, the same case, one round after each of ours, best): %.1f M vertices/s; "
	       "lbs %.2fx its speed, dqbs %.2fx\n", a->ozz, ozz, lbs / ozz, dqbs / ozz);
}

int cmd_bench(int argc, char **argv)
{
	static bench b;
	static bench_args a;
	void *block[2] = { NULL, NULL };
	a.verts = 1000000;
	a.threads = 1;
	a.rounds = 20;
	int rc = parse(argc, argv, &a);
	if (rc != 0)
		return rc < 0;
	workers *w = workers_start((int)a.threads);
	if (!w) {
		fprintf(stderr, "skintool bench: cannot start %ld threads\n", a.threads);
		return 1;
	}
	rc = 1;
	if (prepare(&b, &a, block, workers_count(w)) == 0) {
		double best[2][K_COUNT], ozz = 0;
		best_seconds_per_pass(w, &b, (int)a.rounds, best, a.ozz, &ozz);
		print_table(w, &a, best);
		if (a.ozz)
			print_ozz(&a, ozz, workers_count(w) > 1 ? best[1] : best[0]);
		printf("compact streams: positions within %.3g of the float ones (half a 16-bit step of the "
		       "%.3g-unit box)\n", (double)skin_compact_position_bound(&b.compact), compact_box(&b.compact));
		double pair = (best[0][K_LBS] + best[0][K_DQBS]) * 1e9 / (double)b.soa.count;
		rc = bench_closeup(&b.soa, &b.bones, pair, (int)a.rounds) < 0;
	}
	workers_stop(w);
	free_streams(&b, block);
	return rc;
}
