/* skinplay plays a user's own mesh as given, with no flags: the MakeHuman
 * base mesh (an A-pose in decimetres, 138 groups of helper geometry) on
 * CMU 02, one frame drawn headless. Apart from test_user_mesh.c, whose
 * bind checks need no GL and so also run under qemu-user (rpi4). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>

#include "test_paths.h"
#include "test_run.h"

static void test_skinplay_plays_the_mesh_as_given(void **state)
{
	(void)state;
	if (!test_data_path("mesh/makehuman/base.obj"))
		skip();
	char asf[4096];
	snprintf(asf, sizeof asf, "%s", test_data_path("mocap/cmu/02.asf"));
	const char *out = test_scratch("mh_frames");
	assert_int_equal(test_run("%s --asf %s --amc %s --mesh %s --platform surfaceless --size 160x120 --frames 1 "
				  "--out %s > /dev/null 2>&1", test_tool_path("skinplay"), asf,
				  test_data_path("mocap/cmu/02_01.amc"), test_data_path("mesh/makehuman/base.obj"), out),
			 0);
	char png[4200];
	snprintf(png, sizeof png, "%s/frame_000001.png", out);
	size_t size = 0;
	char *data = test_read_file(png, &size);
	assert_non_null(data);
	free(data);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_skinplay_plays_the_mesh_as_given),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
