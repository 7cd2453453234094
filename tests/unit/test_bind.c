/* Automatic weights (bind.h) on hand-made geometry, fitting, and the
 * weights CSV reader. The MakeHuman body bound to the CMU skeleton:
 * test_bind_makehuman.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bind.h"
#include "bind_fit.h"
#include "test_bind_points.h"
#include "test_parse.h"
#include "test_skel.h"
#include "weights_csv.h"

static skel s;
static skel_pose pose;
static bind_rig rig;
static skin_weights sw;

/* Exact box and ramp sizes: R = 0.2 L, h = 0.2 L. */
static const bind_params sharp = {
	.radius = 0.2f, .radius_min = 0.0f, .radius_max = 1.0f, .radius_cap = 1.0f, .blend = 0.2f,
};

static int add_bone(const char *name, int parent, vec3 head, vec3 tip)
{
	return test_skel_add_bone(&s, &pose, name, parent, head, tip);
}

static void start_skel(void)
{
	memset(&s, 0, sizeof s);
	memset(&pose, 0, sizeof pose);
	add_bone("root", -1, vec3_make(0, 0, 0), vec3_make(0, 0, 0));
}

/* root -> a (0,0,0)-(0,10,0) -> b (0,10,0)-(0,20,0): collinear, L = 10. */
static void two_bones(void)
{
	start_skel();
	add_bone("a", 0, vec3_make(0, 0, 0), vec3_make(0, 10, 0));
	add_bone("b", 1, vec3_make(0, 10, 0), vec3_make(0, 20, 0));
	bind_prepare(&rig, &s, &pose, &sharp);
}

static void bind_points(const vec3 *p, int n, bind_info *info)
{
	test_bind_points(&rig, p, n, &sw, info);
}

static void test_segments_and_ramps(void **state)
{
	(void)state;
	two_bones();
	assert_int_equal(rig.boxed, 2);
	assert_float_equal(rig.size, 20.0f, 1e-6f);
	assert_float_equal(rig.seg[1].radius, 2.0f, 1e-6f);
	assert_float_equal(rig.seg[1].half, 2.0f, 1e-6f);
	/* a's head meets nobody (the root has no box), b's tip is a free end */
	assert_int_equal(rig.seg[1].ramp_head, 0);
	assert_int_equal(rig.seg[1].ramp_tip, 1);
	assert_int_equal(rig.seg[2].ramp_head, 1);
	assert_int_equal(rig.seg[2].ramp_tip, 0);
	assert_float_equal(rig.seg[0].length, 0.0f, 0.0f);
}

/* The distance to a bone's segment, beside, before its head and past its
 * tip; bit for bit the root of its square (the nearest-bone searches
 * compare squares and take one root). */
static void test_segment_distance(void **state)
{
	(void)state;
	two_bones();
	const vec3 p[] = { { 3, 4, 0 }, { 0, -2, 0 }, { 0, 13, 4 }, { 1e-3f, 7.3f, -2.9f } };
	const float want[] = { 3.0f, 2.0f, 5.0f, 2.9f };
	for (int i = 0; i < 4; i++) {
		float d = bind_segment_distance(&rig.seg[1], p[i]), d2 = bind_segment_distance2(&rig.seg[1], p[i]);
		assert_float_equal(d, want[i], 1e-5f);
		assert_memory_equal(&d, &(float){ sqrtf(d2) }, sizeof d);
	}
}

static void test_mid_bone_gets_one(void **state)
{
	(void)state;
	two_bones();
	vec3 p[2] = { vec3_make(0, 5, 0), vec3_make(1.5f, 15, -1) };
	bind_info info;
	bind_points(p, 2, &info);
	assert_int_equal(sw.count[0], 1);
	assert_int_equal(sw.bone[0][0], 1);
	assert_float_equal(sw.weight[0][0], 1.0f, 1e-6f);
	assert_int_equal(sw.count[1], 1);
	assert_int_equal(sw.bone[1][0], 2);
	assert_float_equal(sw.weight[1][0], 1.0f, 1e-6f);
	assert_int_equal(info.fallback, 0);
}

static void test_joint_is_half_half(void **state)
{
	(void)state;
	two_bones();
	vec3 p[2] = { vec3_make(0, 10, 0), vec3_make(1, 10, 1) };
	bind_points(p, 2, NULL);
	for (int v = 0; v < 2; v++) {
		assert_int_equal(sw.count[v], 2);
		assert_float_equal(skin_weights_of(&sw, v, 1), 0.5f, 1e-6f);
		assert_float_equal(skin_weights_of(&sw, v, 2), 0.5f, 1e-6f);
	}
}

/* Past the joint by x (0 < x < h): a = 0.5 - x / 2h, b = 0.5 + x / 2h. */
static void test_ramp_past_joint_is_linear(void **state)
{
	(void)state;
	two_bones();
	const float x[2] = { 0.5f, 1.5f };
	vec3 p[2] = { vec3_make(0.3f, 10 + x[0], 0), vec3_make(0, 10 + x[1], -0.7f) };
	bind_points(p, 2, NULL);
	for (int v = 0; v < 2; v++) {
		float wa = 0.5f - x[v] / (2 * 2.0f), wb = 0.5f + x[v] / (2 * 2.0f);
		assert_float_equal(bind_segment_weight(&rig.seg[1], p[v], NULL), wa, 1e-6f);
		assert_float_equal(bind_segment_weight(&rig.seg[2], p[v], NULL), wb, 1e-6f);
		assert_float_equal(skin_weights_of(&sw, v, 1), wa, 1e-6f);
		assert_float_equal(skin_weights_of(&sw, v, 2), wb, 1e-6f);
		assert_int_equal(skin_weights_dominant(&sw, v), 2);
	}
	/* at h past the joint the parent's share is gone */
	vec3 far = vec3_make(0, 12.5f, 0);
	assert_float_equal(bind_segment_weight(&rig.seg[1], far, NULL), 0.0f, 0.0f);
}

/* root -> a (0,0,0)-(0,10,0) -> b (0,10,0)-(10,10,0): a right angle. */
static void right_angle(void)
{
	start_skel();
	add_bone("a", 0, vec3_make(0, 0, 0), vec3_make(0, 10, 0));
	add_bone("b", 1, vec3_make(0, 10, 0), vec3_make(10, 10, 0));
	bind_prepare(&rig, &s, &pose, &sharp);
}

/* At an angled joint both ramps run along the bisector m = (1,1,0)/sqrt 2:
 * the mitre plane x + y = 10 is the 0.5 line (cut square to b, a point on
 * it off the axis would get 0.5 + x / 2h), and a point and its mirror
 * image across that plane swap weights. */
static void test_angled_joint_ramps_on_the_mitre(void **state)
{
	(void)state;
	right_angle();
	const float r = 1.0f / sqrtf(2.0f);
	assert_float_equal(rig.seg[2].head_n.x, r, 1e-6f);
	assert_float_equal(rig.seg[2].head_n.y, r, 1e-6f);
	assert_float_equal(rig.seg[1].tip_n.x, r, 1e-6f);
	assert_float_equal(rig.seg[1].tip_n.y, r, 1e-6f);
	vec3 p[3] = { vec3_make(1.0f, 9.0f, 0.5f), vec3_make(0.5f, 9.2f, 0.3f), vec3_make(0.8f, 9.5f, 0.3f) };
	bind_points(p, 3, NULL);
	assert_float_equal(skin_weights_of(&sw, 0, 1), 0.5f, 1e-6f);
	assert_float_equal(skin_weights_of(&sw, 0, 2), 0.5f, 1e-6f);
	float wb = 0.5f + (0.5f - 0.8f) * r / (2 * 2.0f);
	assert_float_equal(skin_weights_of(&sw, 1, 2), wb, 1e-6f);
	assert_float_equal(skin_weights_of(&sw, 1, 1), 1.0f - wb, 1e-6f);
	assert_float_equal(skin_weights_of(&sw, 2, 1), wb, 1e-6f);
	assert_float_equal(skin_weights_of(&sw, 2, 2), 1.0f - wb, 1e-6f);
}

/* Folded back by more than about 150 degrees the bisector is left alone:
 * the child ramps along its own direction; and where two bones start at
 * a joint neither takes a mitre. */
static void test_mitre_only_where_it_means_something(void **state)
{
	(void)state;
	start_skel();
	add_bone("a", 0, vec3_make(0, 0, 0), vec3_make(0, 10, 0));
	add_bone("b", 1, vec3_make(0, 10, 0), vec3_make(3.0f, 0.5f, 0));
	bind_prepare(&rig, &s, &pose, &sharp);
	assert_float_equal(rig.seg[2].head_n.x, rig.seg[2].dir.x, 0.0f);
	assert_float_equal(rig.seg[2].head_n.y, rig.seg[2].dir.y, 0.0f);
	assert_float_equal(rig.seg[1].tip_n.y, 1.0f, 0.0f);

	right_angle();
	add_bone("c", 1, vec3_make(0, 10, 0), vec3_make(-10, 10, 0));
	bind_prepare(&rig, &s, &pose, &sharp);
	assert_float_equal(rig.seg[2].head_n.x, 1.0f, 0.0f);
	assert_float_equal(rig.seg[3].head_n.x, -1.0f, 0.0f);
	assert_float_equal(rig.seg[1].tip_n.y, 1.0f, 0.0f);
}

/* root -> a (0,0,0)-(0,1,0), short -> b (0,1,0)-(0,11,0): a's box
 * (R = 0.2) misses a point beside the joint that lies in b's head ramp
 * (R = 2, h = 2); a still takes what b's ramp leaves there. */
static void test_head_ramp_rest_goes_to_parent(void **state)
{
	(void)state;
	start_skel();
	add_bone("a", 0, vec3_make(0, 0, 0), vec3_make(0, 1, 0));
	add_bone("b", 1, vec3_make(0, 1, 0), vec3_make(0, 11, 0));
	bind_prepare(&rig, &s, &pose, &sharp);
	assert_int_equal(rig.seg[2].parent, 1);
	const float x[2] = { -0.8f, 0.6f };  /* past the joint along b */
	vec3 p[2] = { vec3_make(1.5f, 1 + x[0], 0), vec3_make(0, 1 + x[1], 1.2f) };
	bind_points(p, 2, NULL);
	for (int v = 0; v < 2; v++) {
		assert_float_equal(bind_segment_weight(&rig.seg[1], p[v], NULL), 0.0f, 0.0f);
		float wb = 0.5f + x[v] / (2 * 2.0f);
		assert_int_equal(sw.count[v], 2);
		assert_float_equal(skin_weights_of(&sw, v, 2), wb, 1e-6f);
		assert_float_equal(skin_weights_of(&sw, v, 1), 1.0f - wb, 1e-6f);
	}
	/* the root takes the rest at the root joint, where a's head ramps
	 * (c, short, only makes it a joint: its box misses q) */
	start_skel();
	add_bone("a", 0, vec3_make(0, 0, 0), vec3_make(0, 10, 0));
	add_bone("c", 0, vec3_make(0, 0, 0), vec3_make(2, 0, 0));
	bind_prepare(&rig, &s, &pose, &sharp);
	vec3 q = vec3_make(-0.5f, 1, 0);
	bind_points(&q, 1, NULL);
	assert_float_equal(skin_weights_of(&sw, 0, 1), 0.75f, 1e-6f);
	assert_float_equal(skin_weights_of(&sw, 0, 0), 0.25f, 1e-6f);
}

/* Two legs from the root joint, a hip width apart: their boxes overlap in
 * the crotch, but a point there goes to the nearer leg (and the bones it
 * meets at a joint), never to both legs. */
static void test_far_bones_do_not_share(void **state)
{
	(void)state;
	start_skel();
	int lhip = add_bone("lhip", 0, vec3_make(0, 0, 0), vec3_make(1, -1, 0));
	int lleg = add_bone("lleg", lhip, vec3_make(1, -1, 0), vec3_make(1, -11, 0));
	int rhip = add_bone("rhip", 0, vec3_make(0, 0, 0), vec3_make(-1, -1, 0));
	int rleg = add_bone("rleg", rhip, vec3_make(-1, -1, 0), vec3_make(-1, -11, 0));
	bind_prepare(&rig, &s, &pose, &sharp);
	vec3 p[2] = { vec3_make(0.2f, -5, 0), vec3_make(-0.3f, -6, 0.5f) };
	assert_true(bind_segment_weight(&rig.seg[lleg], p[0], NULL) > 0.0f);
	assert_true(bind_segment_weight(&rig.seg[rleg], p[0], NULL) > 0.0f);
	bind_points(p, 2, NULL);
	assert_float_equal(skin_weights_of(&sw, 0, lleg), 1.0f, 1e-6f);
	assert_float_equal(skin_weights_of(&sw, 1, rleg), 1.0f, 1e-6f);
	/* bones meeting at the root joint are neighbours: the hips share */
	vec3 hip = vec3_make(0, -0.3f, 0);
	bind_points(&hip, 1, NULL);
	assert_true(skin_weights_of(&sw, 0, lhip) > 0.0f && skin_weights_of(&sw, 0, rhip) > 0.0f);
}

/* A waist: the back up from the root joint, a hip bone down and sideways
 * from it. Up a flank, outside both boxes, the nearest bone changes from
 * the hip to the back; the two cross-fade across their bisector instead
 * of cutting the skin there. */
static void test_siblings_pointing_apart_cross_fade(void **state)
{
	(void)state;
	start_skel();
	int back = add_bone("back", 0, vec3_make(0, 0, 0), vec3_make(0, 10, 0));
	int hip = add_bone("hip", 0, vec3_make(0, 0, 0), vec3_make(6, -6, 0));
	bind_prepare(&rig, &s, &pose, &sharp);
	enum { N = 101 };
	vec3 p[N];
	for (int i = 0; i < N; i++)
		p[i] = vec3_make(4, -1 + 5.0f * i / (N - 1), 0);
	bind_points(p, N, NULL);
	float most = 0.0f, at_bisector = -1.0f;
	for (int i = 0; i < N; i++) {
		float t = skin_weights_of(&sw, i, back);
		if (i > 0) {
			float prev = skin_weights_of(&sw, i - 1, back);
			most = fmaxf(most, fabsf(t - prev));
		}
		/* the bisector plane meets the flank at y = 4 (1 - cos 45) / (1 + sin 45) */
		if (fabsf(p[i].y - 1.657f) < 0.026f)
			at_bisector = t + skin_weights_of(&sw, i, hip) > 0.0f ? t / (t + skin_weights_of(&sw, i, hip)) : 0.0f;
	}
	/* (where the nearest bone changes, the root's share of the rest does,
	 * by 0.02 here) */
	print_message("back's weight up the flank: %.2f .. %.2f, largest step %.3f, %.2f of back and hip at the bisector\n",
		      (double)skin_weights_of(&sw, 0, back), (double)skin_weights_of(&sw, N - 1, back), (double)most,
		      (double)at_bisector);
	assert_float_equal(skin_weights_of(&sw, 0, back), 0.0f, 1e-6f);
	assert_float_equal(skin_weights_of(&sw, N - 1, back), 1.0f, 1e-6f);
	assert_true(most < 0.05f);
	assert_float_equal(at_bisector, 0.5f, 0.05f);
}

/* Outside every box: the nearest bone, or where the nearest bone's ramps
 * reach (boxes grown to 1.1 times the distance to it), their cross-fade. */
static void test_outside_every_box(void **state)
{
	(void)state;
	two_bones();
	int inside;
	vec3 p[3] = { vec3_make(5, 3, 0), vec3_make(0, 30, 0), vec3_make(-4, 11, 0) };
	assert_float_equal(bind_segment_weight(&rig.seg[1], p[0], &inside), 0.0f, 0.0f);
	assert_int_equal(inside, 0);
	assert_float_equal(bind_segment_weight(&rig.seg[2], p[2], &inside), 0.0f, 0.0f);
	assert_int_equal(inside, 0);
	bind_info info;
	bind_points(p, 3, &info);
	assert_int_equal(info.fallback, 3);
	const int want[2] = { 1, 2 };
	for (int v = 0; v < 2; v++) {
		assert_int_equal(sw.count[v], 1);
		assert_int_equal(sw.bone[v][0], want[v]);
		assert_float_equal(sw.weight[v][0], 1.0f, 0.0f);
	}
	/* 1 past the joint, 4 from the bones (R = 2): the ramp's 0.75 / 0.25 */
	assert_int_equal(sw.count[2], 2);
	assert_float_equal(skin_weights_of(&sw, 2, 2), 0.75f, 1e-6f);
	assert_float_equal(skin_weights_of(&sw, 2, 1), 0.25f, 1e-6f);
}

static void test_invariants_on_a_fan(void **state)
{
	(void)state;
	start_skel();
	int hub = add_bone("spine", 0, vec3_make(0, 0, 0), vec3_make(0, 4, 0));
	int dum = add_bone("dum", hub, vec3_make(0, 4, 0), vec3_make(0, 4, 0));
	for (int k = 0; k < 6; k++) {
		float a = (float)k * 1.0471976f;
		char name[8];
		snprintf(name, sizeof name, "arm%d", k);
		add_bone(name, k == 0 ? dum : hub, vec3_make(0, 4, 0),
			 vec3_make(3 * cosf(a), 4 + 0.5f * (float)k, 3 * sinf(a)));
	}
	bind_prepare(&rig, &s, &pose, NULL);
	assert_float_equal(rig.seg[dum].length, 0.0f, 0.0f);
	assert_int_equal(rig.seg[hub + 2].ramp_head, 1);   /* through the zero-length bone */
	assert_int_equal(rig.seg[hub].ramp_tip, 1);

	static vec3 p[4000];
	srand(7);
	for (int v = 0; v < 4000; v++)
		p[v] = vec3_make(8.0f * rand() / RAND_MAX - 4, 10.0f * rand() / RAND_MAX - 2,
				 8.0f * rand() / RAND_MAX - 4);
	p[0] = vec3_make(0, 4, 0);
	bind_info info;
	bind_points(p, 4000, &info);
	assert_int_equal(sw.count[0], SKP_MAX_INFLUENCES);
	assert_int_equal(info.max_influences, SKP_MAX_INFLUENCES);
	for (int v = 0; v < 4000; v++) {
		double sum = 0;
		assert_true(sw.count[v] >= 1 && sw.count[v] <= SKP_MAX_INFLUENCES);
		for (int k = 0; k < sw.count[v]; k++) {
			assert_true(sw.weight[v][k] >= 0.0f);
			assert_true(sw.bone[v][k] != 0 && sw.bone[v][k] != dum);
			if (k > 0)
				assert_true(sw.weight[v][k] <= sw.weight[v][k - 1]);
			sum += sw.weight[v][k];
		}
		assert_true(fabs(sum - 1.0) <= 1e-6);
	}
}

static void test_all_zero_length_goes_to_root(void **state)
{
	(void)state;
	start_skel();
	add_bone("z", 0, vec3_make(0, 0, 0), vec3_make(0, 0, 0));
	bind_prepare(&rig, &s, &pose, NULL);
	vec3 p[1] = { vec3_make(1, 2, 3) };
	bind_points(p, 1, NULL);
	assert_int_equal(sw.count[0], 1);
	assert_int_equal(sw.bone[0][0], 0);
	assert_float_equal(sw.weight[0][0], 1.0f, 0.0f);
}

static void test_bad_positions_rejected(void **state)
{
	(void)state;
	two_bones();
	skp_error err;
	vec3 p[2] = { vec3_make(0, 1, 0), vec3_make(NAN, 0, 0) };
	assert_int_equal(bind_weights(&rig, p, 2, &sw, NULL, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "vertex 1"));
	assert_int_equal(bind_weights(&rig, p, SKP_MAX_VERTS + 1, &sw, NULL, &err), SKP_ERR_LIMIT);
}

static void test_fit_scales_and_centres(void **state)
{
	(void)state;
	two_bones();
	/* a "body" 4 units tall, its pelvis slice centred at (10, -3), hands
	 * reaching forward at the same height */
	static vec3 p[6];
	p[0] = vec3_make(10, 1, -3);
	p[1] = vec3_make(10, 5, -3);
	p[2] = vec3_make(9.8f, 1.1f, -4);
	p[3] = vec3_make(10.2f, 1.1f, -2);
	p[4] = vec3_make(30, 1.05f, 9);
	p[5] = vec3_make(-10, 1.05f, 9);
	bind_fit_result r;
	skp_error err;
	assert_int_equal(bind_fit(p, 6, &s, &pose, &r, &err), SKP_OK);
	assert_float_equal(r.scale, 5.0f, 1e-5f);
	assert_float_equal(r.skel_height, 20.0f, 1e-5f);
	assert_float_equal(p[0].y, 0.0f, 1e-4f);
	assert_float_equal(p[1].y, 20.0f, 1e-4f);
	/* the root (0,0,0) is at the bottom: the torso there is p0, p2, p3 */
	assert_float_equal(p[0].x, 0.0f, 1e-4f);
	assert_float_equal(p[0].z, 0.0f, 1e-4f);
	vec3 flat[2] = { vec3_make(0, 1, 0), vec3_make(1, 1, 0) };
	assert_int_equal(bind_fit(flat, 2, &s, &pose, &r, &err), SKP_ERR_RANGE);
}

/* ---- weights CSV ---- */

static const char *csv_asf =
	":root\n order TX TY TZ RX RY RZ\n:bonedata\n"
	" begin\n name a\n direction 0 1 0\n length 1\n axis 0 0 0 XYZ\n dof rx\n end\n"
	" begin\n name b\n direction 0 1 0\n length 1\n axis 0 0 0 XYZ\n dof rx\n end\n"
	" begin\n name c\n direction 1 0 0\n length 1\n axis 0 0 0 XYZ\n end\n"
	" begin\n name d\n direction -1 0 0\n length 1\n axis 0 0 0 XYZ\n end\n"
	":hierarchy\n begin\n root a\n a b c d\n end\n";

static skp_status read_csv(const char *text, int verts, skp_error *err)
{
	static text_lines tl;
	skp_mem_source src;
	skp_error e;
	assert_int_equal(test_parse_asf(csv_asf, strlen(csv_asf), &s, &e), SKP_OK);
	text_lines_init(&tl, skp_mem_reader(&src, text, strlen(text)));
	return weights_csv_read(&tl, &s, verts, &sw, err);
}

static void test_csv_good(void **state)
{
	(void)state;
	skp_error err;
	const char *text = "vertex,bone,weight\r\n"
			   "# a comment\r\n"
			   "0,a,0.25\r\n1,root,1\r\n0,b,7.5e-1\r\n\r\n"
			   "2, c , 0.3\r\n2,d,0.2\r\n2,a,0.2\r\n2,b,0.3004\r\n";
	assert_int_equal(read_csv(text, 3, &err), SKP_OK);
	assert_int_equal(sw.vert_count, 3);
	assert_int_equal(sw.count[0], 2);
	assert_float_equal(skin_weights_of(&sw, 0, skel_find(&s, "b")), 0.75f, 1e-7f);
	assert_int_equal(sw.bone[1][0], 0);
	assert_int_equal(sw.count[2], 4);
	double sum = 0;
	for (int k = 0; k < 4; k++)
		sum += sw.weight[2][k];
	assert_true(fabs(sum - 1.0) < 1e-6);   /* re-normalised from 1.0004 */
	assert_float_equal(skin_weights_of(&sw, 2, skel_find(&s, "d")), 0.2f / 1.0004f, 1e-6f);
}

typedef struct csv_case {
	const char *text;
	int verts;
	skp_status code;
	long line;
	const char *needle;
} csv_case;

static const csv_case csv_cases[] = {
	{ "vertex,bone,weight\n0,a,1\n1,elbow,1\n", 2, SKP_ERR_SYNTAX, 3, "unknown bone 'elbow'" },
	{ "vertex,bone,weight\n0,a,1\n1,a,0.5x\n", 2, SKP_ERR_SYNTAX, 3, "bad weight '0.5x'" },
	{ "vertex,bone,weight\n0,a,nan\n", 1, SKP_ERR_SYNTAX, 2, "bad weight" },
	{ "vertex,bone,weight\n0,a,inf\n", 1, SKP_ERR_SYNTAX, 2, "bad weight" },
	{ "vertex,bone,weight\nx,a,1\n", 1, SKP_ERR_SYNTAX, 2, "bad vertex index 'x'" },
	{ "vertex,bone,weight\n0,a,1\n\n2,a,1\n", 2, SKP_ERR_RANGE, 4, "vertex 2 out of range" },
	{ "vertex,bone,weight\n-1,a,1\n", 2, SKP_ERR_RANGE, 2, "vertex -1 out of range" },
	{ "vertex,bone,weight\n0,a,0.2\n0,b,0.2\n0,c,0.2\n0,d,0.2\n0,root,0.2\n", 1, SKP_ERR_LIMIT, 6,
	  "more than 4 rows" },
	{ "vertex,bone,weight\n0,a,1.5\n0,b,-0.5\n", 1, SKP_ERR_RANGE, 3, "negative weight -0.5" },
	{ "vertex,bone,weight\n0,a,0.5\n0,a,0.5\n", 1, SKP_ERR_SYNTAX, 3, "bone 'a' twice" },
	{ "vertex,bone,weight\n0,a\n", 1, SKP_ERR_SYNTAX, 2, "found 2 field(s)" },
	{ "vertex,bone,weight\n0,a,1\n2,a,1\n", 3, SKP_ERR_RANGE, 0, "vertex 1 has no weights" },
	{ "vertex,bone,weight\n0,a,0.5\n0,b,0.49\n", 1, SKP_ERR_RANGE, 0, "vertex 0: weights sum to 0.99" },
	{ "vertex,bone,weight\n0,a,0\n", 1, SKP_ERR_RANGE, 0, "weights sum to 0" },
	{ "v,b,w\n0,a,1\n", 1, SKP_ERR_SYNTAX, 1, "header" },
	{ "", 1, SKP_ERR_SYNTAX, 0, "empty file" },
};

static void test_csv_errors(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof csv_cases / sizeof csv_cases[0]; i++) {
		const csv_case *c = &csv_cases[i];
		skp_error err;
		memset(&err, 0, sizeof err);
		skp_status rc = read_csv(c->text, c->verts, &err);
		if (rc != c->code || err.line != c->line || !strstr(err.msg, c->needle))
			fail_msg("case %zu: status %d line %ld '%s'", i, rc, err.line, err.msg);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_segments_and_ramps),
		cmocka_unit_test(test_segment_distance),
		cmocka_unit_test(test_mid_bone_gets_one),
		cmocka_unit_test(test_joint_is_half_half),
		cmocka_unit_test(test_ramp_past_joint_is_linear),
		cmocka_unit_test(test_angled_joint_ramps_on_the_mitre),
		cmocka_unit_test(test_mitre_only_where_it_means_something),
		cmocka_unit_test(test_head_ramp_rest_goes_to_parent),
		cmocka_unit_test(test_far_bones_do_not_share),
		cmocka_unit_test(test_siblings_pointing_apart_cross_fade),
		cmocka_unit_test(test_outside_every_box),
		cmocka_unit_test(test_invariants_on_a_fan),
		cmocka_unit_test(test_all_zero_length_goes_to_root),
		cmocka_unit_test(test_bad_positions_rejected),
		cmocka_unit_test(test_fit_scales_and_centres),
		cmocka_unit_test(test_csv_good),
		cmocka_unit_test(test_csv_errors),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
