#include "encode.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "encode_segment.h"
#include "encode_work.h"

static void work_free(enc_work *w)
{
	free(w->gsrc);
	free(w->gdec);
	free(w->psrc);
	free(w->pdec);
	free(w->ref);
	free(w->got);
	free(w->dec);
	free(w->q);
	free(w->err);
	free(w->tbuf);
	enc_snap_free(w);
}

static int work_alloc(enc_work *w)
{
	size_t n = (size_t)w->n, c = (size_t)w->s->count, d = (size_t)w->dofs;
	w->gsrc = malloc(n * c * 9 * sizeof(double));
	w->gdec = malloc(n * c * 9 * sizeof(double));
	w->psrc = malloc(n * c * 6 * sizeof(double));
	w->pdec = malloc(n * c * 6 * sizeof(double));
	w->ref = malloc(n * sizeof(skel_pose));
	w->got = malloc(n * sizeof(skel_pose));
	w->dec = malloc(n * d * sizeof(float));
	w->q = malloc(n * d * sizeof(int32_t));
	w->err = malloc(n * sizeof(double));
	w->tbuf = malloc(SKEL_MAX_CHANNELS * n * sizeof(double));
	if (enc_snap_alloc(w))
		return -1;
	return w->gsrc && w->gdec && w->psrc && w->pdec && w->ref && w->got && w->dec && w->q && w->err && w->tbuf ? 0 : -1;
}

/* How far bone b's rotation moves the points the error measures, per
 * radian: the joints below it (their shell points too), except that past
 * a compensating joint only that joint's head moves (its rotation takes
 * up the rest). */
static double reach(const enc_work *w, const skel_pose *rest, int b)
{
	const skel *s = w->s;
	double r = w->shell;
	for (int d = 0; d < s->count; d++) {
		if (d == b || !enc_above(s, b, d))
			continue;
		int shield = -1;
		for (int a = d; a != b; a = s->bone[a].parent)
			if (w->comp[a])
				shield = a;
		vec3 at = rest->head[shield >= 0 ? shield : d], v = vec3_sub(at, rest->head[b]);
		double dist = sqrt((double)v.x * v.x + (double)v.y * v.y + (double)v.z * v.z);
		r = fmax(r, dist + (shield >= 0 ? 0 : w->shell));
	}
	return r;
}

/* Each track's first step: twice the budget over what one unit of it
 * moves (a rotation by its reach, a translation by 1). */
static void base_steps(const enc_work *w, double tol, double *base)
{
	static skel_pose rest;
	fk_pose(w->s, NULL, &rest);
	for (int b = 0; b < w->s->count; b++) {
		const skel_bone *bone = &w->s->bone[b];
		double r = reach(w, &rest, b);
		for (int i = 0; i < bone->channel_count; i++)
			base[bone->dof_offset + i] = 2 * tol / (bone->channel[i] <= SKEL_RZ ? r : 1.0);
	}
}

/* The worst error with the current steps of bone top's tracks and
 * those below it (or the first past limit; top 0: every track), the
 * others as they were; HUGE_VAL when a track does not fit its bits. */
static double trial(enc_work *w, int top, double limit)
{
	return enc_quantise(w, top) ? HUGE_VAL : enc_measure(w, top, limit);
}

static void scale_steps(enc_work *w, const double *base, double a)
{
	for (int d = 0; d < w->dofs; d++)
		w->step[d] = (float)(base[d] * a);
}

/* The largest common scale of the first steps that keeps the error within
 * tol (bisection in the logarithm). */
static void search_scale(enc_work *w, const double *base, double tol)
{
	double lo = 1.0 / 1024, hi = 64;
	for (int i = 0; i < 16; i++) {
		double m = sqrt(lo * hi);
		scale_steps(w, base, m);
		if (trial(w, 0, tol) <= tol)
			lo = m;
		else
			hi = m;
	}
	scale_steps(w, base, lo);
	trial(w, 0, HUGE_VAL);
}

/* Then each track's step on its own, as far as the budget lets it grow:
 * a trial takes again only the bones the track moves (the others were
 * within the budget already), and a refused step is taken back from the
 * state saved before it, so the result is the one a trial of every track
 * would give. */
static void grow_steps(enc_work *w, double tol, const encode_opts *o)
{
	static const float factor[] = { 2.0f, 1.41f, 1.19f, 1.19f, 1.09f, 1.09f, 1.04f };
	const int passes = (int)(sizeof factor / sizeof factor[0]);
	for (int p = 0; p < passes; p++)
		for (int d = 0; d < w->dofs; d++) {
			float keep = w->step[d];
			w->step[d] = keep * factor[p];
			enc_snap_save(w, w->bone_of[d]);
			if (trial(w, w->bone_of[d], tol) > tol) {
				w->step[d] = keep;
				enc_snap_restore(w);
			}
			if (o->progress)
				o->progress(o->progress_ctx, (p * w->dofs + d + 1) / (double)(passes * w->dofs));
		}
}

static int by_value(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static double percentile99(const double *e, long n)
{
	double *copy = malloc((size_t)n * sizeof *copy);
	if (!copy)
		return 0;
	memcpy(copy, e, (size_t)n * sizeof *copy);
	qsort(copy, (size_t)n, sizeof *copy, by_value);
	double p = copy[(size_t)floor(0.99 * (double)(n - 1))];
	free(copy);
	return p;
}

static skp_status write_segments(const enc_work *w, encode_result *r, skp_error *err)
{
	enc_bits bits = { 0 };
	uint32_t segs = codec_segments(&r->clip);
	r->offsets = malloc(((size_t)segs + 1) * sizeof *r->offsets);
	if (!r->offsets)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "out of memory for %lu segments", (unsigned long)segs);
	for (uint32_t s = 0; s < segs; s++) {
		long first = (long)s * r->clip.segment_frames;
		int len = (int)(w->n - first < r->clip.segment_frames ? w->n - first : r->clip.segment_frames);
		r->offsets[s] = (uint32_t)bits.len;
		enc_segment(&r->clip, w->q, w->dofs, first, len, &bits);
		if (bits.len - r->offsets[s] > SKP_CODEC_SEGMENT_BYTES) {
			enc_bits_free(&bits);
			/* SKP_ERR_RANGE: the caller tries shorter segments */
			return skp_fail(err, SKP_ERR_RANGE, 0, "segment %lu takes %lu bytes (board limit SKP_CODEC_SEGMENT_BYTES %d)",
					(unsigned long)s, (unsigned long)(bits.len - r->offsets[s]), SKP_CODEC_SEGMENT_BYTES);
		}
	}
	r->offsets[segs] = (uint32_t)bits.len;
	r->segments = segs;
	r->bytes = bits.buf;
	r->nbytes = bits.len;
	return bits.failed ? skp_fail(err, SKP_ERR_LIMIT, 0, "out of memory for the compressed clip") : SKP_OK;
}

static void prepare(enc_work *w)
{
	for (int b = 0; b < w->s->count; b++)
		for (int i = 0; i < w->s->bone[b].channel_count; i++)
			w->bone_of[w->s->bone[b].dof_offset + i] = (uint8_t)b;
	enc_comp_prepare(w);
	for (long f = 0; f < w->n; f++)
		fk_pose(w->s, w->src + (size_t)f * (size_t)w->dofs, &w->ref[f]);
}

skp_status encode_clip(const skel *s, const float *frames, long n, const encode_opts *o, encode_result *r,
		       skp_error *err)
{
	static enc_work w;
	double base[SKP_MAX_DOF] = { 0 };
	memset(r, 0, sizeof *r);
	memset(&w, 0, sizeof w);
	if (n < 1 || n > INT32_MAX || !(o->tolerance > 0) || !(o->shell >= 0))
		return skp_fail(err, SKP_ERR_RANGE, 0, "encode: %ld frames, tolerance %g, shell %g", n, o->tolerance, o->shell);
	w.s = s;
	w.src = frames;
	w.n = n;
	w.dofs = s->dof_count;
	w.shell = o->shell;
	skp_status rc = SKP_OK;
	if (work_alloc(&w)) {
		rc = skp_fail(err, SKP_ERR_LIMIT, 0, "out of memory for %ld frames", n);
		goto out;
	}
	prepare(&w);
	base_steps(&w, o->tolerance, base);
	search_scale(&w, base, o->tolerance);
	grow_steps(&w, o->tolerance, o);
	r->worst = trial(&w, 0, HUGE_VAL);
	if (r->worst > o->tolerance) {
		rc = skp_fail(err, SKP_ERR_RANGE, 0, "no grid keeps the error within %g (a track needs more than %d bits)",
			      o->tolerance, CODEC_MAX_BITS);
		goto out;
	}
	r->p99 = percentile99(w.err, n);
	r->clip.frames = (uint32_t)n;
	r->clip.tracks = (uint16_t)w.dofs;
	memcpy(r->clip.track, w.track, sizeof w.track);
	/* shorter segments while one is larger than a board reads */
	for (int len = o->segment_frames > 0 ? o->segment_frames : CODEC_SEGMENT_FRAMES;; len /= 2) {
		r->clip.segment_frames = (uint16_t)len;
		rc = write_segments(&w, r, err);
		if (rc != SKP_ERR_RANGE || len <= 8)
			break;
		encode_result_free(r);
	}
out:
	work_free(&w);
	if (rc)
		encode_result_free(r);
	return rc;
}

void encode_result_free(encode_result *r)
{
	free(r->bytes);
	free(r->offsets);
	r->bytes = NULL;
	r->offsets = NULL;
}
