#include "skel.h"

#include <math.h>
#include <string.h>

static double length3(vec3 v)
{
	return sqrt((double)v.x * v.x + (double)v.y * v.y + (double)v.z * v.z);
}

/* reach[b] for every bone; the first beyond the limit (or not finite),
 * else -1. */
static int chain_reach(const skel *s, double *reach, double *most)
{
	int beyond = -1;
	*most = 0;
	for (int i = 0; i < s->count; i++) {
		int b = s->eval_order[i];
		const skel_bone *bone = &s->bone[b];
		double from = b == 0 ? length3(s->root_position) : reach[bone->parent];
		reach[b] = from + length3(bone->offset) + fabs((double)bone->length);
		if (!(reach[b] <= *most))
			*most = isnan(reach[b]) ? INFINITY : reach[b];
		if (beyond < 0 && !(reach[b] <= SKEL_MAX_REACH))
			beyond = b;
	}
	return beyond;
}

double skel_reach(const skel *s)
{
	double reach[SKP_MAX_BONES], most;
	chain_reach(s, reach, &most);
	return most;
}

int skel_beyond_reach(const skel *s)
{
	double reach[SKP_MAX_BONES], most;
	return chain_reach(s, reach, &most);
}

int skel_find(const skel *s, const char *name)
{
	for (int i = 0; i < s->count; i++)
		if (strcmp(s->bone[i].name, name) == 0)
			return i;
	return -1;
}

float skel_angle_to_rad(const skel *s, float value)
{
	return s->angle_in_degrees ? value * (3.14159265358979323846f / 180.0f) : value;
}

double skel_unit_cm(const skel *s)
{
	return fabs((double)s->length_scale - 0.45) < 1e-6 ? 2.54 : 1.0;
}

double skel_length_factor(const skel *s)
{
	return 1.0 / (double)s->length_scale;
}
