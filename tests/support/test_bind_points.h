/* Automatic weights for a list of points, as the binding tests take them
 * (test_bind, test_bind_makehuman). */
#ifndef TEST_BIND_POINTS_H
#define TEST_BIND_POINTS_H

#include "bind.h"

/* Weights p[0..n) with rig into sw (info may be NULL): the test fails
 * unless bind_weights succeeds with n vertices weighted. */
void test_bind_points(const bind_rig *rig, const vec3 *p, int n, skin_weights *sw, bind_info *info);

#endif
