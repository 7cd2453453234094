/* Joints named for people from the bones' roles: CMU's ASF, the CMU BVH's
 * other names, HDM05 and endorphin, and a skeleton whose bones say
 * nothing (sides from where the joints lie). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "asf.h"
#include "skel_joints.h"
#include "test_parse.h"
#include "test_paths.h"
#include "test_skel.h"

static skel s;
static skel_pose p;
static skel_joints j;

static void expect(const char *bone, const char *want)
{
	char buf[32];
	int b = skel_find(&s, bone);
	if (b < 0)
		fail_msg("no bone %s", bone);
	skel_joint_name(&j, b, buf, sizeof buf);
	if (strcmp(buf, want))
		fail_msg("%s: got \"%s\", want \"%s\"", bone, buf, want);
}

static void load_asf(const char *path)
{
	skp_error err;
	if (test_parse_asf_file(path, &s, &err) != SKP_OK)
		fail_msg("%s: %s", path, err.msg);
	fk_pose(&s, NULL, &p);
	skel_joints_find(&s, &p, &j);
}

static void test_cmu(void **state)
{
	(void)state;
	load_asf("assets/cmu/02.asf");
	expect("lradius", "LEFT ELBOW");
	expect("rradius", "RIGHT ELBOW");
	expect("lwrist", "LEFT WRIST");
	expect("lhumerus", "LEFT SHOULDER");
	expect("rclavicle", "RIGHT COLLAR BONE");
	expect("lhand", "LEFT HAND");
	expect("lthumb", "LEFT THUMB");
	expect("rfemur", "RIGHT HIP");
	expect("ltibia", "LEFT KNEE");
	expect("rfoot", "RIGHT ANKLE");
	expect("ltoes", "LEFT TOES");
	expect("lhipjoint", "PELVIS");
	expect("head", "NECK");
	expect("upperneck", "NECK");
	expect("root", "HIPS");
}

static void test_other_names(void **state)
{
	(void)state;
	const char *path = test_data_path("mocap/cmu_bvh/131_01.bvh");
	if (!path)
		skip();
	size_t n;
	char *text = test_read_file(path, &n);
	skp_error err;
	assert_non_null(text);
	assert_true(test_stream_bvh(text, n, &s, &err, NULL, NULL) >= 0);
	free(text);
	fk_pose(&s, NULL, &p);
	skel_joints_find(&s, &p, &j);
	expect("LeftElbow", "LEFT ELBOW");
	expect("RightShoulder", "RIGHT SHOULDER");
	expect("LeftCollar", "LEFT COLLAR BONE");
	expect("RightWrist", "RIGHT WRIST");
	expect("LeftHip", "LEFT HIP");
	expect("RightKnee", "RIGHT KNEE");
	expect("LeftAnkle", "LEFT ANKLE");
}

static void test_endorphin(void **state)
{
	(void)state;
	const char *path = test_data_path("mocap/endorphin/skeleton.asf");
	if (!path)
		skip();
	load_asf(path);
	for (int b = 1; b < s.count; b++) {
		char buf[32];
		skel_joint_name(&j, b, buf, sizeof buf);
		const char *n = s.bone[b].name;
		if (strstr(n, "Elbow") && !strstr(buf, "ELBOW"))
			fail_msg("%s named %s", n, buf);
		if (strstr(n, "Twist") && !strstr(buf, "FOREARM"))
			fail_msg("%s named %s", n, buf);
		if (strstr(n, "Wrist") && !strstr(buf, "WRIST"))
			fail_msg("%s named %s", n, buf);
		if (strstr(n, "Knee") && !strstr(buf, "KNEE"))
			fail_msg("%s named %s", n, buf);
		if (!strncmp(n, "Left", 4) && strstr(buf, "RIGHT"))
			fail_msg("%s named %s", n, buf);
	}
}

/* Bones named a, b, c...: the elbow is found by the limb's shape, the side
 * by where it lies (+x is the left of a body facing +z). */
static void test_sides_from_place(void **state)
{
	(void)state;
	memset(&s, 0, sizeof s);
	memset(&p, 0, sizeof p);
	int root = test_skel_add_bone(&s, &p, "root", -1, vec3_make(0, 10, 0), vec3_make(0, 10, 0));
	int sp = test_skel_add_bone(&s, &p, "a", root, vec3_make(0, 10, 0), vec3_make(0, 15, 0));
	int hd = test_skel_add_bone(&s, &p, "b", sp, vec3_make(0, 15, 0), vec3_make(0, 17, 0));
	(void)hd;
	int names = 0;
	for (int side = -1; side <= 1; side += 2) {
		const char *nm[7] = { "c", "d", "e", "f", "g", "h", "i" };
		int c = test_skel_add_bone(&s, &p, nm[names++], sp, vec3_make(0, 14.5f, 0), vec3_make(side * 1.0f, 14.5f, 0));
		int u = test_skel_add_bone(&s, &p, nm[names++], c, vec3_make(side * 1.0f, 14.5f, 0), vec3_make(side * 4.0f, 14.5f, 0));
		test_skel_add_bone(&s, &p, nm[names++], u, vec3_make(side * 4.0f, 14.5f, 0), vec3_make(side * 6.5f, 14.5f, 0));
		names = 3 * (side > 0) + 3;
	}
	for (int side = -1; side <= 1; side += 2) {
		int t = test_skel_add_bone(&s, &p, side < 0 ? "t1" : "t2", root, vec3_make(side * 1.0f, 10, 0), vec3_make(side * 1.0f, 5, 0));
		test_skel_add_bone(&s, &p, side < 0 ? "s1" : "s2", t, vec3_make(side * 1.0f, 5, 0), vec3_make(side * 1.0f, 0.5f, 0));
	}
	skel_joints_find(&s, &p, &j);
	expect("e", "RIGHT ELBOW");
	expect("d", "RIGHT SHOULDER");
	expect("s2", "LEFT KNEE");
	expect("t1", "RIGHT HIP");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cmu),
		cmocka_unit_test(test_other_names),
		cmocka_unit_test(test_endorphin),
		cmocka_unit_test(test_sides_from_place),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
