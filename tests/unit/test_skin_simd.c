/* The SIMD kernels reproduce the portable ones: same vertices, same
 * results to float rounding (float kernels) or bit for bit (fixed point), on
 * mesh sizes that are not a multiple of the lane count and on slices. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixed_convert.h"
#include "skin_kernels.h"
#include "test_diff.h"

#define N 1003

static mesh m;
static skin_weights w;
static skin_soa soa;
static skin_bones bones;
static float pos_a[3 * N], nrm_a[3 * N], pos_b[3 * N], nrm_b[3 * N];
static int32_t fpos_a[3 * N], fnrm_a[3 * N], fpos_b[3 * N], fnrm_b[3 * N];
static int16_t n16_a[3 * N], n16_b[3 * N];
static skin_compact compact;

static float frand(float lo, float hi)
{
	return lo + (hi - lo) * (float)rand() / (float)RAND_MAX;
}

static quat qrand(void)
{
	return quat_normalize((quat){ frand(-1, 1), frand(-1, 1), frand(-1, 1), frand(-1, 1) });
}

static void setup_scene(void)
{
	static skel s;
	static skel_pose bind, pose;
	static char block[1 << 20] __attribute__((aligned(SKIN_ALIGN)));
	srand(7);
	s.count = 20;
	for (int b = 0; b < s.count; b++) {
		bind.rot[b] = qrand();
		pose.rot[b] = qrand();
		bind.head[b] = vec3_make(frand(-20, 20), frand(-20, 20), frand(-20, 20));
		pose.head[b] = vec3_make(frand(-20, 20), frand(-20, 20), frand(-20, 20));
	}
	m.vert_count = N;
	w.vert_count = N;
	for (int v = 0; v < N; v++) {
		m.pos[v] = vec3_make(frand(-30, 30), frand(-30, 30), frand(-30, 30));
		m.normal[v] = vec3_normalize(vec3_make(frand(-1, 1), frand(-1, 1), frand(-1, 1) + 2));
		int n = v % 7 == 0 ? 0 : 1 + rand() % SKP_MAX_INFLUENCES; /* some with none */
		float sum = 0;
		for (int k = 0; k < n; k++) {
			w.bone[v][k] = (uint16_t)(rand() % s.count);
			sum += w.weight[v][k] = frand(0.05f, 1);
		}
		for (int k = 0; k < n; k++)
			w.weight[v][k] /= sum;
		w.count[v] = (uint8_t)n;
	}
	assert_true(skin_soa_bytes(N) <= sizeof block);
	skin_soa_attach(&soa, block, N);
	skp_error err;
	assert_int_equal(skin_soa_load(&soa, &m, &w, s.count, &err), SKP_OK);
	skin_bones_compute(&bones, &s, &bind, &pose);
}

/* skin_run in three slices (as worker threads split it) */
static void run_sliced(skin_algo a, const skin_out *out)
{
	skin_run(a, &soa, &bones, 0, 512, out);
	skin_run(a, &soa, &bones, 512, 480, out);
	skin_run(a, &soa, &bones, 992, N - 992, out);
}

static void test_float_kernels_match_scalar(void **state)
{
	(void)state;
	setup_scene();
	skin_out a = { pos_a, nrm_a, NULL, NULL, NULL }, b = { pos_b, nrm_b, NULL, NULL, NULL };
	skin_lbs_scalar(&soa, &bones, 0, N, &a);
	memset(pos_b, 0, sizeof pos_b);
	run_sliced(SKIN_LBS, &b);
	double dp = test_max_diff(pos_a, pos_b, 3 * N), dn = test_max_diff(nrm_a, nrm_b, 3 * N);
	print_message("%s LBS vs scalar: positions %.3g, normals %.3g\n", skin_simd_name(), dp, dn);
	assert_true(dp < 1e-4 && dn < 1e-5);
	skin_dqbs_scalar(&soa, &bones, 0, N, &a);
	memset(pos_b, 0, sizeof pos_b);
	run_sliced(SKIN_DQBS, &b);
	dp = test_max_diff(pos_a, pos_b, 3 * N);
	dn = test_max_diff(nrm_a, nrm_b, 3 * N);
	print_message("%s DQBS vs scalar: positions %.3g, normals %.3g\n", skin_simd_name(), dp, dn);
	assert_true(dp < 1e-4 && dn < 1e-5);
}

static void test_fixed_kernel_matches_scalar(void **state)
{
	(void)state;
	setup_scene();
	skin_out a = { NULL, NULL, fpos_a, fnrm_a, NULL }, b = { NULL, NULL, fpos_b, fnrm_b, NULL };
	skin_dqbs_fixed(&soa, &bones, 0, N, &a);
	memset(fpos_b, 0, sizeof fpos_b);
	run_sliced(SKIN_DQBS_FIXED, &b);
	long dp = test_max_diff_i32(fpos_a, fpos_b, 3 * N), dn = test_max_diff_i32(fnrm_a, fnrm_b, 3 * N);
	print_message("%s fixed DQBS vs scalar fixed: positions %ld LSB, normals %ld LSB (Q16)\n",
		      skin_simd_name(), dp, dn);
	assert_int_equal(dp, 0);
	assert_int_equal(dn, 0);
}

/* A blend whose squared norm lies just below 1.0 (2^60 in Q60): scaled by
 * 4 it rounds up to 2^62, which once pushed X to 2^32 and broke the SIMD
 * rsqrt. Every vertex here has a single influence on bone 0. */
static void test_fixed_norm_just_below_one(void **state)
{
	(void)state;
	setup_scene();
	for (int v = 0; v < soa.padded; v++)
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			soa.bone[k][v] = k ? SKIN_IDENTITY_BONE : 0;
			soa.fweight[k][v] = k ? 0 : FX_W15_ONE;
		}
	fx_dq d = { { (1 << 30) - 1, 46340, 0, 0 }, { 0, 3 << 16, -(5 << 16), 1 << 16 } };
	bones.fdq[0] = d;
	skin_bones_derive(&bones);
	skin_out a = { NULL, NULL, fpos_a, fnrm_a, NULL }, b = { NULL, NULL, fpos_b, fnrm_b, NULL };
	skin_dqbs_fixed(&soa, &bones, 0, N, &a);
	run_sliced(SKIN_DQBS_FIXED, &b);
	assert_int_equal(test_max_diff_i32(fpos_a, fpos_b, 3 * N), 0);
	assert_int_equal(test_max_diff_i32(fnrm_a, fnrm_b, 3 * N), 0);
}

static void expect_fixed_same_as_scalar(void)
{
	skin_out a = { NULL, NULL, fpos_a, fnrm_a, NULL }, b = { NULL, NULL, fpos_b, fnrm_b, NULL };
	skin_dqbs_fixed(&soa, &bones, 0, N, &a);
	memset(fpos_b, 0, sizeof fpos_b);
	run_sliced(SKIN_DQBS_FIXED, &b);
	assert_int_equal(test_max_diff_i32(fpos_a, fpos_b, 3 * N), 0);
	assert_int_equal(test_max_diff_i32(fnrm_a, fnrm_b, 3 * N), 0);
}

/* Weights skin_soa_load never writes but a caller may (a full weight,
 * more than int16 holds, outside slot 0; weights summing past 1.0, which
 * would overflow 32-bit sums): the SIMD kernel must still agree. */
static void test_fixed_weights_outside_invariants(void **state)
{
	(void)state;
	setup_scene();
	for (int v = 0; v < N; v += 3) {
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
			soa.fweight[k][v] = v % 2 ? 0 : FX_W15_ONE;
		soa.fweight[1 + v % 3][v] = FX_W15_ONE;
	}
	expect_fixed_same_as_scalar();
}

/* Blends far shorter than a unit quaternion (weights summing to a few
 * LSB: squared norms from 2^34 down to 0, the range where the reciprocal's
 * scaling shift is largest, and below it, where fx_dq_transform_blend
 * leaves the vertex as it is): the SIMD kernel must agree there too. */
static void test_fixed_short_blends(void **state)
{
	(void)state;
	setup_scene();
	for (int v = 0; v < N; v++)
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
			soa.fweight[k][v] = (fx_w15)(v % 7 > k ? 1 + v % 3 : 0);
	expect_fixed_same_as_scalar();
}

/* A bone whose translation saturated the dual part (|t| beyond the Q16
 * range): its components do not split into 16-bit halves, so the SIMD
 * kernel must fall back, not wrap. */
static void test_fixed_saturated_dual(void **state)
{
	(void)state;
	setup_scene();
	bones.fdq[3].dual.x = INT32_MAX;
	bones.fdq[5].dual.z = INT32_MIN;
	skin_bones_derive(&bones);
	expect_fixed_same_as_scalar();
}

/* Vertices the vector path cannot keep within 32 bits (a position 34,641
 * units from the origin, normals of length up to 2^31): where the scalar
 * kernel saturates, the SIMD kernel must hand them over rather than wrap. */
static void test_fixed_outside_envelope(void **state)
{
	(void)state;
	setup_scene();
	for (int v = 0; v < N; v += 5) {
		int32_t far = (v % 2 ? 20000 : -20000) * FX_POS_ONE;
		soa.fpx[v] = far; soa.fpy[v] = -far; soa.fpz[v] = far;
	}
	for (int v = 2; v < N; v += 11) {
		soa.fnx[v] = INT32_MAX; soa.fny[v] = INT32_MIN; soa.fnz[v] = INT32_MAX;
	}
	expect_fixed_same_as_scalar();
}

/* The compact kernels skin_run_compact picks agree with the portable
 * ones: positions to float rounding, snorm16 normals within a step. */
static void test_compact_kernels_match_scalar(void **state)
{
	(void)state;
	static char block[1 << 16] __attribute__((aligned(SKIN_ALIGN)));
	setup_scene();
	assert_true(skin_compact_bytes(N) <= sizeof block);
	skin_compact_attach(&compact, block, N);
	skin_compact_load(&compact, &soa);
	skin_out a = { pos_a, NULL, NULL, NULL, n16_a }, b = { pos_b, NULL, NULL, NULL, n16_b };
	for (int algo = SKIN_LBS; algo <= SKIN_DQBS; algo++) {
		if (algo == SKIN_LBS)
			skin_lbs_compact_scalar(&compact, &bones, 0, N, &a);
		else
			skin_dqbs_compact_scalar(&compact, &bones, 0, N, &a);
		memset(pos_b, 0, sizeof pos_b);
		skin_run_compact((skin_algo)algo, &compact, &bones, 0, 512, &b);
		skin_run_compact((skin_algo)algo, &compact, &bones, 512, N - 512, &b);
		double dp = test_max_diff(pos_a, pos_b, 3 * N);
		long dn = test_max_diff_i16(n16_a, n16_b, 3 * N);
		print_message("%s compact %s vs scalar compact: positions %.3g, normals %ld snorm16 steps\n",
			      skin_simd_name(), algo == SKIN_LBS ? "LBS" : "DQBS", dp, dn);
		assert_true(dp < 1e-4 && dn <= 2);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_float_kernels_match_scalar),
		cmocka_unit_test(test_fixed_kernel_matches_scalar),
		cmocka_unit_test(test_fixed_norm_just_below_one),
		cmocka_unit_test(test_fixed_weights_outside_invariants),
		cmocka_unit_test(test_fixed_short_blends),
		cmocka_unit_test(test_fixed_saturated_dual),
		cmocka_unit_test(test_fixed_outside_envelope),
		cmocka_unit_test(test_compact_kernels_match_scalar),
	};
	return cmocka_run_group_tests_name("skin_simd", tests, NULL, NULL);
}
