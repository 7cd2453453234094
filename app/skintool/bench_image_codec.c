#include "bench_image_codec.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "clock.h"
#include "codec_decode.h"
#include "encode_error.h"
#include "fk.h"
#include "tool_anchor.h"
#include "tool_clip.h"

#define SHELL_CM 3.0

static double unit_cm(const skp_image_clip *c, const skel *s)
{
	return c->unit_cm > 0 ? (double)c->unit_cm : skel_unit_cm(s);
}

/* The stream's bytes a frame: the compressed stream, or the blocks' values. */
static double stream_bytes(const skp_image_clip *c)
{
	return c->coded ? (double)c->stream_bytes : 2.0 * c->dofs * (double)c->frame_count;
}

/* ns a frame: the image stream (blocks read and checked, segments gathered
 * and decoded), best of 5; *codec: the decoder alone on gathered segments. */
static double time_decode(show_image *img, int clip, double *codec)
{
	static skp_clip_stream st;
	static codec_decoder d;
	static amc_frame f;
	static float v[SKP_MAX_DOF];
	skp_error err;
	double best = 1e30, best_codec = 1e30;
	for (int run = 0; run < 5; run++) {
		if (skp_clip_stream_open(&st, &img->im, clip, &err) != SKP_OK)
			return -1;
		uint64_t t0 = clock_now_ns(), in_codec = 0;
		long n = 0;
		while (skp_clip_stream_next(&st, &f, &err) != 0)
			n++;
		uint64_t t1 = clock_now_ns();
		best = fmin(best, n ? (double)(t1 - t0) / (double)n : 0);
		if (!st.c.coded)
			continue;
		/* each segment once more from its gathered bytes: the codec alone */
		for (uint32_t s = 0; s < st.c.segments; s++) {
			skp_clip_stream_seek(&st, s * st.cc.segment_frames);
			if (skp_clip_stream_next(&st, &f, &err) != 1)
				continue;
			uint64_t a = clock_now_ns();
			if (codec_begin(&d, &st.cc, s, st.seg_bytes, st.dec.nbytes, &err) == SKP_OK)
				while (codec_next(&d, v, &err) == 1)
					;
			in_codec += clock_now_ns() - a;
		}
		best_codec = fmin(best_codec, n ? (double)in_codec / (double)n : 0);
	}
	*codec = img->im.clip[clip].coded ? best_codec : -1;
	return best;
}

static int by_value(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The shell error of every frame as the image decodes it against the
 * source's; worst and 99th percentile in cm. */
static int shell_errors(show_image *img, const skel *s, int clip, const tool_clip *src, double *worst, double *p99)
{
	static skp_clip_stream st;
	static amc_frame f;
	static skel_pose ref, got;
	skp_error err;
	const skp_image_clip *c = &img->im.clip[clip];
	double unit = unit_cm(c, s);
	double *e = malloc(sizeof(double) * (size_t)src->n);
	if (!e || skp_clip_stream_open(&st, &img->im, clip, &err) != SKP_OK) {
		free(e);
		return -1;
	}
	long n = 0;
	while (n < src->n && skp_clip_stream_next(&st, &f, &err) == 1) {
		fk_pose(s, src->frames + (size_t)n * (size_t)src->dofs, &ref);
		fk_pose(s, f.value, &got);
		e[n++] = encode_shell_error(s, &ref, &got, SHELL_CM / unit) * unit;
	}
	if (n != src->n || n != (long)c->frame_count) {
		fprintf(stderr, "%s: %ld frames decoded of %ld in the source\n", c->name, n, src->n);
		free(e);
		return -1;
	}
	qsort(e, (size_t)n, sizeof *e, by_value);
	*worst = e[n - 1];
	*p99 = e[(size_t)ceil(0.99 * (double)n) - 1];
	free(e);
	return 0;
}

/* The source as ACL's anchor reads it (export_local.py's text: joints,
 * frames, parents, then per frame and joint the local rotation x y z w and
 * translation in cm), made from the players' own FK, parents first. */
static int write_acl_text(FILE *out, const skel *s, const tool_clip *src, double unit)
{
	static skel_pose p;
	int at[SKP_MAX_BONES];
	for (int i = 0; i < s->count; i++)
		at[s->eval_order[i]] = i;
	fprintf(out, "%d %ld\n", s->count, src->n);
	for (int i = 0; i < s->count; i++) {
		int parent = s->bone[s->eval_order[i]].parent;
		fprintf(out, "%d%c", parent < 0 ? -1 : at[parent], i + 1 < s->count ? ' ' : '\n');
	}
	for (long f = 0; f < src->n; f++) {
		fk_pose(s, src->frames + (size_t)f * (size_t)src->dofs, &p);
		for (int i = 0; i < s->count; i++) {
			int b = s->eval_order[i], parent = s->bone[b].parent;
			quat q = p.rot[b];
			vec3 t = p.head[b];
			if (parent >= 0) {
				quat inv = quat_conj(p.rot[parent]);
				q = quat_mul(inv, q);
				t = quat_rotate(inv, vec3_sub(p.head[b], p.head[parent]));
			}
			fprintf(out, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", q.x, q.y, q.z, q.w, t.x * unit, t.y * unit,
				t.z * unit);
		}
	}
	return ferror(out) ? -1 : 0;
}

static void run_acl(const char *acl, const skel *s, const tool_clip *src, double unit, double fps)
{
	char tmp[] = "/tmp/skintool-acl-XXXXXX", rate[32], out[512];
	if (access(acl, X_OK) != 0) {
		printf("  ACL: skipped (%s: %s; build ../shared/tools/acl-bench as ../shared/tools/README.md says)\n", acl,
		       strerror(errno));
		return;
	}
	int fd = mkstemp(tmp);
	FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
	int bad = !f || write_acl_text(f, s, src, unit) < 0;
	if (f && fclose(f) != 0)
		bad = 1;
	snprintf(rate, sizeof rate, "%g", fps);
	char *const argv[] = { (char *)acl, tmp, rate, NULL };
	int rc = bad ? -1 : tool_anchor_run(argv, out, sizeof out);
	unlink(tmp);
	out[strcspn(out, "\n")] = '\0';
	if (rc != 0 || strncmp(out, "acl:", 4))
		printf("  ACL: failed (%s exit %d%s%s)\n", acl, rc, *out ? ": " : "", out);
	else
		printf("  ACL (default settings, the same frames): %s\n", out + 5);
}

int bench_clip_motion(show_image *img, const skel *s, int clip, const char *src_path, const char *acl)
{
	static tool_clip src;
	const skp_image_clip *c = &img->im.clip[clip];
	double raw = 40.0 * s->count, bytes = stream_bytes(c) / c->frame_count;
	double blocks = (double)(c->frame_blocks + c->quant_blocks) * img->im.hdr.block_size / c->frame_count;
	double codec_ns = -1, ns = time_decode(img, clip, &codec_ns);
	printf("clip %s: %s, %.1f bytes a frame (%.1f:1 against 10 float32 a bone a frame; %.1f with its blocks), "
	       "decode %.0f ns a frame", c->name, c->coded ? "compressed" : "16-bit quantised", bytes, raw / bytes,
	       blocks, ns);
	if (codec_ns >= 0)
		printf(" (the codec alone %.0f ns)", codec_ns);
	printf("\n");
	if (!src_path) {
		if (c->coded)
			printf("  shell error (3 cm points) as packed: worst %.4f cm (--amc for the 99th percentile)\n",
			       (double)c->shell_err);
		if (acl)
			printf("  ACL: skipped (it needs the source: --amc)\n");
		return 0;
	}
	if (tool_clip_load(src_path, s, &src) < 0)
		return -1;
	double worst, p99;
	int rc = shell_errors(img, s, clip, &src, &worst, &p99);
	if (rc == 0)
		printf("  shell error (3 cm points, %.3g cm a unit) against %s: worst %.4f cm, 99th percentile %.4f cm\n",
		       unit_cm(c, s), src_path, worst, p99);
	if (rc == 0 && acl)
		run_acl(acl, s, &src, unit_cm(c, s), (double)c->fps);
	else if (rc == 0)
		printf("  ACL: skipped (no --acl=PROGRAM: the anchor ../shared/tools/acl-bench, built)\n");
	tool_clip_free(&src);
	return rc;
}
