/* The thinnest cross-section past a bone's middle (bind_pose_narrow.h),
 * on made-up limbs: a forearm thinning to a wrist then widening into a
 * hand, its bone off the flesh's axis, gives the wrist's centre; a limb
 * thinning all the way (no waist) gives none. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "bind_pose_narrow.h"

#define RING 16

static mesh m;
static skel_pose pose;

/* Rings across x from 0 to 14, radius radius(x), centred at (x, dy, 0). */
static void limb(float (*radius)(float), float dy)
{
	memset(&m, 0, sizeof m);
	for (float x = 0.0f; x <= 14.0f; x += 0.1f)
		for (int k = 0; k < RING; k++) {
			float a = 6.2831853f * (float)k / RING, r = radius(x);
			m.pos[m.vert_count++] = vec3_make(x, dy + r * cosf(a), r * sinf(a));
		}
	memset(&pose, 0, sizeof pose);
	pose.head[1] = vec3_make(0.0f, 0.0f, 0.0f);
	pose.tip[1] = vec3_make(10.0f, 0.0f, 0.0f);
}

static float forearm_and_hand(float x)
{
	return x < 10.5f ? 1.5f - 0.1f * x : fminf(1.5f, 0.45f + 0.7f * (x - 10.5f));
}

static float cone(float x)
{
	return 2.0f - 0.12f * x;
}

static void test_wrist_found(void **state)
{
	(void)state;
	limb(forearm_and_hand, 0.5f);
	vec3 at;
	assert_true(bind_guess_narrowest(&m, &pose, 1, &at));
	assert_true(fabsf(at.x - 10.5f) < 0.5f);
	assert_true(fabsf(at.y - 0.5f) < 0.05f);
	assert_true(fabsf(at.z) < 0.05f);
}

static void test_no_waist_no_wrist(void **state)
{
	(void)state;
	limb(cone, 0.0f);
	vec3 at;
	assert_false(bind_guess_narrowest(&m, &pose, 1, &at));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_wrist_found),
		cmocka_unit_test(test_no_waist_no_wrist),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
