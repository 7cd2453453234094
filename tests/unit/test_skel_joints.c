/* Joints named for people from the bones' roles: CMU's ASF, the CMU BVH's
 * other names, HDM05 and endorphin, and a skeleton whose bones say
 * nothing (sides from where the joints lie); how far they turned, as a
 * visitor would measure it. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
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

/* ---- how far a joint turned, as the close-up says it ----
 * A figure bound as the default show's body stands (the CMU skeleton
 * posed to MakeHuman's mesh): the arms in an A-pose, 39 degrees out from hanging, the elbows bent
 * 47 degrees forward, the thighs hanging. The poses turn its bones in
 * world axes, each bone's motion given since the bind pose. */
static skel_pose bind_p, pose_p;
static int rfemur, rtibia, lhumerus, lwrist, rhumerus, rradius, neck;

static int add(const char *name, int parent, vec3 head, vec3 dir, float len)
{
	vec3 tip = vec3_add(head, vec3_scale(vec3_normalize(dir), len));
	int b = test_skel_add_bone(&s, &bind_p, name, parent, head, tip);
	bind_p.rot[b] = (quat){ 1.0f, 0.0f, 0.0f, 0.0f };
	s.eval_order[b] = b;
	return b;
}

/* An upper arm out degrees from hanging, to the body's left (+x) when
 * side is 1, its right when -1. */
static vec3 arm_dir(float side, float out)
{
	float o = out * (float)M_PI / 180.0f;
	return vec3_make(side * sinf(o), -cosf(o), 0.0f);
}

static void build_figure(void)
{
	memset(&s, 0, sizeof s);
	memset(&bind_p, 0, sizeof bind_p);
	int root = add("root", -1, vec3_make(0, 10, 0), vec3_make(0, 1, 0), 0.0f);
	bind_p.tip[root] = bind_p.head[root];
	int back = add("lowerback", root, vec3_make(0, 10, 0), vec3_make(0, 1, 0), 4.5f);
	int thorax = add("thorax", back, vec3_make(0, 14.5f, 0), vec3_make(0, 1, 0), 0.5f);
	neck = add("lowerneck", thorax, vec3_make(0, 15, 0), vec3_make(0, 1, 0), 1.0f);
	add("head", neck, vec3_make(0, 16, 0), vec3_make(0, 1, 0), 1.5f);
	for (int side = -1; side <= 1; side += 2) {
		float x = (float)side;
		int cl = add(side > 0 ? "lclavicle" : "rclavicle", thorax, vec3_make(0, 14.5f, 0), vec3_make(x, 0, 0),
			     1.5f);
		vec3 sh = bind_p.tip[cl];
		int hu = add(side > 0 ? "lhumerus" : "rhumerus", cl, sh, arm_dir(x, 39.0f), 3.0f);
		vec3 el = bind_p.tip[hu];
		/* the forearm 47 degrees off the upper arm, forward */
		vec3 up = vec3_normalize(vec3_sub(bind_p.tip[hu], bind_p.head[hu]));
		float a = 47.0f * (float)M_PI / 180.0f;
		vec3 fore = vec3_add(vec3_scale(up, cosf(a)), vec3_make(0, 0, sinf(a)));
		int ra = add(side > 0 ? "lradius" : "rradius", hu, el, fore, 2.5f);
		int wr = add(side > 0 ? "lwrist" : "rwrist", ra, bind_p.tip[ra], fore, 0.3f);
		add(side > 0 ? "lhand" : "rhand", wr, bind_p.tip[wr], fore, 0.7f);
		if (side > 0)
			lhumerus = hu, lwrist = wr;
		else
			rhumerus = hu, rradius = ra;
	}
	for (int side = -1; side <= 1; side += 2) {
		float x = (float)side;
		int hj = add(side > 0 ? "lhipjoint" : "rhipjoint", root, vec3_make(0, 10, 0), vec3_make(x, -0.5f, 0),
			     1.1f);
		int fe = add(side > 0 ? "lfemur" : "rfemur", hj, bind_p.tip[hj], vec3_make(0, -1, 0), 4.5f);
		int ti = add(side > 0 ? "ltibia" : "rtibia", fe, bind_p.tip[fe], vec3_make(0, -1, 0), 4.0f);
		add(side > 0 ? "lfoot" : "rfoot", ti, bind_p.tip[ti], vec3_make(0, 0, 1), 1.0f);
		if (side < 0)
			rfemur = fe, rtibia = ti;
	}
	skel_joints_find(&s, &bind_p, &j);
	assert_true(j.biped);
}

/* The pose as bound; then pose_turn turns a bone and all below it by q
 * about its head. */
static void pose_bind(void)
{
	pose_p = bind_p;
}

static int below(int b, int top)
{
	for (; b >= 0; b = s.bone[b].parent)
		if (b == top)
			return 1;
	return 0;
}

static void pose_turn(int top, quat q)
{
	vec3 pivot = pose_p.head[top];
	for (int b = 0; b < s.count; b++) {
		if (!below(b, top))
			continue;
		pose_p.head[b] = vec3_add(pivot, quat_rotate(q, vec3_sub(pose_p.head[b], pivot)));
		pose_p.tip[b] = vec3_add(pivot, quat_rotate(q, vec3_sub(pose_p.tip[b], pivot)));
		pose_p.rot[b] = quat_mul(q, pose_p.rot[b]);
	}
}

/* Turns bone b (and all below it) so that it points along dir, the
 * shortest way. */
static void pose_aim(int b, vec3 dir)
{
	vec3 from = vec3_normalize(vec3_sub(pose_p.tip[b], pose_p.head[b])), to = vec3_normalize(dir);
	vec3 axis = vec3_cross(from, to);
	float sn = vec3_length(axis), c = vec3_dot(from, to);
	if (sn < 1e-6f)
		return;
	pose_turn(b, quat_from_axis_angle(vec3_scale(axis, 1.0f / sn), atan2f(sn, c)));
}

static void expect_turn(int bone, const char *want_name, const char *want_note)
{
	char name[48], note[32];
	skel_joint_turn t;
	int deg, named = skel_joint_turning(&s, &j, &bind_p, &pose_p, bone, &t);
	skel_joint_name(&j, named, name, sizeof name);
	skel_joint_turn_say(t, note, sizeof note, &deg);
	if (strcmp(name, want_name) || strcmp(note, want_note))
		fail_msg("%s: got %s \"%s\" (bend %.1f, twist %.1f, swing %.1f), want %s \"%s\"", s.bone[bone].name,
			 name, note, (double)t.bend, (double)t.twist, (double)t.swing, want_name, want_note);
}

/* The tour's curl: the upper arm hanging, the forearm folded 150 degrees
 * from it. Bound bent 47, the swing since the bind pose is 103: what the
 * close-up said. */
static void test_turn_elbow_curl(void **state)
{
	(void)state;
	build_figure();
	pose_bind();
	pose_aim(rhumerus, vec3_make(0, -1, 0));
	vec3 fore = vec3_make(0, -cosf(150.0f * (float)M_PI / 180.0f), sinf(150.0f * (float)M_PI / 180.0f));
	pose_aim(rradius, fore);
	expect_turn(rradius, "RIGHT ELBOW", "BENT 150 DEG");
	/* straightened: nothing to say; as bound, bent */
	pose_aim(rradius, vec3_make(0, -1, 0));
	expect_turn(rradius, "RIGHT ELBOW", "");
	pose_bind();
	expect_turn(rradius, "RIGHT ELBOW", "BENT 47 DEG");
	/* the whole body turned a quarter (the tour's profile): the same */
	pose_bind();
	pose_aim(rhumerus, vec3_make(0, -1, 0));
	pose_aim(rradius, fore);
	pose_turn(0, quat_from_axis_angle(vec3_make(0, 1, 0), (float)M_PI / 2));
	expect_turn(rradius, "RIGHT ELBOW", "BENT 150 DEG");
}

/* The arm raised from the A-pose to 80 degrees above the horizontal: 170
 * from hanging at the side (the swing since the bind pose, 131). */
static void test_turn_shoulder_raised(void **state)
{
	(void)state;
	build_figure();
	pose_bind();
	float a = 170.0f * (float)M_PI / 180.0f;
	pose_aim(lhumerus, vec3_make(sinf(a), -cosf(a), 0));
	expect_turn(lhumerus, "LEFT SHOULDER", "BENT 170 DEG");
}

/* A high march step: the thigh 115 degrees forward of hanging, the knee
 * bent 100. */
static void test_turn_hip_knee(void **state)
{
	(void)state;
	build_figure();
	pose_bind();
	float a = 115.0f * (float)M_PI / 180.0f, k = 15.0f * (float)M_PI / 180.0f;
	pose_aim(rfemur, vec3_make(0, -cosf(a), sinf(a)));
	pose_aim(rtibia, vec3_make(0, -cosf(k), sinf(k)));
	expect_turn(rfemur, "RIGHT HIP", "BENT 115 DEG");
	expect_turn(rtibia, "RIGHT KNEE", "BENT 100 DEG");
	/* the whole body turned a quarter and leaning 20 degrees forward:
	 * hanging leans with it */
	pose_turn(0, quat_from_axis_angle(vec3_make(1, 0, 0), 20.0f * (float)M_PI / 180.0f));
	pose_turn(0, quat_from_axis_angle(vec3_make(0, 1, 0), (float)M_PI / 2));
	expect_turn(rfemur, "RIGHT HIP", "BENT 115 DEG");
	expect_turn(rtibia, "RIGHT KNEE", "BENT 100 DEG");
}

/* Twists are since the bind pose, about the bone: the forearm's half turn
 * (the candy wrapper) and the neck's 45 degrees. */
static void test_turn_twists(void **state)
{
	(void)state;
	build_figure();
	pose_bind();
	vec3 fore = vec3_normalize(vec3_sub(pose_p.tip[lwrist], pose_p.head[lwrist]));
	pose_turn(lwrist, quat_from_axis_angle(fore, (float)M_PI));
	expect_turn(lwrist, "LEFT WRIST", "TWISTED 180 DEG");
	pose_bind();
	pose_turn(neck, quat_from_axis_angle(vec3_make(0, 1, 0), -45.0f * (float)M_PI / 180.0f));
	expect_turn(neck, "NECK", "TWISTED 45 DEG");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cmu),
		cmocka_unit_test(test_other_names),
		cmocka_unit_test(test_endorphin),
		cmocka_unit_test(test_sides_from_place),
		cmocka_unit_test(test_turn_elbow_curl),
		cmocka_unit_test(test_turn_shoulder_raised),
		cmocka_unit_test(test_turn_hip_knee),
		cmocka_unit_test(test_turn_twists),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
