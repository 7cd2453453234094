/* Forward kinematics against hand-computed poses. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "fk.h"
#include "test_parse.h"

static skel s;
static skel_pose p;

static void near3(vec3 v, float x, float y, float z)
{
	if (fabsf(v.x - x) > 1e-5f || fabsf(v.y - y) > 1e-5f || fabsf(v.z - z) > 1e-5f)
		fail_msg("got (%g %g %g), want (%g %g %g)", v.x, v.y, v.z, x, y, z);
}

static void load(const char *asf)
{
	skp_error err;
	assert_int_equal(test_parse_asf(asf, strlen(asf), &s, &err), SKP_OK);
}

static const char *arm =
	":root\n order TX TY TZ RX RY RZ\n position 0 1 0\n:bonedata\n"
	" begin\n name upper\n direction 1 0 0\n length 2\n axis 0 0 0 XYZ\n dof rx ry rz\n end\n"
	" begin\n name lower\n direction 1 0 0\n length 1.5\n axis 0 0 90 XYZ\n dof rx rz\n end\n"
	":hierarchy\n begin\n root upper\n upper lower\n end\n";

static void test_rest_pose_follows_directions(void **state)
{
	(void)state;
	load(arm);
	fk_pose(&s, NULL, &p);
	near3(p.tip[0], 0, 1, 0);
	near3(p.head[1], 0, 1, 0);
	near3(p.tip[1], 2, 1, 0);
	near3(p.tip[2], 3.5f, 1, 0);
}

static void test_root_translation_and_rotation(void **state)
{
	(void)state;
	load(arm);
	float v[16] = { 0 };
	const float d = (float)(M_PI / 180.0);
	v[0] = 5; v[1] = 0; v[2] = -1;  /* TX TY TZ add to position */
	v[4] = 90 * d;                  /* RY: +X turns to -Z */
	fk_pose(&s, v, &p);
	near3(p.tip[0], 5, 1, -1);
	near3(p.tip[1], 5, 1, -3);
	near3(p.tip[2], 5, 1, -4.5f);
}

static void test_axis_conjugation(void **state)
{
	(void)state;
	load(arm);
	float v[16] = { 0 };
	const float d = (float)(M_PI / 180.0);
	/* lower's local frame is turned 90 deg about Z, so its local rx turns
	 * about world Y: +X goes to -Z for +90 */
	v[6 + 3] = 90 * d;
	fk_pose(&s, v, &p);
	near3(p.tip[2], 2, 1, -1.5f);
	/* and its rz stays about world Z */
	v[9] = 0; v[10] = 90 * d;
	fk_pose(&s, v, &p);
	near3(p.tip[2], 2, 2.5f, 0);
}

static void test_dof_order_first_applied_first(void **state)
{
	(void)state;
	load(arm);
	float v[16] = { 0 };
	const float d = (float)(M_PI / 180.0);
	/* upper: rx 90 then rz 90: X -> X (rx) -> Y (rz) */
	v[6] = 90 * d; v[8] = 90 * d;
	fk_pose(&s, v, &p);
	near3(p.tip[1], 0, 3, 0);
	/* ry 90 then rz 90: X -> -Z -> -Z */
	memset(v, 0, sizeof v);
	v[7] = 90 * d; v[8] = 90 * d;
	fk_pose(&s, v, &p);
	near3(p.tip[1], 0, 1, -2);
}

static void test_root_orientation_and_order(void **state)
{
	(void)state;
	/* order lists RZ before RY: RZ applied first. orientation turns the root
	 * frame 90 deg about Y, so the root's RX channel turns about world Z. */
	load(":root\n order RZ RY RX TX TY TZ\n axis XYZ\n orientation 0 90 0\n:bonedata\n"
	     " begin\n name a\n direction 0 0 -1\n length 1\n end\n:hierarchy\n begin\n root a\n end\n");
	float v[8] = { 0 };
	const float d = (float)(M_PI / 180.0);
	v[2] = 90 * d; /* RX */
	fk_pose(&s, v, &p);
	/* C Rx C^-1 with C = Ry(90): rotation about C*x = -Z by 90: -Z stays */
	near3(p.tip[1], 0, 0, -1);
	memset(v, 0, sizeof v);
	v[0] = 90 * d; /* RZ: conjugated to rotation about C*z = +X; -Z -> +Y */
	fk_pose(&s, v, &p);
	near3(p.tip[1], 0, 1, 0);
}

static void test_translation_and_length_channels(void **state)
{
	(void)state;
	load(":root\n:bonedata\n begin\n name a\n direction 0 1 0\n length 1\n axis 0 0 90 XYZ\n dof tx l\n end\n"
	     ":hierarchy\n begin\n root a\n end\n");
	float v[8] = { 0 };
	v[6] = 2;   /* tx in the bone's axis frame: local X is world Y */
	v[7] = 0.5f;
	fk_pose(&s, v, &p);
	near3(p.head[1], 0, 2, 0);
	near3(p.tip[1], 0, 3.5f, 0);
}

static void test_rotation_is_unit(void **state)
{
	(void)state;
	load(arm);
	float v[16];
	for (int i = 0; i < 16; i++)
		v[i] = (float)(i * 1.7 - 9.0);
	fk_pose(&s, v, &p);
	for (int b = 0; b < s.count; b++)
		assert_true(fabsf(quat_dot(p.rot[b], p.rot[b]) - 1.0f) < 1e-5f);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_rest_pose_follows_directions),
		cmocka_unit_test(test_root_translation_and_rotation),
		cmocka_unit_test(test_axis_conjugation),
		cmocka_unit_test(test_dof_order_first_applied_first),
		cmocka_unit_test(test_root_orientation_and_order),
		cmocka_unit_test(test_translation_and_length_channels),
		cmocka_unit_test(test_rotation_is_unit),
	};
	return cmocka_run_group_tests_name("fk", tests, NULL, NULL);
}
