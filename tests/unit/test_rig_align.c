/* Putting joints on joints (app/import/rig_align.c): a known turn, scale
 * and move is found again from the points it made, exactly for any turn
 * and snapped to a quarter-turn combination near one; degenerate inputs
 * fail. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "rig_align.h"
#include "test_dref.h"
#include "test_rng.h"

#define N 12

static void make_points(vec3 *from, quat rot, float scale, vec3 offset, float noise, vec3 *to)
{
	for (int i = 0; i < N; i++) {
		from[i] = vec3_make((float)test_rng_range(-1, 1), (float)test_rng_range(-1, 1),
				    (float)test_rng_range(-1, 1));
		to[i] = vec3_add(vec3_scale(quat_rotate(rot, from[i]), scale), offset);
		to[i] = vec3_add(to[i], vec3_scale(rand_axis(), noise * (float)test_rng_range(0, 1)));
	}
}

static void test_any_turn(void **state)
{
	(void)state;
	test_rng_seed(7);
	int checked = 0;
	for (int k = 0; k < 50; k++) {
		vec3 from[N], to[N];
		/* turns 25..180 degrees: never snapped */
		quat rot = quat_from_axis_angle(rand_axis(), (float)test_rng_range(0.45, 3.14));
		float scale = (float)test_rng_range(0.01, 100.0);
		vec3 offset = rand_vec(50.0);
		make_points(from, rot, scale, offset, 0.0f, to);
		rig_align al;
		skp_error err;
		assert_int_equal(rig_align_fit(from, to, N, &al, &err), SKP_OK);
		if (al.snapped)
			continue;   /* a random axis near a quarter-turn combination */
		close_to(al.scale, scale, 1e-4 * scale, 0, "scale");
		for (int i = 0; i < N; i++)
			vec_close(rig_align_point(&al, from[i]), dv_f(to[i]), 1e-4 * scale + 1e-4, 0, "point");
		assert_true(al.rms <= 1e-4 * scale + 1e-4);
		checked++;
	}
	assert_true(checked >= 40);
}

static void test_snapped(void **state)
{
	(void)state;
	test_rng_seed(11);
	/* a Z-up file turned to Y up and 180 degrees about Y, points off by noise */
	quat exact = quat_mul(quat_from_axis_angle(vec3_make(0, 1, 0), (float)M_PI),
			      quat_from_axis_angle(vec3_make(1, 0, 0), (float)(-M_PI / 2)));
	quat tilted = quat_mul(quat_from_axis_angle(vec3_make(0, 0, 1), 0.1f), exact);
	vec3 from[N], to[N];
	make_points(from, tilted, 30.0f, vec3_make(1, 2, 3), 0.5f, to);
	rig_align al;
	skp_error err;
	assert_int_equal(rig_align_fit(from, to, N, &al, &err), SKP_OK);
	assert_true(al.snapped);
	assert_true(fabsf(al.snap_deg - 5.73f) < 2.0f);
	assert_true(fabsf(quat_dot(al.rot, exact)) > 0.99999f);
	close_to(al.turn_deg, 180.0, 0.01, 0, "turn");
	close_to(al.scale, 30.0, 1.0, 0, "scale");
}

static void test_degenerate(void **state)
{
	(void)state;
	vec3 p[3] = { { 1, 2, 3 }, { 1, 2, 3 }, { 1, 2, 3 } };
	rig_align al;
	skp_error err;
	assert_int_equal(rig_align_fit(p, p, 2, &al, &err), SKP_ERR_RANGE);
	assert_int_equal(rig_align_fit(p, p, 3, &al, &err), SKP_ERR_RANGE);
	vec3 nan_p[3] = { { NAN, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
	assert_int_equal(rig_align_fit(nan_p, nan_p, 3, &al, &err), SKP_ERR_RANGE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_any_turn),
		cmocka_unit_test(test_snapped),
		cmocka_unit_test(test_degenerate),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
