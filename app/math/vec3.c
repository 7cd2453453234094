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

float vec3_segment_distance(vec3 a, vec3 b, vec3 p)
{
	vec3 ab = vec3_sub(b, a);
	float len2 = vec3_dot(ab, ab);
	float t = len2 > 0.0f ? vec3_dot(vec3_sub(p, a), ab) / len2 : 0.0f;
	t = t < 0.0f ? 0.0f : t > 1.0f ? 1.0f : t;
	return vec3_length(vec3_sub(vec3_madd(a, ab, t), p));
}
