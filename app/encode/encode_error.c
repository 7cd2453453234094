#include "encode_error.h"

#include <math.h>

static double point_gap(vec3 ha, quat ga, vec3 hb, quat gb, vec3 axis)
{
	vec3 a = vec3_add(ha, quat_rotate(ga, axis)), b = vec3_add(hb, quat_rotate(gb, axis));
	vec3 d = vec3_sub(a, b);
	return sqrt((double)d.x * d.x + (double)d.y * d.y + (double)d.z * d.z);
}

double encode_joint_error(const skel_pose *ref, const skel_pose *got, int b, double shell)
{
	const float r = (float)shell;
	const vec3 axes[3] = { vec3_make(r, 0, 0), vec3_make(0, r, 0), vec3_make(0, 0, r) };
	double worst = 0;
	for (int i = 0; i < 3; i++)
		worst = fmax(worst, point_gap(ref->head[b], ref->rot[b], got->head[b], got->rot[b], axes[i]));
	return worst;
}

double encode_shell_error(const skel *s, const skel_pose *ref, const skel_pose *got, double shell)
{
	double worst = 0;
	for (int b = 0; b < s->count; b++)
		worst = fmax(worst, encode_joint_error(ref, got, b, shell));
	return worst;
}
