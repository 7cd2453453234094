#include "pack_encode.h"

#include <math.h>
#include <stdio.h>

#include "cli_error.h"
#include "cli_progress.h"
#include "cli_quiet.h"
#include "codec_decode.h"
#include "encode.h"

static int is_rotation(const skel *s, int dof)
{
	for (int b = s->count - 1; b >= 0; b--)
		if (s->bone[b].dof_offset <= dof && dof < s->bone[b].dof_offset + s->bone[b].channel_count)
			return s->bone[b].channel[dof - s->bone[b].dof_offset] <= SKEL_RZ;
	return 0;
}

void pack_value_errors(const skel *s, const float *frames, const codec_clip *cc, const uint8_t *bytes,
		       const uint32_t *offsets, float *rot, float *trans)
{
	static codec_decoder d;
	static float v[SKP_MAX_DOF];
	skp_error err;
	*rot = *trans = 0;
	long f = 0;
	for (uint32_t sg = 0; sg < codec_segments(cc); sg++) {
		if (codec_begin(&d, cc, sg, bytes + offsets[sg], offsets[sg + 1] - offsets[sg], &err) != SKP_OK)
			return;
		for (; codec_next(&d, v, &err) == 1; f++)
			for (int i = 0; i < cc->tracks; i++) {
				float e = fabsf(v[i] - frames[(size_t)f * (size_t)cc->tracks + (size_t)i]);
				float *worst = is_rotation(s, i) ? rot : trans;
				*worst = fmaxf(*worst, e);
			}
	}
}

static void told(void *ctx, double done)
{
	cli_progress_step(ctx, (long)(done * 1000.0));
}

int pack_encode_clip(skp_image_writer *w, const char *path, const char *name, double fps,
		     const tool_clip *clip, const pack_codec *o)
{
	static cli_progress pr;
	static char what[SKP_MAX_NAME + 32];
	encode_result r = { 0 };
	skp_error err;
	const skel *s = w->s;
	double unit = o->unit_cm > 0 ? o->unit_cm : skel_unit_cm(s);
	encode_opts eo = { o->error_cm / unit, 3.0 / unit, 0, told, &pr };
	snprintf(what, sizeof what, "pack %s", name);
	cli_progress_start(&pr, what, "permille", 1000);
	skp_status rc = encode_clip(s, clip->frames, clip->n, &eo, &r, &err);
	cli_progress_clear(&pr);
	if (rc != SKP_OK) {
		cli_error(path, &err);
		encode_result_free(&r);
		return -1;
	}
	skp_coded_clip k = { &r.clip, r.bytes, (uint32_t)r.nbytes, r.offsets, r.segments, clip->first_number,
			     0, 0, (float)(r.worst * unit), (float)unit };
	pack_value_errors(s, clip->frames, &r.clip, r.bytes, r.offsets, &k.max_rot_err, &k.max_trans_err);
	rc = skp_image_clip_coded(w, name, (float)fps, &k, &err);
	if (rc != SKP_OK)
		cli_error(path, &err);
	else
		fprintf(cli_summary(),
			"clip %s: %ld frames, %.1f bytes a frame (%.1f:1 against 10 float32 a bone a frame), "
			"shell error worst %.4f cm, 99th percentile %.4f cm (%.3g cm a unit)\n",
			name, clip->n, (double)r.nbytes / (double)clip->n,
			40.0 * s->count * (double)clip->n / (double)(r.nbytes ? r.nbytes : 1), r.worst * unit, r.p99 * unit,
			unit);
	encode_result_free(&r);
	return rc == SKP_OK ? 0 : -1;
}
