/* ASF parser: the whole Acclaim spec on hand-made files, broken input with
 * clear errors, and every real skeleton in ../shared/data. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_parse.h"
#include "test_paths.h"

static skel s;

static skp_status parse(const char *text, skp_error *err)
{
	return test_parse_asf(text, strlen(text), &s, err);
}

/* Root keywords in another order and case, axis before order, commas and
 * parentheses as separators, CR line ends, Latin-1 bytes, radians. */
static const char *unusual =
	"# a comment\r:version 1.10\r:name t\xe9st\r:units\r  mass 2.5\r  length 0.01\r  angle rad\r"
	":documentation\r  free text: with ( any ) words, begin end 1 2 3\r"
	":root\r  position 1 2 3\r  axis ZYX\r  order rz RY rx, TX ty TZ\r  orientation 0 0 0.5\r"
	":bonedata\r  begin\r    name a\r    id 7\r    direction 0, 2, 0\r    length 3\r"
	"    axis 0.1 0.2 0.3 yzx\r    dof tz l rx\r    limits (-inf inf)\r"
	"           (0.0 1.5)\r (-1e-011, 2)\r  end\r"
	"  begin\r    name stub\r    direction 1 0 0\r    length 0\r    axis 0 0 0 XYZ\r  end\r"
	":hierarchy\r  begin\r    root a\r    a stub\r  end\r";

static void test_unusual_but_valid(void **state)
{
	(void)state;
	skp_error err;
	assert_int_equal(parse(unusual, &err), SKP_OK);
	assert_string_equal(s.name, "t\xe9st");
	assert_string_equal(s.version, "1.10");
	assert_int_equal(s.angle_in_degrees, 0);
	assert_true(fabsf(s.mass_scale - 2.5f) < 1e-6f);
	assert_true(fabsf(s.length_scale - 0.01f) < 1e-9f);
	assert_int_equal(s.count, 3);
	const skel_bone *r = &s.bone[0];
	assert_int_equal(r->channel_count, 6);
	static const uint8_t want[6] = { SKEL_RZ, SKEL_RY, SKEL_RX, SKEL_TX, SKEL_TY, SKEL_TZ };
	assert_memory_equal(r->channel, want, 6);
	assert_int_equal(r->axis_order[0], 2);
	assert_int_equal(r->axis_order[2], 0);
	/* :units length 0.01 applied: lengths read are divided by it */
	assert_true(fabsf(s.root_position.z - 300.0f) < 1e-3f);
	const skel_bone *a = &s.bone[1];
	assert_string_equal(a->name, "a");
	assert_int_equal(a->id, 7);
	assert_true(fabsf(a->direction.y - 1.0f) < 1e-7f); /* normalised */
	assert_true(fabsf(a->length - 300.0f) < 1e-3f);
	assert_int_equal(a->channel_count, 3);
	assert_int_equal(a->channel[0], SKEL_TZ);
	assert_int_equal(a->channel[1], SKEL_L);
	assert_int_equal(a->axis_order[0], 1);
	assert_true(isinf(a->limit[0][0]) && a->limit[0][0] < 0);
	assert_true(fabsf(a->limit[1][1] - 150.0f) < 1e-3f); /* l limits: a length, in the length unit */
	assert_true(a->limit[2][0] < 0 && a->limit[2][0] > -1e-10f);
	assert_int_equal(a->dof_offset, 6);
	assert_int_equal(s.bone[2].channel_count, 0);
	assert_int_equal(s.bone[2].parent, 1);
	assert_int_equal(s.dof_count, 9);
}

static void test_hierarchy_may_list_children_before_parents(void **state)
{
	(void)state;
	const char *t = ":root\n:bonedata\nbegin\nname c\nend\nbegin\nname p\nend\n"
			":hierarchy\nbegin\np c\nroot p\nend\n";
	skp_error err;
	assert_int_equal(parse(t, &err), SKP_OK);
	/* c (index 1) has parent p (index 2): evaluation must visit p first */
	assert_int_equal(s.eval_order[1], 2);
	assert_int_equal(s.eval_order[2], 1);
}

typedef struct bad_case {
	const char *text;
	long line;
	const char *needle;
} bad_case;

static const bad_case bad[] = {
	{ ":root\n  order TX TY TQ\n", 2, "unknown channel 'TQ'" },
	{ ":root\n  position 1 2\n", 2, "expects 3 value(s), found 2" },
	{ ":root\n  spin 1\n", 2, "unknown keyword 'spin'" },
	{ ":root\n  axis XXY\n", 2, "permutation of XYZ" },
	{ ":units\n  angle grad\n", 2, "expected deg or rad" },
	{ ":units\n  length 0\n", 2, "'length': expected a positive scale, found '0'" },
	{ ":units\n  mass -1\n", 2, "'mass': expected a positive scale, found '-1'" },
	{ ":root\n:bonedata\n  name x\n", 3, "expected 'begin'" },
	{ ":root\n:bonedata\n begin\n  name a\n  length 1.2.3\n", 5, "expected a number, found '1.2.3'" },
	{ ":root\n:bonedata\n begin\n  name a\n  length -1\n", 5, "not negative" },
	{ ":root\n:bonedata\n begin\n  name a\n  direction 0 0 0\n  length 2\n end\n", 7,
	  "'direction' is 0 0 0 but 'length' is 2" },
	{ ":root\n:bonedata\n begin\n  name a\n  dof rx rx\n", 5, "listed twice" },
	{ ":root\n:bonedata\n begin\n  name a\n  limits (0 1)\n", 5, "'limits' before 'dof'" },
	{ ":root\n:bonedata\n begin\n  name a\n  dof rx ry\n  limits (0 1)\n  end\n", 7, "needs 2 more" },
	{ ":root\n:bonedata\n begin\n  name a\n  dof rx\n  limits (0 1) (2 3)\n", 6, "more limit values" },
	{ ":root\n:bonedata\n begin\n  name a\n  wobble 1\n", 5, "unknown keyword 'wobble'" },
	{ ":root\n:bonedata\n begin\n  name root\n", 4, "may not be named 'root'" },
	{ ":root\n:bonedata\n begin\n  length 1\n end\n", 5, "without a 'name'" },
	{ ":root\n:bonedata\n begin\n name a\n end\n begin\n name a\n end\n", 8, "used twice" },
	{ ":root\n:bonedata\n begin\n  name a\n", 4, "missing 'end'" },
	{ ":root\n:bonedata\n begin\n  name a\n:hierarchy\n", 5, "missing 'end'" },
	{ ":root\n:bonedata\n begin\n name a\n end\n:hierarchy\n begin\n root b\n end\n", 8, "unknown bone 'b'" },
	{ ":root\n:bonedata\n begin\n name a\n end\n:hierarchy\n begin\n end\n", 8, "no parent" },
	{ ":root\n:bonedata\n begin\n name a\n end\n begin\n name b\n end\n:hierarchy\n begin\n root a b\n a b\n end\n", 12, "two parents" },
	{ ":root\n:bonedata\n begin\n name a\n end\n begin\n name b\n end\n:hierarchy\n begin\n a b\n b a\n end\n", 13, "cycle" },
	{ ":root\n:bonedata\n begin\n name a\n end\n begin\n name b\n end\n begin\n name c\n end\n:hierarchy\n begin\n root a\n c b\n b c\n end\n", 17, "cycle" },
	{ ":root\n:bonedata\n begin\n name a\n end\n:hierarchy\n begin\n a root\n end\n", 8, "root cannot have a parent" },
	{ ":bonedata\n", 1, "no :root" },
	{ "garbage here\n", 1, "expected a ':' keyword" },
	{ ":root\n:bonedata\n begin\n name a_very_long_bone_name_that_goes_on_and_on_forever_and_ever\n", 4, "SKP_MAX_NAME" },
	/* what forward kinematics cannot represent: NaN rows otherwise */
	{ ":root\n:bonedata\n begin\n  name a\n  axis 1e308 0 0 XYZ\n", 5, "'axis': value '1e308' is beyond a float's range" },
	{ ":root\n:bonedata\n begin\n  name a\n  direction 1 0 0\n  length 3e38\n end\n:hierarchy\n begin\n root a\n end\n",
	  0, "bone 'a': the skeleton reaches beyond" },
	{ ":root\n  position 1e30 0 0\n:bonedata\n begin\n  name a\n end\n:hierarchy\n begin\n root a\n end\n", 0,
	  "bone 'root': the skeleton reaches beyond" },
	{ ":root\n:bonedata\n begin\n  name a\n  direction 1e30 0 0\n  length 1\n end\n:hierarchy\n begin\n root a\n end\n",
	  0, "bone 'a': its direction cannot be normalised" },
	/* names reach terminals: control characters refused, quoted escaped */
	{ ":root\n:bonedata\n begin\n  name a\x1b[31mb\n", 4, "name 'a\\x1b[31mb' holds a control character" },
};

static void test_broken_inputs_name_line_and_expectation(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		skp_error err;
		skp_status rc = parse(bad[i].text, &err);
		if (rc == SKP_OK || err.line != bad[i].line || !strstr(err.msg, bad[i].needle))
			fail_msg("case %zu: rc %d line %ld '%s' (wanted line %ld, '%s')", i, rc, err.line,
				 err.msg, bad[i].line, bad[i].needle);
	}
}

static void test_cycle_detected(void **state)
{
	(void)state;
	/* a and b parent each other, detached from the root */
	const char *t = ":root\n:bonedata\n begin\n name a\n end\n begin\n name b\n end\n"
			":hierarchy\n begin\n a b\n end\n";
	skp_error err;
	assert_int_not_equal(parse(t, &err), SKP_OK);
	assert_non_null(strstr(err.msg, "no parent"));
}

static void test_too_many_bones(void **state)
{
	(void)state;
	static char text[64 * (SKP_MAX_BONES + 8)];
	size_t n = (size_t)snprintf(text, sizeof text, ":root\n:bonedata\n");
	for (int i = 0; i < SKP_MAX_BONES + 4; i++)
		n += (size_t)snprintf(text + n, sizeof text - n, "begin\nname b%d\nend\n", i);
	skp_error err;
	assert_int_equal(test_parse_asf(text, n, &s, &err), SKP_ERR_LIMIT);
	assert_non_null(strstr(err.msg, "SKP_MAX_BONES"));
	assert_int_equal(err.line, 2 + 3 * (SKP_MAX_BONES - 1) + 1);
}

static void test_truncated_real_file_never_crashes(void **state)
{
	(void)state;
	const char *path = test_data_path("mocap/cmu/02.asf");
	if (!path)
		skip();
	size_t n;
	char *data = test_read_file(path, &n);
	assert_non_null(data);
	int ok = 0;
	/* every prefix: parses or fails cleanly, ASan checks the reads */
	for (size_t cut = 0; cut < n; cut += 7) {
		skp_error err;
		if (test_parse_asf(data, cut, &s, &err) == SKP_OK)
			ok++;
		else
			assert_true(err.msg[0] != '\0');
	}
	/* a cut inside :hierarchy's last line still parses (fewer children
	 * attached is an error); the whole file parses */
	skp_error err;
	assert_int_equal(test_parse_asf(data, n, &s, &err), SKP_OK);
	free(data);
	(void)ok;
}

typedef struct real_case {
	const char *path;
	int bones;     /* including root */
	int dof;
	const char *first_bone, *zero_length_bone;
} real_case;

static const real_case real[] = {
	{ "mocap/cmu/02.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/cmu/07.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/cmu/09.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/cmu/131.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/cmu/135.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/cmu/lambada.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/cmu/kick.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/cmu/backflip.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/hdm05/HDM_dg.asf", 31, 62, "lhipjoint", NULL },
	{ "mocap/endorphin/skeleton.asf", 34, 87, "LowerSpineJoint_dum", "UpperSpineJoint" },
};

static void test_real_skeletons(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	for (size_t i = 0; i < sizeof real / sizeof real[0]; i++) {
		skp_error err;
		skp_status rc = test_parse_asf_file(test_data_path(real[i].path), &s, &err);
		if (rc != SKP_OK)
			fail_msg("%s:%ld: %s", real[i].path, err.line, err.msg);
		assert_int_equal(s.count, real[i].bones);
		assert_int_equal(s.dof_count, real[i].dof);
		assert_string_equal(s.bone[1].name, real[i].first_bone);
		if (real[i].zero_length_bone) {
			int b = skel_find(&s, real[i].zero_length_bone);
			assert_true(b > 0);
			assert_true(s.bone[b].length == 0.0f);
		}
	}
}

static void test_cmu_details(void **state)
{
	(void)state;
	const char *path = test_data_path("mocap/cmu/02.asf");
	if (!path)
		skip();
	skp_error err;
	assert_int_equal(test_parse_asf_file(path, &s, &err), SKP_OK);
	assert_true(fabsf(s.length_scale - 0.45f) < 1e-6f);
	int lh = skel_find(&s, "lhipjoint"), lf = skel_find(&s, "lfemur"), rc = skel_find(&s, "rclavicle");
	assert_int_equal(s.bone[lh].channel_count, 0);
	assert_int_equal(s.bone[lf].parent, lh);
	assert_int_equal(s.bone[rc].channel_count, 2);
	assert_int_equal(s.bone[rc].channel[0], SKEL_RY);
	assert_int_equal(s.bone[lf].has_limits, 1);
	assert_true(s.bone[lf].limit[0][0] == -160.0f);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_unusual_but_valid),
		cmocka_unit_test(test_hierarchy_may_list_children_before_parents),
		cmocka_unit_test(test_broken_inputs_name_line_and_expectation),
		cmocka_unit_test(test_cycle_detected),
		cmocka_unit_test(test_too_many_bones),
		cmocka_unit_test(test_truncated_real_file_never_crashes),
		cmocka_unit_test(test_real_skeletons),
		cmocka_unit_test(test_cmu_details),
	};
	return cmocka_run_group_tests_name("asf", tests, NULL, NULL);
}
