#include "vec3.h"

#include <math.h>

float vec3_length(vec3 a)
{
	return sqrtf(vec3_dot(a, a));
}

vec3 vec3_normalize(vec3 a)
{
	float len = vec3_length(a);
	return len > 0.0f ? vec3_scale(a, 1.0f / len) : a;
}

vec3 vec3_min(vec3 a, vec3 b)
{
	return vec3_make(fminf(a.x, b.x), fminf(a.y, b.y), fminf(a.z, b.z));
}

vec3 vec3_max(vec3 a, vec3 b)
{
	return vec3_make(fmaxf(a.x, b.x), fmaxf(a.y, b.y), fmaxf(a.z, b.z));
}
