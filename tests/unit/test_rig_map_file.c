/* The joint map file (app/import/rig_map_file.c): pairs, comments, blanks,
 * CRLF, names with spaces, `-`, and broken lines with their numbers. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "rig_map_file.h"

static rig_map_file map;

static skp_status parse(const char *text, skp_error *err)
{
	return rig_map_file_parse(text, strlen(text), &map, err);
}

static void test_pairs(void **state)
{
	(void)state;
	skp_error err;
	assert_int_equal(parse("# Mixamo onto CMU\r\n\r\nmixamorig:LeftArm = lhumerus\r\n"
			       "  Upper Arm R\t=\trhumerus   # spaces inside a name\n"
			       "f_index.01.L = -\n"
			       "last=line", &err), SKP_OK);
	assert_int_equal(map.count, 4);
	assert_string_equal(map.entry[0].joint, "mixamorig:LeftArm");
	assert_string_equal(map.entry[0].bone, "lhumerus");
	assert_int_equal(map.entry[0].line, 3);
	assert_string_equal(map.entry[1].joint, "Upper Arm R");
	assert_string_equal(map.entry[1].bone, "rhumerus");
	assert_string_equal(map.entry[2].bone, "-");
	assert_string_equal(map.entry[3].joint, "last");
	assert_int_equal(map.entry[3].line, 6);
	assert_int_equal(parse("", &err), SKP_OK);
	assert_int_equal(map.count, 0);
}

static void broken(const char *text, long line, const char *words)
{
	skp_error err;
	assert_int_not_equal(parse(text, &err), SKP_OK);
	if (err.line != line || !strstr(err.msg, words))
		fail_msg("'%s': got line %ld '%s', want line %ld '%s'", text, err.line, err.msg, line, words);
}

static void test_broken(void **state)
{
	(void)state;
	broken("a = b\nhand.L lhumerus\n", 2, "no '='");
	broken(" = lradius\n", 1, "joint name is empty");
	broken("hand.L =   # nothing\n", 1, "bone name is empty");
	broken("hand.L = l\x01x\n", 1, "control byte \\x01");
	broken("\n\nhand\x7f.L = x\n", 3, "control byte \\x7f");
	char nul[] = "a = b\nc = d\0e\n";
	skp_error err;
	assert_int_not_equal(rig_map_file_parse(nul, sizeof nul - 1, &map, &err), SKP_OK);
	assert_int_equal(err.line, 2);
	assert_non_null(strstr(err.msg, "NUL"));
	char longname[300];
	memset(longname, 'j', sizeof longname);
	memcpy(longname + sizeof longname - 8, " = b\n", 6);
	broken(longname, 1, "longer than");
}

static void test_too_many_pairs(void **state)
{
	(void)state;
	static char text[RIG_MAP_MAX_ENTRIES * 16 + 64];
	size_t n = 0;
	for (int i = 0; i <= RIG_MAP_MAX_ENTRIES; i++)
		n += (size_t)snprintf(text + n, sizeof text - n, "j%d = b\n", i);
	skp_error err;
	assert_int_equal(rig_map_file_parse(text, n, &map, &err), SKP_ERR_LIMIT);
	assert_int_equal(err.line, RIG_MAP_MAX_ENTRIES + 1);
}

static void test_read_missing_file(void **state)
{
	(void)state;
	skp_error err;
	assert_int_equal(rig_map_file_read("/nonexistent/joints.map", &map, &err), SKP_ERR_IO);
	assert_non_null(strstr(err.msg, "No such file"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_pairs),
		cmocka_unit_test(test_broken),
		cmocka_unit_test(test_too_many_pairs),
		cmocka_unit_test(test_read_missing_file),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
