/* skintool view: a rig and a motion played in one command (bound and
 * packed by skintool, played by skinplay), its temporary image removed
 * whatever happened; a missing mesh and bad usage refused. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_paths.h"
#include "test_run.h"

/* Temporary images of skintool view left in /tmp. */
static size_t left_behind(void)
{
	glob_t g;
	size_t n = glob("/tmp/skintool-view-*", 0, NULL, &g) == 0 ? g.gl_pathc : 0;
	globfree(&g);
	return n;
}

static void test_rig_and_bvh_in_one_command(void **state)
{
	(void)state;
	const char *glb = test_data_path("mesh/orange_juice_male_base/male_base_mesh.glb");
	const char *bvh = test_data_path("mocap/cmu_bvh/131_01.bvh");
	if (!glb || !bvh)
		skip();
	/* under the sanitizers or an emulator its first 120 frames, under its
	 * name: each view packed all 994 in about 18 s there */
	if (test_slow())
		bvh = test_clip_head(bvh, 120, NULL);
	size_t before = left_behind();
	const char *out = test_scratch("frames"), *log = test_scratch("view.log");
	assert_int_equal(test_run("%s view '%s' '%s' -- --platform surfaceless --size 160x90 --frames 40 --every 20 "
				  "-o '%s' 2>'%s'", test_tool_path("skintool"), glb, bvh, out, log),
			 0);
	static const char *const said[] = { "weights computed from the skeleton", "image: playing /tmp/skintool-view-",
					    "played 40 frames of 131_01", NULL };
	test_assert_contains_all(log, said);
	assert_int_equal(test_run("test -s '%s/frame_000001.png' && test -s '%s/frame_000021.png'", out, out), 0);
	assert_int_equal(left_behind(), before);
	/* the pack options before --: the artist's weights */
	assert_int_equal(test_run("%s view '%s' '%s' --weights mesh -- --platform surfaceless --size 160x90 "
				  "--frames 2 2>'%s'", test_tool_path("skintool"), glb, bvh, log),
			 0);
	assert_false(test_file_contains(log, "weights computed from the skeleton"));
	assert_int_equal(left_behind(), before);
}

static void test_refusals(void **state)
{
	(void)state;
	const char *log = test_scratch("refused.log");
	size_t before = left_behind();
	assert_int_equal(test_run("%s view 2>'%s'", test_tool_path("skintool"), log), 1);
	static const char *const usage[] = { "give the mesh, then the motion", NULL };
	test_assert_contains_all(log, usage);
	assert_int_equal(test_run("%s view /nonexistent.glb assets/cmu/02.asf assets/cmu/02_01.amc -- --platform "
				  "surfaceless 2>'%s'", test_tool_path("skintool"), log),
			 1);
	static const char *const missing[] = { "/nonexistent.glb", NULL };
	test_assert_contains_all(log, missing);
	assert_false(test_file_contains(log, "image: playing"));
	assert_int_equal(left_behind(), before);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_rig_and_bvh_in_one_command),
		cmocka_unit_test(test_refusals),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
