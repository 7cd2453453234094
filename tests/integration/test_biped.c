/* Not a biped, not animated as one (rig_biped.h, bind_shape.h): a
 * quadruped made here (a body on four legs, as OBJ), a box and a figure
 * lying down (Debian's assimp-testmodels), a rigged four-legged creature
 * (Testwuson.X) and Khronos' rigged fox (tests/data/rigs/Fox.glb, whose
 * hind legs slope back enough to pass the spine test: its forepaws stand
 * on the floor) are refused naming why, before a skeleton is fitted into
 * them; --force binds anyway with the same words; a standing body binds. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <unistd.h>

#include "test_paths.h"
#include "test_run.h"

#define ASF "assets/demo.asf"
#define SAMPLES "/usr/share/assimp/models"

/* An axis-aligned box as 8 vertices and 12 triangles after base. */
static void box(FILE *f, int base, float x0, float y0, float z0, float x1, float y1, float z1)
{
	for (int k = 0; k < 8; k++)
		fprintf(f, "v %g %g %g\n", (double)(k & 1 ? x1 : x0), (double)(k & 2 ? y1 : y0), (double)(k & 4 ? z1 : z0));
	static const int q[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
	for (int s = 0; s < 6; s++)
		fprintf(f, "f %d %d %d %d\n", base + q[s][0] + 1, base + q[s][1] + 1, base + q[s][2] + 1, base + q[s][3] + 1);
}

static void test_quadruped_obj(void **state)
{
	(void)state;
	const char *obj = test_scratch("dog.obj"), *log = test_scratch("dog.log"), *w = test_scratch("dog.csv");
	FILE *f = fopen(obj, "w");
	assert_non_null(f);
	fprintf(f, "o dog\n");
	box(f, 0, -0.2f, 0.5f, -0.6f, 0.2f, 0.9f, 0.6f);   /* the body, long along z */
	for (int k = 0; k < 4; k++)
		box(f, 8 * (k + 1), k & 1 ? 0.1f : -0.2f, 0.0f, k & 2 ? 0.4f : -0.6f, k & 1 ? 0.2f : -0.1f, 0.5f,
		    k & 2 ? 0.6f : -0.4f);
	fclose(f);
	assert_int_equal(test_run("%s bind " ASF " %s --group dog -o %s 2> %s", test_tool_path("skintool"), obj, w, log),
			 1);
	test_assert_contains_all(log, (const char *const[]){
		"dog.obj: not a biped: what touches the ground spans 133% by 44% of its height (two feet 70% by 35% at most)",
		"(--force binds it anyway)",
		NULL,
	});
	assert_int_not_equal(access(w, F_OK), 0);
	assert_true(test_run("%s bind " ASF " %s --group dog --force -o %s 2> %s", test_tool_path("skintool"), obj, w,
			     log) == 0);
	assert_true(test_file_contains(log, "not a biped: what touches the ground spans 133% by 44%"));
	assert_true(test_file_contains(log, "(--force: bound anyway)"));
}

static void test_standing_body_binds(void **state)
{
	(void)state;
	const char *obj = test_scratch("body.obj"), *log = test_scratch("body.log");
	assert_int_equal(test_run("%s mannequin " ASF " -o %s 2> /dev/null", test_tool_path("skintool"), obj), 0);
	/* the generated body's first line is cut: it binds as a mesh of one's own */
	assert_int_equal(test_run("sed -i 1d %s && %s bind " ASF " %s -o %s 2> %s", obj, test_tool_path("skintool"), obj,
				  test_scratch("body.csv"), log), 0);
	assert_false(test_file_contains(log, "not a biped"));
}

static void test_samples(void **state)
{
	(void)state;
	if (access(SAMPLES "/OBJ/box.obj", R_OK) || access(SAMPLES "/X/Testwuson.X", R_OK) ||
	    access(SAMPLES "/BLEND/HUMAN.blend", R_OK))
		skip();
	const char *log = test_scratch("s.log"), *w = test_scratch("s.csv");
	assert_int_equal(test_run("%s bind " ASF " " SAMPLES "/OBJ/box.obj -o %s 2> %s", test_tool_path("skintool"), w,
				  log), 1);
	assert_true(test_file_contains(log, "box.obj: not a biped: what touches the ground spans 100% by 100% of its height"));
	assert_int_equal(test_run("%s bind " ASF " " SAMPLES "/BLEND/HUMAN.blend -o %s 2> %s", test_tool_path("skintool"),
				  w, log), 1);
	assert_true(test_file_contains(log, "HUMAN.blend: not a biped: what touches the ground spans 183% by 79%"));
	assert_int_equal(test_run("%s bind " ASF " " SAMPLES "/X/Testwuson.X --weights mesh -o %s 2> %s",
				  test_tool_path("skintool"), w, log), 1);
	assert_true(test_file_contains(log, "Testwuson.X: not a biped: its spine and legs are 104 degrees apart"));
}

/* The fox, with the file's weights and with computed ones: refused as a
 * quadruped first, not for the tearing a human skeleton fitted into it
 * would cause. */
static void test_fox(void **state)
{
	(void)state;
	const char *log = test_scratch("fox.log"), *w = test_scratch("fox.csv");
	static const char *const weights[] = { "", "--weights mesh" };
	for (int k = 0; k < 2; k++) {
		assert_int_equal(test_run("%s bind " ASF " tests/data/rigs/Fox.glb %s -o %s 2> %s",
					  test_tool_path("skintool"), weights[k], w, log), 1);
		test_assert_contains_all(log, (const char *const[]){
			"Fox.glb: not a biped: its arms reach the floor like its legs (their ends 34% of the legs' "
			"height below the feet, a biped's 25% or more above): a quadruped",
			"(--force binds it anyway)",
			NULL,
		});
		assert_false(test_file_contains(log, "tears"));
		assert_false(test_file_contains(log, "put on the skeleton"));
		assert_int_not_equal(access(w, F_OK), 0);
	}
	assert_int_equal(test_run("%s bind " ASF " tests/data/rigs/Fox.glb --force -o %s 2> %s",
				  test_tool_path("skintool"), w, log), 0);
	assert_true(test_file_contains(log, "not a biped: its arms reach the floor"));
	assert_true(test_file_contains(log, "(--force: bound anyway)"));
	assert_int_equal(access(w, F_OK), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_quadruped_obj),
		cmocka_unit_test(test_standing_body_binds),
		cmocka_unit_test(test_samples),
		cmocka_unit_test(test_fox),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
