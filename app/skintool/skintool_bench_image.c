/* skintool bench-image show.skn [--amc M.amc ...] [--runs N] [--acl PROGRAM]
 * Figures of a flash image: time from nothing to the first decoded frame
 * (open, header, directory, skeleton, bind data, quantisation, first frame
 * block; no GL); per clip its motion's figures (bench_image_codec.h: bytes
 * a frame, the ratio against 10 float32 a bone a frame, the shell error
 * against the source, decode time, ACL's figures beside them) and bytes per
 * frame against the AMC text it came from; the size parity and the header
 * copy add, and the time to the first frame again with one block of the
 * bind section damaged (rebuilt from parity on the way). Best of N runs
 * (the machine is shared). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_args.h"
#include "cli_error.h"
#include "cli_opts.h"
#include "bench_image_codec.h"
#include "bench_image_digests.h"
#include "show_source.h"
#include "clock.h"
#include "fk.h"
#include "skintool_cmds.h"
#include "tool_state.h"

typedef struct first_frame_ns {
	uint64_t open, body, frame;
} first_frame_ns;

static int time_first_frame(const char *path, first_frame_ns *t)
{
	static show_image img;
	static skp_clip_stream pl;
	TOOL_STATE(bound_body, body);
	static amc_frame f;
	static float values[SKP_MAX_DOF];
	skp_error err;
	long number;
	uint64_t t0 = clock_now_ns();
	if (show_image_open(&img, path, &err) < 0) {
		cli_error(path, &err);
		return -1;
	}
	uint64_t t1 = clock_now_ns();
	int ok = skp_image_load_skel(&img.im, &body->skel, &err) == SKP_OK &&
		 skp_image_load_bind(&img.im, &body->skel, &body->mesh, &body->weights, values, &number, &err) == SKP_OK;
	if (ok)
		fk_pose(&body->skel, values, &body->pose); /* values are 0 for the rest pose */
	uint64_t t2 = clock_now_ns();
	ok = ok && skp_clip_stream_open(&pl, &img.im, 0, &err) == SKP_OK && skp_clip_stream_next(&pl, &f, &err) == 1;
	uint64_t t3 = clock_now_ns();
	show_image_close(&img);
	if (!ok) {
		cli_error(path, &err);
		return -1;
	}
	t->open = t1 - t0;
	t->body = t2 - t1;
	t->frame = t3 - t2;
	return 0;
}

/* The clip's motion figures, then its bytes against the AMC text. */
static int print_clip(show_image *img, const skel *s, int c, const char *amc, const char *acl)
{
	const skp_image_clip *cl = &img->im.clip[c];
	if (bench_clip_motion(img, s, c, amc, acl) < 0)
		return -1;
	double packed = (double)cl->frame_blocks * img->im.hdr.block_size / cl->frame_count;
	struct stat st;
	if (amc && stat(amc, &st) == 0)
		printf("  AMC text %.1f bytes per frame (%.1fx the packed frame blocks)\n", (double)st.st_size / cl->frame_count,
		       (double)st.st_size / cl->frame_count / packed);
	return 0;
}

static first_frame_ns best_first_frame(const char *path, long runs)
{
	first_frame_ns best = { UINT64_MAX, UINT64_MAX, UINT64_MAX }, t;
	for (long r = 0; r < runs; r++) {
		if (time_first_frame(path, &t) < 0)
			return best;
		if (t.open + t.body + t.frame < best.open + best.body + best.frame)
			best = t;
	}
	return best;
}

static double total_ms(const first_frame_ns *t)
{
	return (double)(t->open + t->body + t->frame) * 1e-6;
}

/* A copy of path with one byte of the bind section's middle block flipped,
 * timed like the original: what a rebuild costs the first frame. */
static void time_with_rebuild(const char *path, const show_image *img, long runs, double clean_ms)
{
	const skp_image_header *h = &img->im.hdr;
	char tmp[] = "/tmp/skintool-bench-XXXXXX";
	int fd = mkstemp(tmp);
	FILE *in = fopen(path, "rb"), *out = fd >= 0 ? fdopen(fd, "wb") : NULL;
	long at = ((long)h->sec[SKP_SEC_BIND].first + (long)h->sec[SKP_SEC_BIND].count / 2) * (long)h->block_size + 100;
	int c;
	for (long i = 0; in && out && (c = fgetc(in)) != EOF; i++)
		fputc(i == at ? c ^ 0x10 : c, out);
	if (in)
		fclose(in);
	if (out)
		fclose(out);
	first_frame_ns t = best_first_frame(tmp, runs);
	unlink(tmp);
	if (t.open != UINT64_MAX)
		printf("with block %ld (bind section) damaged and rebuilt from parity: first frame %.2f ms (%+.2f ms)\n",
		       at / (long)h->block_size, total_ms(&t), total_ms(&t) - clean_ms);
}

static void print_parity(const show_image *img)
{
	const skp_image_header *h = &img->im.hdr;
	if (h->parity_blocks == 0)
		printf("parity: none: a bad block other than the header's and the directory's cannot be rebuilt\n");
	else
		printf("parity: %lu blocks and the copies (directory, header) for %lu data blocks: %.1f%% larger than without\n",
		       (unsigned long)h->parity_blocks, (unsigned long)h->data_blocks,
		       100.0 * (h->block_count - h->data_blocks) / h->data_blocks);
}

typedef struct bench_image_args {
	const char *path, *amc[SKP_IMAGE_MAX_CLIPS], *acl;
	long runs;
	int amc_count;
} bench_image_args;

enum { OPT_AMC = 1, OPT_RUNS, OPT_ACL };

static const cli_opt bench_image_opts[] = {
	{ "amc", 0, "M.amc", OPT_AMC, "the clip's source AMC, to compare bytes per frame (repeat per clip)" },
	{ "runs", 0, "N", OPT_RUNS, "time the first frame N times and keep the best (default 10)" },
	{ "acl", 0, "PROGRAM", OPT_ACL, "also compress each clip's source (--amc) with ACL's anchor "
					"(../shared/tools/acl-bench, built) and print its figures beside ours" },
	{ NULL, 0, NULL, 0, NULL },
};

static int bi_take(void *ctx, int id, const char *v)
{
	bench_image_args *a = ctx;
	if (id == OPT_ACL) {
		a->acl = v;
		return 0;
	}
	if (id == OPT_AMC) {
		if (a->amc_count == SKP_IMAGE_MAX_CLIPS)
			return fprintf(stderr, "skintool bench-image: more than %d --amc\n", SKP_IMAGE_MAX_CLIPS), -1;
		a->amc[a->amc_count++] = v;
		return 0;
	}
	if (cli_parse_long("--runs", v, &a->runs) < 0)
		return -1;
	return a->runs < 1 ? fprintf(stderr, "skintool bench-image: --runs expects 1 or more\n"), -1 : 0;
}

static int bi_file(void *ctx, const char *arg)
{
	bench_image_args *a = ctx;
	const char **slots[] = { &a->path };
	return cli_take_positional("skintool bench-image", slots, 1, arg);
}

static const cli_command bench_image_command = {
	.prog = "skintool bench-image",
	.usage = "SHOW.skn [--amc=M.amc]... [--runs=N] [--acl=PROGRAM]",
	.about = "An image's time to the first frame (open, header, skeleton and body, first block and\n"
		 "decode; no GL), its parity overhead, and per clip: bytes a frame, the ratio against 10 float32\n"
		 "a bone a frame (ACL's raw measure), decode time a frame, and with the clip's source (--amc, in\n"
		 "clip order) the worst and 99th-percentile shell error (ACL's measure: points 3 cm along each\n"
		 "joint's axes, cm) and, with --acl, ACL's own figures on the same frames (skipped, saying so,\n"
		 "when the anchor is not built).",
	.opts = { bench_image_opts },
	.take = bi_take,
	.positional = bi_file,
	.examples = (const cli_example[]){
		{ "An image's time to the first frame, and its bytes per frame against the AMC text",
		  "skintool bench-image show.skn --amc=02_01.amc" },
		{ "Side by side with ACL (the anchor built as ../shared/tools/README.md says)",
		  "skintool bench-image show.skn --amc=02_01.amc --acl=anchors/acl_bench" },
		{ NULL, NULL },
	},
};

int cmd_bench_image(int argc, char **argv)
{
	static show_image img;
	static bench_image_args a;
	skp_error err;
	memset(&a, 0, sizeof a);
	a.runs = 10;
	int rc = cli_parse(&bench_image_command, &a, argc, argv, 0);
	if (rc != 0)
		return rc < 0;
	const char *path = a.path, *const *amc = a.amc;
	long runs = a.runs;
	int amc_count = a.amc_count;
	if (!path)
		return -cli_missing(bench_image_command.prog, "SHOW.skn");
	first_frame_ns best = best_first_frame(path, runs);
	if (best.open == UINT64_MAX)
		return 1;
	printf("%s: first frame %.2f ms after start (open + header + directory %.2f ms, skeleton + body %.2f ms, "
	       "quantisation + first block + decode %.3f ms; best of %ld, no GL)\n", path,
	       (best.open + best.body + best.frame) * 1e-6, best.open * 1e-6, best.body * 1e-6, best.frame * 1e-6, runs);
	if (show_image_open(&img, path, &err) < 0) {
		cli_error(path, &err);
		return 1;
	}
	print_parity(&img);
	if (img.im.hdr.parity_blocks)
		time_with_rebuild(path, &img, runs, total_ms(&best));
	bench_block_digests(&img, runs);
	static skel s;
	if (skp_image_load_skel(&img.im, &s, &err) != SKP_OK) {
		cli_error(path, &err);
		show_image_close(&img);
		return 1;
	}
	rc = 0;
	for (int c = 0; c < img.im.clip_count && !rc; c++)
		rc = print_clip(&img, &s, c, c < amc_count ? amc[c] : NULL, a.acl) < 0;
	show_image_close(&img);
	return rc;
}
