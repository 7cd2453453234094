/* A side branch (a thumb) in the mesh's own pose (bind_pose_ends.h), on a
 * made-up hand hanging down: a palm and fingers along the main chain, the
 * thumb's flesh beside the knuckles, partly behind them. The thumb turns
 * square to the main chain, toward the side its flesh is on (the
 * centroid of the flesh past the knuckles would lean it toward the
 * fingers); with no flesh beside a flat palm it is left as it was. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bind_pose_ends.h"
#include "test_parse.h"

#define DEG 0.017453292519943295f

static skel s;
static skel_pose pose;
static skel_roles roles;
static mesh m;
static float values[SKP_MAX_DOF];

/* A palm 2 long from (0, 10, 0) down to the knuckles at y 8, fingers 1
 * long below it; the thumb starts at the knuckles, leaning out to +x and
 * a little to depth_lean (+z: the front). */
static void hand(float depth_lean)
{
	char asf[1024];
	float t = sqrtf(1.0f + depth_lean * depth_lean + 1.0f);
	int n = snprintf(asf, sizeof asf,
			 ":root\n order TX TY TZ RX RY RZ\n position 0 10 0\n:bonedata\n"
			 " begin\n name palm\n direction 0 -1 0\n length 2\n axis 0 0 0 XYZ\n dof rx ry rz\n end\n"
			 " begin\n name fingers\n direction 0 -1 0\n length 1\n axis 0 0 0 XYZ\n dof rx rz\n end\n"
			 " begin\n name thumb\n direction %g %g %g\n length 0.8\n axis 0 0 0 XYZ\n dof rx ry rz\n end\n"
			 ":hierarchy\n begin\n root palm\n palm fingers thumb\n end\n",
			 (double)(1.0f / t), (double)(-1.0f / t), (double)(depth_lean / t));
	skp_error err;
	assert_int_equal(test_parse_asf(asf, (size_t)n, &s, &err), SKP_OK);
	memset(values, 0, sizeof values);
	memset(&roles, 0, sizeof roles);
	roles.up = vec3_make(0.0f, 1.0f, 0.0f);
	roles.side = vec3_make(1.0f, 0.0f, 0.0f);
	roles.depth = vec3_make(0.0f, 0.0f, 1.0f);
	roles.reach[1] = 1.0f;
	memset(&m, 0, sizeof m);
}

static void box(vec3 lo, vec3 hi, float step)
{
	for (float x = lo.x; x <= hi.x + 1e-4f; x += step)
		for (float y = lo.y; y <= hi.y + 1e-4f; y += step)
			for (float z = lo.z; z <= hi.z + 1e-4f; z += step)
				m.pos[m.vert_count++] = vec3_make(x, y, z);
}

static void palm_and_fingers(void)
{
	box(vec3_make(-0.5f, 7.0f, -0.2f), vec3_make(0.5f, 10.0f, 0.2f), 0.1f);
}

/* A flat palm: nothing beside the knuckles for a thumb. */
static void flat_palm(void)
{
	box(vec3_make(-0.5f, 7.0f, -0.05f), vec3_make(0.5f, 10.0f, 0.05f), 0.1f);
}

static vec3 thumb_dir(void)
{
	int b = skel_find(&s, "thumb");
	fk_pose(&s, values, &pose);
	return vec3_normalize(vec3_sub(pose.tip[b], pose.head[b]));
}

static float angle_deg(vec3 a, vec3 b)
{
	return acosf(fmaxf(-1.0f, fminf(1.0f, vec3_dot(a, b)))) / DEG;
}

/* The thumb square to the palm (which leans toward the thumb's flesh; the
 * fingers, turned after the thumb, lean back), toward the front (side +1)
 * or the back. */
static void square_to_palm(float side)
{
	vec3 d = thumb_dir();
	vec3 chain = vec3_normalize(vec3_sub(pose.tip[1], pose.head[1]));
	if (fabsf(angle_deg(d, chain) - 90.0f) > 0.5f || side * d.z < 0.95f)
		fail_msg("the thumb points (%g %g %g), the palm (%g %g %g): not square to it toward %s",
			 (double)d.x, (double)d.y, (double)d.z, (double)chain.x, (double)chain.y, (double)chain.z,
			 side > 0.0f ? "the front" : "the back");
}

static void test_thumb_square_to_the_front(void **state)
{
	(void)state;
	hand(0.2f);
	palm_and_fingers();
	box(vec3_make(-0.2f, 7.4f, 0.5f), vec3_make(0.2f, 8.6f, 1.5f), 0.1f);
	fk_pose(&s, values, &pose);
	assert_true(bind_guess_ends(&s, &roles, &m, 1, values, &pose) > 0);
	square_to_palm(1.0f);
}

static void test_thumb_square_to_the_back(void **state)
{
	(void)state;
	hand(-0.2f);
	palm_and_fingers();
	box(vec3_make(-0.2f, 7.4f, -1.5f), vec3_make(0.2f, 8.6f, -0.5f), 0.1f);
	fk_pose(&s, values, &pose);
	assert_true(bind_guess_ends(&s, &roles, &m, 1, values, &pose) > 0);
	square_to_palm(-1.0f);
}

static void test_no_flesh_beside_no_turn(void **state)
{
	(void)state;
	hand(0.2f);
	flat_palm();
	vec3 before = thumb_dir();
	fk_pose(&s, values, &pose);
	bind_guess_ends(&s, &roles, &m, 1, values, &pose);
	vec3 after = thumb_dir();
	if (angle_deg(after, before) > 0.1f)
		fail_msg("the thumb turned from (%g %g %g) to (%g %g %g)", (double)before.x, (double)before.y,
			 (double)before.z, (double)after.x, (double)after.y, (double)after.z);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_thumb_square_to_the_front),
		cmocka_unit_test(test_thumb_square_to_the_back),
		cmocka_unit_test(test_no_flesh_beside_no_turn),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
