/* The quality gate every bind passes (setup_gate.h), through the real
 * command line on the project's own skeleton and its generated body (no
 * shared data needed): the body as bound by skintool passes with every
 * figure reported; weights that leave every vertex to the root, or hand
 * the whole body to one foot, are refused naming the part, the figure and
 * the fix, before anything is written; --force writes them with the same
 * warning; commands with a motion check its frames too. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test_paths.h"
#include "test_run.h"

#define ASF "assets/demo.asf"

/* The generated body; under the sanitizers or an emulator a coarser one
 * (each of the five binds took 6 s under qemu on the default one, and
 * the gate's figures and refusals are the same kinds on it). */
static const char *body_obj(void)
{
	static char path[4096];
	if (!path[0]) {
		snprintf(path, sizeof path, "%s", test_scratch("demo_body.obj"));
		assert_int_equal(test_run("%s mannequin " ASF " %s -o %s 2> /dev/null", test_tool_path("skintool"),
					  test_mannequin_detail(), path), 0);
	}
	return path;
}

/* The demo clip the build generates. */
static const char *demo_amc(void)
{
	static char path[4096];
	snprintf(path, sizeof path, "%s", test_tool_path("assets/demo.amc"));
	return path;
}

/* A weights CSV giving each of the body's vertices to one bone. */
static const char *all_to(const char *bone, const char *name)
{
	const char *csv = test_scratch(name);
	assert_int_equal(test_run("awk 'BEGIN { print \"vertex,bone,weight\" } /^v / { print n++ \",%s,1\" }' %s > %s", bone,
				  body_obj(), csv), 0);
	return csv;
}

static void test_good_bind_passes_with_figures(void **state)
{
	(void)state;
	const char *log = test_scratch("good.log"), *w = test_scratch("good.csv");
	assert_int_equal(test_run("%s bind " ASF " %s --report --motion %s -o %s 2> %s", test_tool_path("skintool"),
				  body_obj(), demo_amc(), w, log), 0);
	test_assert_contains_all(log, (const char *const[]){
		"quality gate: 24 range-of-motion poses, ",
		" motion frames, skeleton extent ",
		"edges ever past 2x, 0 past 3x and 30%: ok",
		"vertices past 12%: ok",
		"limit 25%: ok",
		"limit 0.35: ok",
		NULL,
	});
	assert_false(test_file_contains(log, "motion frames: 0"));
	assert_false(test_file_contains(log, " 0 motion frames"));
}

static void test_root_only_refused(void **state)
{
	(void)state;
	const char *csv = all_to("root", "root.csv"), *log = test_scratch("root.log"), *w = test_scratch("root_w.csv");
	assert_int_equal(test_run("%s bind " ASF " %s --weights %s -o %s 2> %s", test_tool_path("skintool"), body_obj(),
				  csv, w, log), 1);
	test_assert_contains_all(log, (const char *const[]){
		"moves, but 100% of its vertices are bound to the root alone",
		"stays rigid: its vertices follow its bone 0.00 of the way",
		"leave out --weights to compute them",
		"demo_body.obj: bind refused (bind --report prints every figure; --force binds anyway)",
		NULL,
	});
	assert_int_not_equal(access(w, F_OK), 0);
	/* the same gate before a frame is skinned or an image packed */
	assert_int_equal(test_run("%s skin " ASF " %s %s --weights %s --frame 1 --algo dqbs -o %s 2> %s",
				  test_tool_path("skintool"), demo_amc(), body_obj(), csv, test_scratch("f.obj"), log), 1);
	assert_true(test_file_contains(log, "bind refused"));
	assert_int_not_equal(access(test_scratch("f.obj"), F_OK), 0);
	assert_int_equal(test_run("%s bind " ASF " %s --weights %s --force -o %s 2> %s", test_tool_path("skintool"),
				  body_obj(), csv, w, log), 0);
	test_assert_contains_all(log, (const char *const[]){
		"bound to the root alone",
		"demo_body.obj: --force: bound anyway",
		NULL,
	});
	assert_int_equal(access(w, F_OK), 0);
}

static void test_body_on_a_foot_refused(void **state)
{
	(void)state;
	const char *csv = all_to("lfoot", "foot.csv"), *log = test_scratch("foot.log");
	assert_int_equal(test_run("%s bind " ASF " %s --weights %s --report -o %s 2> %s", test_tool_path("skintool"),
				  body_obj(), csv, test_scratch("foot_w.csv"), log), 1);
	/* every vertex keeps its distance to its bone (the foot): the legs,
	 * arms and head that do not follow theirs give it away */
	test_assert_contains_all(log, (const char *const[]){
		"stays rigid: its vertices follow its bone 0.00 of the way",
		"rigid: the region following its bone least follows it 0.00 of the way",
		"bind refused",
		NULL,
	});
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_good_bind_passes_with_figures),
		cmocka_unit_test(test_root_only_refused),
		cmocka_unit_test(test_body_on_a_foot_refused),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
