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
