#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "test_bind_points.h"

void test_bind_points(const bind_rig *rig, const vec3 *p, int n, skin_weights *sw, bind_info *info)
{
	skp_error err;
	assert_int_equal(bind_weights(rig, p, n, sw, info, &err), SKP_OK);
	assert_int_equal(sw->vert_count, n);
}
