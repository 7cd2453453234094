/* Automatic weights (bind.h) on a real body: the MakeHuman base mesh from
 * the shared data, fitted to the CMU skeleton in its A-pose
 * (tests/data/makehuman_apose.amc) and bound: hands, legs, head and upper
 * arms on their bones, smooth across the edges, the root taking only what
 * the bones at the root joint share. Skipped without ../shared/data. The
 * hand-made cases: test_bind.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bind.h"
#include "bind_fit.h"
#include "obj.h"
#include "skin_weights.h"
#include "test_bind_points.h"
#include "test_parse.h"
#include "test_paths.h"

static skel s;
static skel_pose pose;
static bind_rig rig;
static skin_weights sw;
static mesh body;
static obj_work work;

static int load_makehuman(void)
{
	const char *asf = test_data_path("mocap/cmu/02.asf");
	const char *obj = test_data_path("mesh/makehuman/base.obj");
	if (!asf || !obj)
		return 0;
	skp_error err;
	assert_int_equal(test_parse_asf_file(asf, &s, &err), SKP_OK);

	/* bind pose: the first frame of tests/data/makehuman_apose.amc */
	size_t n;
	char *amc = test_read_file("tests/data/makehuman_apose.amc", &n);
	assert_non_null(amc);
	static amc_frame first;
	static text_lines tl;
	static amc_stream as;
	skp_mem_source src;
	text_lines_init(&tl, skp_mem_reader(&src, amc, n));
	amc_open(&as, &s, &tl);
	assert_int_equal(amc_next(&as, &first, &err), 1);
	free(amc);
	fk_pose(&s, first.value, &pose);

	char *text = test_read_file(obj, &n);
	assert_non_null(text);
	obj_options opt = { .group = "body" };
	text_lines_init(&tl, skp_mem_reader(&src, text, n));
	assert_int_equal(obj_parse(&body, &work, &tl, &opt, &err), SKP_OK);
	free(text);
	assert_int_equal(body.vert_count, 13380);
	assert_int_equal(bind_fit(body.pos, body.vert_count, &s, &pose, NULL, &err), SKP_OK);
	return 1;
}

static int in_group(int bone, const char *const *names)
{
	for (; *names; names++)
		if (strcmp(s.bone[bone].name, *names) == 0)
			return 1;
	return 0;
}

/* Share of the vertices selected by pick whose largest weight is on one of
 * the named bones. */
static double dominated(int (*pick)(vec3 p, void *ctx), void *ctx, const char *const *names,
			int *count)
{
	int n = 0, hit = 0;
	for (int v = 0; v < body.vert_count; v++) {
		if (!pick(body.pos[v], ctx))
			continue;
		n++;
		hit += in_group(skin_weights_dominant(&sw, v), names);
	}
	*count = n;
	return n ? (double)hit / n : 0.0;
}

typedef struct band {
	float lo, hi;           /* fitted Y */
	float x_min, x_max;     /* |x| */
} band;

static int pick_band(vec3 p, void *ctx)
{
	const band *b = ctx;
	return p.y >= b->lo && p.y <= b->hi && fabsf(p.x) >= b->x_min && fabsf(p.x) <= b->x_max;
}

static void test_makehuman_apose_regions(void **state)
{
	(void)state;
	if (!load_makehuman())
		skip();
	bind_info info;
	bind_prepare(&rig, &s, &pose, NULL);
	test_bind_points(&rig, body.pos, body.vert_count, &sw, &info);

	float lo, h = bind_fit_skel_height(&s, &pose, &lo);
	float x_max = 0;
	for (int v = 0; v < body.vert_count; v++)
		x_max = fmaxf(x_max, fabsf(body.pos[v].x));
	/* hands: the most lateral points of the arms (the A-pose hangs the
	 * hands lowest and furthest out) */
	static const char *const hand[] = { "lwrist", "lhand", "lfingers", "lthumb",
					    "rwrist", "rhand", "rfingers", "rthumb", NULL };
	static const char *const leg[] = { "lfemur", "ltibia", "rfemur", "rtibia", NULL };
	static const char *const head[] = { "head", "upperneck", "lowerneck", NULL };
	static const char *const arm[] = { "lhumerus", "lradius", "rhumerus", "rradius", NULL };
	band hands = { lo, lo + h, 0.88f * x_max, x_max };
	band legs = { lo + 0.08f * h, lo + 0.42f * h, 0.0f, x_max };
	band heads = { lo + 0.88f * h, lo + h, 0.0f, x_max };
	band arms = { lo + 0.68f * h, lo + 0.78f * h, 0.45f * x_max, 0.7f * x_max };
	int n;
	double share = dominated(pick_band, &hands, hand, &n);
	print_message("hands: %d vertices, %.1f%% on wrist/hand/fingers/thumb\n", n, 100 * share);
	assert_true(n > 200 && share > 0.95);
	share = dominated(pick_band, &legs, leg, &n);
	print_message("legs: %d vertices, %.1f%% on femur/tibia\n", n, 100 * share);
	assert_true(n > 500 && share > 0.95);
	share = dominated(pick_band, &heads, head, &n);
	print_message("head: %d vertices, %.1f%% on head/neck\n", n, 100 * share);
	assert_true(n > 500 && share > 0.99);
	share = dominated(pick_band, &arms, arm, &n);
	print_message("upper arms: %d vertices, %.1f%% on humerus/radius\n", n, 100 * share);
	assert_true(n > 50 && share > 0.9);

	static skin_weights_stats st;
	skin_weights_stats_compute(&sw, s.count, (const uint32_t (*)[3])body.tri, body.tri_count, &st);
	print_message("fallback %d, smoothness %.4f over %ld edges\n", info.fallback,
		      st.edge_diff_mean, st.edge_count);
	assert_true(st.edge_diff_mean < 0.1);
	/* the root only takes what the bones starting at the root joint leave
	 * across it: never a vertex of its own */
	const int at_root[] = { skel_find(&s, "lowerback"), skel_find(&s, "lhipjoint"),
				skel_find(&s, "rhipjoint") };
	int root_verts = 0;
	for (int v = 0; v < body.vert_count; v++) {
		if (!(skin_weights_of(&sw, v, 0) > 0.0f))
			continue;
		root_verts++;
		float shared = 0;
		for (int k = 0; k < 3; k++)
			shared += skin_weights_of(&sw, v, at_root[k]);
		assert_true(shared > 0.0f);
	}
	print_message("root shares %d vertices\n", root_verts);
	assert_int_equal(st.bone_verts[0], root_verts);
}
int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_makehuman_apose_regions),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
