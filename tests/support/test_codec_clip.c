#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test_codec_clip.h"

#include "codec_decode.h"
#include "encode_error.h"
#include "motion_file.h"
#include "test_paths.h"

/* cm per unit of the shared skeletons: CMU and HDM05 inches, endorphin cm */
static double unit_cm(const char *asf)
{
	return strstr(asf, "endorphin") ? 1.0 : 2.54;
}

int codec_test_load(const char *asf, const char *amc, codec_test_clip *c)
{
	const char *a = test_data_path(asf);
	if (!a)
		return -1;
	static motion_file m;
	static amc_frame f;
	assert_int_equal(motion_load_skel(a, &c->s), 0);
	assert_int_equal(motion_file_open(&m, test_data_path(amc), &c->s), 0);
	long cap = 1024;
	c->frames = malloc(sizeof(float) * (size_t)cap * (size_t)c->s.dof_count);
	c->n = 0;
	while (motion_file_next(&m, &f) == 1) {
		if (c->n == cap)
			c->frames = realloc(c->frames, sizeof(float) * (size_t)(cap *= 2) * (size_t)c->s.dof_count);
		memcpy(c->frames + (size_t)c->n * (size_t)c->s.dof_count, f.value, sizeof(float) * (size_t)c->s.dof_count);
		c->n++;
	}
	motion_file_close(&m);
	c->cm = unit_cm(asf);
	return 0;
}

void codec_test_encode(const codec_test_clip *c, encode_result *r)
{
	codec_test_encode_segments(c, 0, r);
}

void codec_test_encode_segments(const codec_test_clip *c, int segment_frames, encode_result *r)
{
	encode_opts o = { CODEC_TEST_BUDGET_CM * 0.999 / c->cm, CODEC_TEST_SHELL_CM / c->cm, segment_frames, NULL, NULL };
	skp_error err;
	skp_status rc = encode_clip(&c->s, c->frames, c->n, &o, r, &err);
	if (rc)
		fail_msg("encode: %s", err.msg);
}

const uint8_t *codec_test_segment(const encode_result *r, uint32_t s, uint32_t *n)
{
	*n = r->offsets[s + 1] - r->offsets[s];
	return r->bytes + r->offsets[s];
}

double codec_test_decode_all(const codec_test_clip *c, const encode_result *r, float *keep)
{
	static codec_decoder dec;
	static float values[SKP_MAX_DOF];
	static skel_pose ref, got;
	skp_error err;
	double worst = 0;
	long f = 0;
	for (uint32_t s = 0; s < r->segments; s++) {
		uint32_t n;
		const uint8_t *b = codec_test_segment(r, s, &n);
		assert_int_equal(codec_begin(&dec, &r->clip, s, b, n, &err), SKP_OK);
		int rc;
		while ((rc = codec_next(&dec, values, &err)) == 1) {
			if (keep)
				memcpy(keep + (size_t)f * (size_t)c->s.dof_count, values, sizeof(float) * (size_t)c->s.dof_count);
			fk_pose(&c->s, c->frames + (size_t)f * (size_t)c->s.dof_count, &ref);
			fk_pose(&c->s, values, &got);
			worst = fmax(worst, encode_shell_error(&c->s, &ref, &got, CODEC_TEST_SHELL_CM / c->cm) * c->cm);
			f++;
		}
		assert_int_equal(rc, 0);
	}
	assert_int_equal(f, c->n);
	return worst;
}
