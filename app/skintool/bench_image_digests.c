/* The per-block digests' cost, measured against their absence in the same
 * run: the check at open (the digest blocks read and hashed against the
 * root, timed by doing it again), and the check of every block read (the
 * body's sections, the clip's blocks) with im->digests on and off. */
#include "bench_image_digests.h"

#include <stdint.h>
#include <stdio.h>

#include "clock.h"
#include "image_digests.h"
#include "tool_state.h"

typedef struct digest_ns {
	uint64_t body, decode;      /* skeleton and body loaded; every frame of clip 0 decoded */
} digest_ns;

static int time_reads(show_image *img, digest_ns *t)
{
	TOOL_STATE(bound_body, body);
	static skp_clip_stream st;
	static amc_frame f;
	static float values[SKP_MAX_DOF];
	skp_error err;
	long number;
	uint64_t t0 = clock_now_ns();
	if (skp_image_load_skel(&img->im, &body->skel, &err) != SKP_OK ||
	    skp_image_load_bind(&img->im, &body->skel, &body->mesh, &body->weights, values, &number, &err) != SKP_OK)
		return -1;
	uint64_t t1 = clock_now_ns();
	if (skp_clip_stream_open(&st, &img->im, 0, &err) != SKP_OK)
		return -1;
	while (skp_clip_stream_next(&st, &f, &err) == 1)
		;
	t->body = t1 - t0;
	t->decode = clock_now_ns() - t1;
	return 0;
}

static int best_reads(show_image *img, long runs, int check, digest_ns *best)
{
	digest_ns t;
	int saved = img->im.digests;
	best->body = best->decode = UINT64_MAX;
	img->im.digests = check && saved;
	for (long r = 0; r < runs; r++) {
		if (time_reads(img, &t) < 0)
			break;
		best->body = t.body < best->body ? t.body : best->body;
		best->decode = t.decode < best->decode ? t.decode : best->decode;
	}
	img->im.digests = saved;
	return best->body == UINT64_MAX ? -1 : 0;
}

static double best_open_check(show_image *img, long runs)
{
	uint64_t best = UINT64_MAX;
	skp_error err;
	for (long r = 0; r < runs; r++) {
		uint64_t t0 = clock_now_ns();
		if (skp_image_digests_open(&img->im, &err) != SKP_OK)
			return -1;
		uint64_t t = clock_now_ns() - t0;
		best = t < best ? t : best;
	}
	return (double)best * 1e-6;
}

void bench_block_digests(show_image *img, long runs)
{
	const skp_image_header *h = &img->im.hdr;
	digest_ns on, off;
	if (!img->im.digest_first) {
		printf("block digests: none (format version %u: the whole-image digest only)\n", (unsigned)h->version);
		return;
	}
	if (!img->im.digests) {
		printf("block digests: they do not give the header's root: not timed\n");
		return;
	}
	double open_ms = best_open_check(img, runs);
	if (img->im.clip_count == 0 || best_reads(img, runs, 1, &on) < 0 || best_reads(img, runs, 0, &off) < 0)
		return;
	uint32_t frames = img->im.clip[0].frame_count;
	printf("block digests: %lu digest blocks checked against the root at open: %.3f ms\n",
	       (unsigned long)(h->data_blocks - img->im.digest_first), open_ms);
	printf("block digests: skeleton + body %.2f ms checked, %.2f ms not (%+.1f%%); clip %s decoded from its blocks "
	       "%.2f us a frame checked, %.2f us not (%+.1f%%; best of %ld)\n",
	       (double)on.body * 1e-6, (double)off.body * 1e-6, 100.0 * ((double)on.body / (double)off.body - 1),
	       img->im.clip[0].name, (double)on.decode * 1e-3 / frames, (double)off.decode * 1e-3 / frames,
	       100.0 * ((double)on.decode / (double)off.decode - 1), runs);
}
