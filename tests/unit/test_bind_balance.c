/* Volume balancing (bind_balance.h) on hand-made tubes: the first-order
 * volume change of a DQBS bend, measured by skinning the tube at +-10
 * degrees, goes away where the flesh is off the joint, nothing moves where
 * it is centred, and bad input is refused without touching the weights. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bind.h"
#include "bind_balance.h"
#include "dq.h"
#include "mesh.h"
#include "metrics.h"
#include "test_skel.h"

#define PI 3.14159265358979323846

static skel s;
static skel_pose pose;
static bind_rig rig;
static mesh tube;
static skin_weights sw, before;
static bind_balance_work work;
static bind_balance_info info;
static float posed[SKP_MAX_VERTS * 3];

/* A bone that turns about x, y and z. */
static int add_bone(const char *name, int parent, vec3 head, vec3 tip)
{
	int b = test_skel_add_bone(&s, &pose, name, parent, head, tip);
	s.bone[b].channel_count = 3;
	for (int k = 0; k < 3; k++)
		s.bone[b].channel[k] = (uint8_t)(SKEL_RX + k);
	return b;
}

/* root, "upper" (0,-10,0)-(0,0,0), "lower" (0,0,0)-(0,10,0): the joint at
 * the origin, the "lower" bone turns about it. With `hand`, "lower" stops
 * at (0,5,0) and a "hand" without channels carries on to (0,10,0). */
static void limb_with(int hand)
{
	static const bind_params wide = {
		.radius = 0.6f, .radius_min = 0.0f, .radius_max = 1.0f, .radius_cap = 1.0f, .blend = 0.2f,
	};
	memset(&s, 0, sizeof s);
	memset(&pose, 0, sizeof pose);
	add_bone("root", -1, vec3_make(0, 0, 0), vec3_make(0, 0, 0));
	s.bone[0].channel_count = 0;
	add_bone("upper", 0, vec3_make(0, -10, 0), vec3_make(0, 0, 0));
	add_bone("lower", 1, vec3_make(0, 0, 0), vec3_make(0, hand ? 5 : 10, 0));
	if (hand)
		s.bone[add_bone("hand", 2, vec3_make(0, 5, 0), vec3_make(0, 10, 0))].channel_count = 0;
	bind_prepare(&rig, &s, &pose, &wide);
}

static void limb(void)
{
	limb_with(0);
}

static int add_vertex(vec3 p)
{
	tube.pos[tube.vert_count] = p;
	return tube.vert_count++;
}

static void add_tri(int a, int b, int c)
{
	uint32_t *t = tube.tri[tube.tri_count++];
	t[0] = (uint32_t)a;
	t[1] = (uint32_t)b;
	t[2] = (uint32_t)c;
}

/* A closed tube along y from -9 to 9 around the line x = cx, z = 0,
 * radius 2, counter-clockwise from outside. */
static void make_tube(float cx)
{
	enum { AROUND = 24, ALONG = 73 };
	memset(&tube, 0, sizeof tube);
	for (int j = 0; j < ALONG; j++)
		for (int i = 0; i < AROUND; i++) {
			double a = 2.0 * PI * i / AROUND;
			add_vertex(vec3_make(cx + 2.0f * (float)cos(a), -9.0f + 18.0f * j / (ALONG - 1),
					     2.0f * (float)sin(a)));
		}
	int bottom = add_vertex(vec3_make(cx, -9.0f, 0.0f)), top = add_vertex(vec3_make(cx, 9.0f, 0.0f));
	for (int j = 0; j + 1 < ALONG; j++)
		for (int i = 0; i < AROUND; i++) {
			int a = j * AROUND + i, b = j * AROUND + (i + 1) % AROUND;
			add_tri(a, b + AROUND, b);
			add_tri(a, a + AROUND, b + AROUND);
		}
	for (int i = 0; i < AROUND; i++) {
		add_tri(bottom, i, (i + 1) % AROUND);
		add_tri(top, (ALONG - 1) * AROUND + (i + 1) % AROUND, (ALONG - 1) * AROUND + i);
	}
}

static void bind_tube(float cx)
{
	skp_error err;
	limb();
	make_tube(cx);
	assert_int_equal(bind_weights(&rig, tube.pos, tube.vert_count, &sw, NULL, &err), SKP_OK);
	before = sw;
}

static double volume_of(const float *xyz)
{
	return metrics_mesh_volume(xyz, (const uint32_t (*)[3])tube.tri, tube.tri_count);
}

/* DQBS with "lower" turned by deg about axis through the joint. */
static double bent_volume(const skin_weights *w, vec3 axis, double deg)
{
	dq bone[3];
	bone[0] = bone[1] = dq_identity();
	bone[2] = dq_from_quat_trans(quat_from_axis_angle(axis, (float)(deg * PI / 180.0)),
				     vec3_make(0, 0, 0));
	for (int v = 0; v < tube.vert_count; v++) {
		quat pivot = dq_blend_pivot(bone, w->bone[v], w->weight[v], w->count[v]);
		dq d = dq_blend_normalized(bone, w->bone[v], w->weight[v], w->count[v], pivot);
		vec3 p = dq_transform_point(&d, tube.pos[v]);
		posed[3 * v] = p.x;
		posed[3 * v + 1] = p.y;
		posed[3 * v + 2] = p.z;
	}
	return volume_of(posed);
}

/* The volume's change per degree at the bind pose, relative to it. */
static double bend_rate(const skin_weights *w, vec3 axis)
{
	double v0 = bent_volume(w, axis, 0.0);
	return (bent_volume(w, axis, 10.0) - bent_volume(w, axis, -10.0)) / (20.0 * v0);
}

static void check_weights(const skin_weights *w)
{
	for (int v = 0; v < w->vert_count; v++) {
		float sum = 0.0f;
		assert_true(w->count[v] >= 1 && w->count[v] <= SKP_MAX_INFLUENCES);
		for (int k = 0; k < w->count[v]; k++) {
			assert_true(w->weight[v][k] > 0.0f);
			assert_true(w->bone[v][k] < s.count);
			if (k > 0)
				assert_true(w->weight[v][k] <= w->weight[v][k - 1]);
			sum += w->weight[v][k];
		}
		assert_float_equal(sum, 1.0f, 1e-5f);
	}
}

/* bind_balance on the tube's first n vertices (n = all: -1). */
static skp_status balance_tube(int n, skp_error *err)
{
	return bind_balance(&s, &pose, tube.pos, n < 0 ? tube.vert_count : n,
			    (const uint32_t (*)[3])tube.tri, tube.tri_count, &sw, &work, &info, err);
}

static double largest_change(void)
{
	double most = 0.0;
	for (int v = 0; v < sw.vert_count; v++)
		for (int b = 0; b < s.count; b++)
			most = fmax(most, fabs(skin_weights_of(&sw, v, b) - skin_weights_of(&before, v, b)));
	return most;
}

static void test_off_centre_flesh_is_balanced(void **state)
{
	(void)state;
	skp_error err;
	const vec3 z = vec3_make(0, 0, 1), x = vec3_make(1, 0, 0);
	bind_tube(1.5f);
	double rate_z = bend_rate(&sw, z), rate_x = bend_rate(&sw, x);
	/* flesh beside the joint: bending towards it changes the volume */
	assert_true(fabs(rate_z) > 1e-4);
	assert_int_equal(balance_tube(-1, &err), SKP_OK);
	print_message("bend about z: %.3g -> %.3g of the volume per degree (x: %.3g -> %.3g), "
		      "largest change %.3f, %d rings\n", rate_z, bend_rate(&sw, z), rate_x,
		      bend_rate(&sw, x), largest_change(), info.rings[2]);
	assert_int_equal(info.outcome[2], BIND_BALANCE_DONE);
	assert_true(fabs(bend_rate(&sw, z)) < 0.05 * fabs(rate_z));
	assert_true(fabs(bend_rate(&sw, x)) <= fmax(0.05 * fabs(rate_z), fabs(rate_x)));
	/* the reported moment is the measured one: per 30 degrees */
	assert_float_equal(info.moment[2], fabs(rate_z) * 30.0, 0.05 * fabs(rate_z) * 30.0);
	assert_true(info.moment_after[2] < 1e-3 * info.moment[2]);
	assert_true(largest_change() <= BIND_BALANCE_MAX_CHANGE + 1e-6);
	assert_true(largest_change() > 0.01);
	check_weights(&sw);
}

static void test_centred_flesh_is_left_alone(void **state)
{
	(void)state;
	skp_error err;
	bind_tube(0.0f);
	assert_true(fabs(bend_rate(&sw, vec3_make(0, 0, 1))) < 1e-5);
	assert_int_equal(balance_tube(-1, &err), SKP_OK);
	assert_int_equal(info.outcome[2], BIND_BALANCE_NEEDLESS);
	assert_int_equal(info.outcome[1], BIND_BALANCE_NONE);   /* no cross-fade at the root */
	assert_memory_equal(&sw, &before, sizeof sw);
}

/* Flesh that lies wholly beside the joint cannot be balanced by a modest
 * change: the change is capped, the moment shrinks in proportion. */
static void test_too_far_is_balanced_in_part(void **state)
{
	(void)state;
	skp_error err;
	const vec3 z = vec3_make(0, 0, 1);
	bind_tube(6.0f);
	double rate = bend_rate(&sw, z);
	assert_int_equal(balance_tube(-1, &err), SKP_OK);
	assert_int_equal(info.outcome[2], BIND_BALANCE_PARTLY);
	assert_int_equal(info.rings[2], BIND_BALANCE_MAX_RINGS);
	assert_float_equal(info.change[2], BIND_BALANCE_MAX_CHANGE, 1e-6);
	assert_true(largest_change() <= BIND_BALANCE_MAX_CHANGE + 1e-5);
	assert_true(info.moment_after[2] > 0.0f && info.moment_after[2] < info.moment[2]);
	/* what is left is what the bend measures */
	double after = bend_rate(&sw, z);
	print_message("capped: %.3g -> %.3g of the volume per degree (reported %.3g -> %.3g per 30)\n",
		      rate, after, (double)info.moment[2], (double)info.moment_after[2]);
	assert_true(fabs(after) < fabs(rate));
	assert_float_equal(fabs(after) * 30.0, info.moment_after[2], 0.1 * info.moment_after[2]);
	check_weights(&sw);
}

/* The limb beyond the joint's own bone (the "hand") keeps its weights:
 * the balancing works on the joint's bone and the body before it. */
static void test_limb_beyond_is_untouched(void **state)
{
	(void)state;
	skp_error err;
	skin_weights bound;
	limb_with(1);
	make_tube(1.5f);
	assert_int_equal(bind_weights(&rig, tube.pos, tube.vert_count, &sw, NULL, &err), SKP_OK);
	bound = before = sw;
	assert_int_equal(balance_tube(-1, &err), SKP_OK);
	assert_true(info.outcome[2] == BIND_BALANCE_DONE || info.outcome[2] == BIND_BALANCE_PARTLY);
	int hand_verts = 0, changed = 0;
	for (int v = 0; v < tube.vert_count; v++) {
		int same = sw.count[v] == bound.count[v] &&
			   memcmp(sw.weight[v], bound.weight[v], sizeof sw.weight[v]) == 0 &&
			   memcmp(sw.bone[v], bound.bone[v], sizeof sw.bone[v]) == 0;
		changed += !same;
		if (bound.bone[v][0] == 3 && bound.weight[v][0] > 0.5f) {
			hand_verts++;
			if (!same)
				fail_msg("hand vertex %d changed", v);
		}
	}
	print_message("%d hand vertices kept, %d vertices changed\n", hand_verts, changed);
	assert_true(hand_verts > 100 && changed > 100);
	check_weights(&sw);
}

static void test_bad_input_changes_nothing(void **state)
{
	(void)state;
	skp_error err;
	bind_tube(1.5f);
	tube.tri[7][1] = (uint32_t)tube.vert_count;
	assert_int_equal(balance_tube(-1, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "triangle 7"));
	assert_memory_equal(&sw, &before, sizeof sw);

	make_tube(1.5f);
	sw.bone[3][0] = (uint16_t)s.count;
	assert_int_equal(balance_tube(-1, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "vertex 3"));
	sw.bone[3][0] = before.bone[3][0];
	assert_memory_equal(&sw, &before, sizeof sw);

	assert_int_equal(balance_tube(tube.vert_count - 1, &err), SKP_ERR_RANGE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_off_centre_flesh_is_balanced),
		cmocka_unit_test(test_centred_flesh_is_left_alone),
		cmocka_unit_test(test_too_far_is_balanced_in_part),
		cmocka_unit_test(test_limb_beyond_is_untouched),
		cmocka_unit_test(test_bad_input_changes_nothing),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
