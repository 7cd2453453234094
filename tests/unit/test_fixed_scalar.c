/* Scalar fixed-point operations (fixed.h) against double: the Q30 multiply
 * (rounded, saturating), the integer square root (exact), the reciprocal
 * square root and reciprocal of Q60 values (within 2^-29), the conversions
 * from float (rounding, saturation, NaN) and back, and weights turned into
 * Q15 summing to exactly one. The measured maxima are printed. Quaternions
 * and DQ skinning: test_fixed.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "fixed.h"
#include "fixed_convert.h"
#include "test_fx.h"
#include "test_rng.h"

#define N_RANDOM 5000
#define Q30 1073741824.0
#define POS ((double)FX_POS_ONE)

/* error slots (test_fx.h) */
enum { E_MUL, E_RSQRT, E_COUNT };
_Static_assert(E_COUNT <= TEST_FX_SLOTS, "more slots than test_fx keeps");

static void test_mul_q30(void **state)
{
	(void)state;
	for (int i = 0; i < 20 * N_RANDOM; i++) {
		/* a in [-1, 1], b anything: the result must be a * b rounded */
		int32_t a = test_fx_raw(test_rng_range(-1, 1), Q30), b = (int32_t)test_rng_u32();
		double want = test_fx_q30d(a) * b;
		test_fx_track(E_MUL, fx_mul_q30(a, b), want, 0.5 + 1e-6, "fx_mul_q30 (LSB of b's format)");
	}
	assert_int_equal(fx_mul_q30(FX_Q30_ONE, 12345), 12345);
	assert_int_equal(fx_mul_q30(FX_Q30_ONE / 2, 3), 2);    /* 1.5 rounds up */
	assert_int_equal(fx_mul_q30(FX_Q30_ONE / 2, -3), -1);  /* -1.5 rounds up too */
	assert_int_equal(fx_mul_q30(INT32_MIN, INT32_MIN), INT32_MAX);  /* 4 saturates */
	print_message("fx_mul_q30: max error %.3g LSB (bound 0.5)\n", test_fx_max_err[E_MUL]);
}

static void test_isqrt_rsqrt(void **state)
{
	(void)state;
	const uint64_t edge[] = { 0, 1, 2, 3, 4, 5, 15, 16, 17, UINT32_MAX, (uint64_t)UINT32_MAX * UINT32_MAX,
				  (uint64_t)UINT32_MAX * UINT32_MAX - 1, UINT64_MAX, UINT64_MAX - 1,
				  (uint64_t)1 << 62, ((uint64_t)1 << 62) - 1 };
	for (size_t i = 0; i < sizeof edge / sizeof edge[0] + 20 * N_RANDOM; i++) {
		uint64_t x = i < sizeof edge / sizeof edge[0] ? edge[i] : test_rng_u64() >> (test_rng_u32() % 64);
		unsigned __int128 s = fx_isqrt64(x);
		if (!(s * s <= x && (s + 1) * (s + 1) > x))
			fail_msg("isqrt(%llu) = %llu", (unsigned long long)x, (unsigned long long)s);
	}
	double worst = 0;
	for (int i = 0; i < 20 * N_RANDOM; i++) {
		/* squared norms from 2^-30 up to just below 4 (Q60) */
		uint64_t x = (test_rng_u64() >> 2) >> (test_rng_u32() % 61);
		if (x == 0)
			continue;
		int shift;
		uint32_t m = fx_rsqrt_q60(x, &shift);
		double want = 1.0 / sqrt((double)x / 1152921504606846976.0);
		double got = ldexp(m, -shift);
		double rel = fabs(got / want - 1.0);
		if (rel > worst)
			worst = rel;
		/* Newton in Q31 with a Q30 copy of x: within two LSBs of Q31 */
		assert_true(rel < 2.0 / Q30);
		assert_true(m >= (1u << 30) && m < (1u << 31) && shift >= 1 && shift <= 31);
	}
	test_fx_max_err[E_RSQRT] = worst;
	int shift = 7;
	assert_int_equal(fx_rsqrt_q60(0, &shift), 0);
	assert_int_equal(shift, 0);
	assert_int_equal(fx_rsqrt_q60((uint64_t)1 << 62, &shift), 0);
	print_message("fx_isqrt64 exact; fx_rsqrt_q60: max relative error %.3g (bound 2^-29 = 1.9e-9)\n", worst);
}

static void test_recip(void **state)
{
	(void)state;
	double worst = 0;
	for (int i = 0; i < 20 * N_RANDOM + 4; i++) {
		/* squared norms from 2^-60 up to just below 2 (Q60), the ends
		 * of the range and of the seed's segments among them */
		uint64_t x = i == 0 ? 1 : i == 1 ? ((uint64_t)1 << 61) - 1 : i == 2 ? (uint64_t)1 << 60
			   : i == 3 ? ((uint64_t)9 << 57) - 1 : (test_rng_u64() >> 3) >> (test_rng_u32() % 61);
		if (x == 0)
			continue;
		int e;
		uint32_t y = fx_recip_q60(x, &e);
		double want = 1152921504606846976.0 / (double)x, got = ldexp(y, e - 31);
		double rel = fabs(got / want - 1.0);
		if (rel > worst)
			worst = rel;
		/* X cut to Q30 (up to 2^-30) and Newton in Q31 */
		assert_true(rel < 2.0 / Q30);
		assert_true(y >= (1u << 30) && y <= (1u << 31) && e >= 0 && e <= 60);
	}
	int e = 7;
	assert_int_equal(fx_recip_q60(0, &e), 0);
	assert_int_equal(e, 0);
	assert_int_equal(fx_recip_q60((uint64_t)1 << 61, &e), 0);
	assert_int_equal(fx_recip_q60(UINT64_MAX, &e), 0);
	print_message("fx_recip_q60: max relative error %.3g (bound 2^-29 = 1.9e-9)\n", worst);
}

static void test_convert(void **state)
{
	(void)state;
	assert_int_equal(fx_q30_from_float(1.0f), FX_Q30_ONE);
	assert_int_equal(fx_q30_from_float(-1.0f), -FX_Q30_ONE);
	assert_int_equal(fx_q30_from_float(2.0f), INT32_MAX);
	assert_int_equal(fx_q30_from_float(-2.0f), INT32_MIN);
	assert_int_equal(fx_q30_from_float(1e30f), INT32_MAX);
	assert_int_equal(fx_q30_from_float(NAN), 0);
	assert_int_equal(fx_pos_from_float(1.5f), 3 * FX_POS_ONE / 2);
	assert_int_equal(fx_pos_from_float(40000.0f), INT32_MAX);
	assert_int_equal(fx_pos_from_float(-40000.0f), INT32_MIN);
	/* ties away from zero, otherwise nearest */
	assert_int_equal(fx_pos_from_float(0.5f / FX_POS_ONE), 1);
	assert_int_equal(fx_pos_from_float(-0.5f / FX_POS_ONE), -1);
	assert_int_equal(fx_pos_from_float(0.49f / FX_POS_ONE), 0);
	assert_int_equal(fx_w15_from_float(1.0f), 32768);
	assert_int_equal(fx_w15_from_float(2.0f), 32768);
	assert_int_equal(fx_w15_from_float(-1.0f), 0);
	for (int i = 0; i < N_RANDOM; i++) {
		float f = (float)test_rng_range(-1000, 1000);
		assert_true(fabs(fx_pos_to_double(fx_pos_from_float(f)) - f) <= 0.5 / POS);
		float u = (float)test_rng_range(-1, 1);
		assert_true(fabs(fx_q30_to_double(fx_q30_from_float(u)) - u) <= 0.5 / Q30);
		/* from 2^-7 up a float's ulp is a multiple of 2^-30: exact */
		if (fabsf(u) >= 1.0f / 128)
			assert_true(fx_q30_to_float(fx_q30_from_float(u)) == u);
	}
	dq d = dq_from_quat_trans(quat_from_axis_angle(vec3_make(0, 0, 1), 0.5f), vec3_make(10, 20, 30));
	fx_dq fd = fx_dq_from_dq(&d);
	dq back = fx_dq_to_dq(&fd);
	assert_true(fabs(back.real.z - d.real.z) < 1e-7 && fabs(back.dual.x - d.dual.x) < 1e-4);
}

static void test_weights(void **state)
{
	(void)state;
	fx_w15 out[8];
	const float thirds[3] = { 1, 1, 1 };
	assert_int_equal(fx_weights_from_float(thirds, out, 3), SKP_OK);
	assert_int_equal(out[0] + out[1] + out[2], 32768);
	const float one[1] = { 0.3f };
	assert_int_equal(fx_weights_from_float(one, out, 1), SKP_OK);
	assert_int_equal(out[0], 32768);
	const float zeros[2] = { 0, 0 }, neg[2] = { 1, -0.5f };
	assert_int_equal(fx_weights_from_float(zeros, out, 2), SKP_ERR_RANGE);
	assert_int_equal(out[0], 32768);
	assert_int_equal(fx_weights_from_float(neg, out, 2), SKP_ERR_RANGE);

	for (int i = 0; i < N_RANDOM; i++) {
		int n = 1 + (int)(test_rng_u32() % 8);
		float w[8];
		double s = 0;
		for (int j = 0; j < n; j++) {
			/* include tiny and zero weights */
			w[j] = (test_rng_u32() % 5 == 0) ? 0.0f : (float)pow(10, test_rng_range(-6, 0));
			s += w[j];
		}
		if (s == 0)
			w[0] = 1, s = 1;
		assert_int_equal(fx_weights_from_float(w, out, n), SKP_OK);
		unsigned sum = 0;
		for (int j = 0; j < n; j++) {
			sum += out[j];
			assert_true(fabs(out[j] - w[j] / s * 32768) < 1.0);
		}
		assert_int_equal(sum, 32768);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_mul_q30, test_fx_rng_reset),
		cmocka_unit_test_setup(test_isqrt_rsqrt, test_fx_rng_reset),
		cmocka_unit_test_setup(test_recip, test_fx_rng_reset),
		cmocka_unit_test_setup(test_convert, test_fx_rng_reset),
		cmocka_unit_test_setup(test_weights, test_fx_rng_reset),
	};
	return cmocka_run_group_tests_name("fixed_scalar", tests, NULL, NULL);
}
