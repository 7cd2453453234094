/* The compare view's close-up: the joint it shows is where the two
 * skinned bodies part most, held at least CLOSEUP_HOLD_S before another
 * takes it, and only one that parts clearly more; skin_diff measures the
 * parting per joint and finds where on the joint it is. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "render_closeup.h"
#include "skin_diff.h"

static void test_pick_holds_then_moves(void **state)
{
	(void)state;
	closeup_pick c;
	float score[4] = { 0, 0, 0, 0 };
	closeup_pick_init(&c);
	assert_int_equal(closeup_pick_update(&c, score, 4, 0.1f), -1); /* nothing parts: none */
	score[1] = 2.0f;
	assert_int_equal(closeup_pick_update(&c, score, 4, 0.1f), 1);
	score[2] = 5.0f; /* far more, but joint 1 has been shown 0.1 s */
	for (float t = 0.1f; t < CLOSEUP_HOLD_S - 0.05f; t += 0.1f)
		assert_int_equal(closeup_pick_update(&c, score, 4, 0.1f), 1);
	assert_int_equal(closeup_pick_update(&c, score, 4, 0.2f), 2);
	/* held again: a joint barely ahead (under CLOSEUP_SWITCH) never takes it */
	score[3] = 5.0f * CLOSEUP_SWITCH * 0.95f;
	for (int i = 0; i < 100; i++)
		assert_int_equal(closeup_pick_update(&c, score, 4, 0.1f), 2);
	score[3] = 5.0f * CLOSEUP_SWITCH * 1.05f;
	assert_int_equal(closeup_pick_update(&c, score, 4, 0.1f), 3);
}

/* The camera glides: after a switch it moves part of the way a frame. */
static void test_camera_glides(void **state)
{
	(void)state;
	closeup_camera cam;
	memset(&cam, 0, sizeof cam);
	vec3 axis = vec3_make(1, 0, 0), parent = vec3_make(1, 0, 0);
	closeup_camera_follow(&cam, vec3_make(0, 0, 0), axis, parent, 0.45f, 0.016f, 1);
	closeup_camera_follow(&cam, vec3_make(10, 0, 0), axis, parent, 0.45f, 0.016f, 0);
	assert_true(cam.target.x > 0.0f && cam.target.x < 1.0f);
	/* settled within a second of a joint's 2 s hold: 5% of the way left */
	for (int i = 0; i < 62; i++)
		closeup_camera_follow(&cam, vec3_make(10, 0, 0), axis, parent, 0.45f, 0.016f, 0);
	assert_true(cam.target.x > 9.5f);
	for (int i = 0; i < 300; i++)
		closeup_camera_follow(&cam, vec3_make(10, 0, 0), axis, parent, 0.45f, 0.016f, 0);
	assert_true(fabsf(cam.target.x - 10.0f) < 0.01f);
	/* a straight limb along x is seen from across it, not down its length */
	float along = fabsf(sinf(cam.azimuth) * cosf(cam.pitch));
	assert_true(along < 0.2f);
}

/* Round where the methods part, within the body's bounds; a joint folded
 * past 60 degrees wide enough for its two bones. */
static void test_span_wants(void **state)
{
	(void)state;
	vec3 x = vec3_make(10, 0, 0), y = vec3_make(0, 8, 0), back = vec3_make(-9, 1, 0);
	float h = 100.0f;
	assert_float_equal(closeup_span_want(3.0f, x, x, h), CLOSEUP_REACH * 3.0f, 1e-5f);
	assert_float_equal(closeup_span_want(0.0f, x, x, h), CLOSEUP_SPAN * h, 1e-5f);
	assert_float_equal(closeup_span_want(0.1f, x, x, h), CLOSEUP_SPAN_MIN * h, 1e-5f);
	assert_float_equal(closeup_span_want(50.0f, x, x, h), CLOSEUP_SPAN_MAX * h, 1e-5f);
	/* bent 90 degrees: the shorter bone (8) sets it; folded back: 9.06
	 * (on a body whose smallest close-up is under either) */
	float small = 0.5f * h;
	assert_float_equal(closeup_span_want(1.0f, x, y, small), CLOSEUP_FOLD_SHOWN * 8.0f, 1e-4f);
	assert_float_equal(closeup_span_want(1.0f, back, x, small), CLOSEUP_FOLD_SHOWN * sqrtf(82.0f), 1e-4f);
	/* bent 55 degrees: round the parting; 65: the fold's 0.26 of 10 */
	vec3 at55 = vec3_make(10 * cosf(0.96f), 10 * sinf(0.96f), 0), at65 = vec3_make(10 * cosf(1.134f), 10 * sinf(1.134f), 0);
	assert_float_equal(closeup_span_want(1.5f, at55, x, small), CLOSEUP_REACH * 1.5f, 1e-4f);
	assert_float_equal(closeup_span_want(1.5f, at65, x, small), CLOSEUP_FOLD_SHOWN * 10.0f, 1e-4f);
	/* bent 45 degrees: still round the parting */
	assert_float_equal(closeup_span_want(3.0f, vec3_make(1, 1, 0), x, h), CLOSEUP_REACH * 3.0f, 1e-5f);
}

static skel sk;
static skel_pose bind;
static uint8_t block[SKIN_SOA_BYTES(8)] __attribute__((aligned(SKIN_ALIGN)));

/* Two bones along x, four vertices round each joint: the per-joint score
 * is the largest distance among the joint's vertices, and the focus the
 * weighted centre of where they part. */
static void test_diff_scores_and_focus(void **state)
{
	(void)state;
	static skin_diff d;
	skin_soa soa;
	memset(&sk, 0, sizeof sk);
	sk.count = 2;
	sk.bone[0].parent = -1;
	sk.bone[1].parent = 0;
	bind.head[0] = bind.tip[0] = vec3_make(0, 0, 0);
	bind.head[1] = vec3_make(0, 0, 0);
	bind.tip[1] = vec3_make(4, 0, 0);
	skin_soa_attach(&soa, block, 8);
	for (int v = 0; v < 8; v++) {
		soa.px[v] = v < 4 ? 0.1f * (float)v : 3.9f;
		soa.py[v] = 0.5f;
		soa.pz[v] = 0.0f;
		soa.bone[0][v] = 1;
		soa.weight[0][v] = 1.0f;
		for (int k = 1; k < SKP_MAX_INFLUENCES; k++)
			soa.bone[k][v] = 0, soa.weight[k][v] = 0.0f;
	}
	skin_diff_init(&d, &sk, &bind, NULL, &soa);
	float a[24], b[24];
	for (int v = 0; v < 8; v++) {
		a[3 * v] = b[3 * v] = soa.px[v];
		a[3 * v + 1] = b[3 * v + 1] = soa.py[v];
		a[3 * v + 2] = b[3 * v + 2] = 0.0f;
	}
	b[3 * 2 + 1] -= 0.3f; /* vertex 2 parts by 0.3, vertex 3 by 0.1 */
	b[3 * 3 + 1] -= 0.1f;
	float most = skin_diff_between(&d, a, b, NULL);
	assert_true(fabsf(most - 0.3f) < 1e-5f);
	/* every vertex is nearest the joint at the origin (bone 0's and 1's heads coincide: the first) */
	assert_int_equal(skin_diff_worst(&d), 0);
	skin_focus f = skin_diff_focus(&d, &bind, a, b, 0);
	vec3 at = f.at;
	float reach = f.reach;
	assert_true(f.found);
	/* weighed by the squared distance: 0.09 and 0.01 */
	float w2 = 0.09f, w3 = 0.01f, w = w2 + w3;
	assert_true(fabsf(at.x - (w2 * 0.2f + w3 * 0.3f) / w) < 1e-5f);
	/* the spread round it: of the midpoints (0.2, 0.35) and (0.3, 0.45),
	 * 0.02 apart squared, the root of the weights' product times that */
	assert_true(fabsf(reach - sqrtf(w2 / w * w3 / w * 0.02f)) < 1e-5f);
	/* the skin's distance from its bone: vertex 2 came 0.3 nearer */
	float dist[8];
	skin_diff_from_bind(&d, &bind, b, dist);
	assert_true(fabsf(dist[2] + 0.3f) < 1e-5f && fabsf(dist[0]) < 1e-6f);
}

/* An elbow folded past a right angle (its head away from the origin):
 * its vertices part on both sides, more on the inside (hidden between the
 * bones), and the focus and its reach are the outside's alone; straight,
 * a shoulder, a skeleton not a human's, or an outside that barely parts,
 * they are all the vertices'. */
static void place_fold(skin_soa *soa, vec3 o, float *a, float *b)
{
	/* outside, outside, inside the fold; parting by 0.1, 0.1, 0.3 */
	static const float at[3][2] = { { 0.3f, -0.3f }, { 0.5f, -0.1f }, { -0.3f, 0.3f } }, part[3] = { 0.1f, 0.1f, 0.3f };
	for (int v = 0; v < 3; v++) {
		soa->px[v] = o.x + at[v][0], soa->py[v] = o.y + at[v][1], soa->pz[v] = o.z;
		soa->bone[0][v] = 1, soa->weight[0][v] = 1.0f;
		for (int k = 1; k < SKP_MAX_INFLUENCES; k++)
			soa->bone[k][v] = 0, soa->weight[k][v] = 0.0f;
		a[3 * v] = b[3 * v] = soa->px[v];
		a[3 * v + 1] = soa->py[v], b[3 * v + 1] = soa->py[v] - part[v];
		a[3 * v + 2] = b[3 * v + 2] = o.z;
	}
}

static void test_focus_outside_fold(void **state)
{
	(void)state;
	static skin_diff d;
	static skel_joints joints;
	skin_soa soa;
	vec3 o = vec3_make(5, 2, 1);
	memset(&sk, 0, sizeof sk);
	sk.count = 2;
	sk.bone[0].parent = -1;
	sk.bone[1].parent = 0;
	bind.head[0] = vec3_add(o, vec3_make(-4, 0, 0));
	bind.tip[0] = bind.head[1] = o;
	bind.tip[1] = vec3_add(o, vec3_make(-1, 3, 0)); /* back past a right angle from bone 0's +x */
	memset(&joints, 0, sizeof joints);
	joints.count = 2;
	joints.biped = 1;
	joints.skel = &sk;
	joints.kind[1] = JOINT_ELBOW;
	vec3 out = skin_fold_outside(vec3_make(-1, 3, 0), vec3_make(4, 0, 0));
	assert_true(out.x > 0.5f && out.y < -0.5f && fabsf(vec3_length(out) - 1.0f) < 1e-5f);
	out = skin_fold_outside(vec3_make(0.2f, 1, 0), vec3_make(1, 0, 0)); /* 79 degrees: not folded */
	assert_true(vec3_dot(out, out) == 0.0f);
	float a[9], b[9];
	skin_soa_attach(&soa, block, 3);
	place_fold(&soa, o, a, b);
	skin_diff_init(&d, &sk, &bind, &joints, &soa);
	/* the outside's midpoints (0.3, -0.35) and (0.5, -0.15), equally
	 * weighed: their centre, each 0.1 * sqrt(2) from it */
	skin_focus f = skin_diff_focus(&d, &bind, a, b, 1);
	assert_true(f.found);
	assert_float_equal(f.at.x, o.x + 0.4f, 1e-5f);
	assert_float_equal(f.at.y, o.y - 0.25f, 1e-5f);
	assert_float_equal(f.reach, 0.1f * sqrtf(2.0f), 1e-5f);
	assert_true(skin_focus_counts(&f, a, b, 0) && skin_focus_counts(&f, a, b, 1) && !skin_focus_counts(&f, a, b, 2));
	/* all three, weighed 0.01, 0.01 and 0.09 */
	float all_x = o.x + (0.01f * 0.3f + 0.01f * 0.5f - 0.09f * 0.3f) / 0.11f;
	joints.kind[1] = JOINT_SHOULDER;
	f = skin_diff_focus(&d, &bind, a, b, 1);
	assert_float_equal(f.at.x, all_x, 1e-5f);
	assert_true(skin_focus_counts(&f, a, b, 2));
	joints.kind[1] = JOINT_ELBOW;
	joints.biped = 0;
	assert_float_equal(skin_diff_focus(&d, &bind, a, b, 1).at.x, all_x, 1e-5f);
	joints.biped = 1;
	bind.tip[1] = vec3_add(o, vec3_make(4, 0, 0)); /* straight */
	assert_float_equal(skin_diff_focus(&d, &bind, a, b, 1).at.x, all_x, 1e-5f);
	/* folded, the outside parting by 0.001 only: under SKIN_FOLD_SHARE_MIN */
	bind.tip[1] = vec3_add(o, vec3_make(-1, 3, 0));
	b[1] = a[1] - 0.001f, b[4] = a[4] - 0.001f;
	f = skin_diff_focus(&d, &bind, a, b, 1);
	assert_true(f.at.x < o.x - 0.29f && skin_focus_counts(&f, a, b, 2));
	/* nothing parts: not found, the joint's head */
	f = skin_diff_focus(&d, &bind, a, a, 1);
	assert_false(f.found);
	assert_true(f.at.x == o.x && f.at.y == o.y && f.at.z == o.z);
	/* no joint: nothing found */
	assert_false(skin_diff_focus(&d, &bind, a, b, -1).found);
	assert_false(skin_diff_focus(&d, &bind, a, b, 2).found);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_pick_holds_then_moves),
		cmocka_unit_test(test_camera_glides),
		cmocka_unit_test(test_span_wants),
		cmocka_unit_test(test_diff_scores_and_focus),
		cmocka_unit_test(test_focus_outside_fold),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
