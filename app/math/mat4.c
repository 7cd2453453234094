#include "mat4.h"

#include <math.h>
#include <string.h>

mat4 mat4_identity(void)
{
	mat4 r;
	memset(&r, 0, sizeof r);
	r.m[0] = r.m[5] = r.m[10] = r.m[15] = 1.0f;
	return r;
}

mat4 mat4_mul(const mat4 *a, const mat4 *b)
{
	mat4 r;
	for (int c = 0; c < 4; c++)
		for (int row = 0; row < 4; row++) {
			float s = 0.0f;
			for (int k = 0; k < 4; k++)
				s += a->m[k * 4 + row] * b->m[c * 4 + k];
			r.m[c * 4 + row] = s;
		}
	return r;
}

mat4 mat4_perspective(float fovy, float aspect, float n, float f)
{
	mat4 r;
	memset(&r, 0, sizeof r);
	float t = 1.0f / tanf(fovy * 0.5f);
	r.m[0] = t / aspect;
	r.m[5] = t;
	r.m[10] = (f + n) / (n - f);
	r.m[11] = -1.0f;
	r.m[14] = 2.0f * f * n / (n - f);
	return r;
}

mat4 mat4_ortho(float l, float rt, float b, float t, float n, float f)
{
	mat4 r = mat4_identity();
	r.m[0] = 2.0f / (rt - l);
	r.m[5] = 2.0f / (t - b);
	r.m[10] = -2.0f / (f - n);
	r.m[12] = -(rt + l) / (rt - l);
	r.m[13] = -(t + b) / (t - b);
	r.m[14] = -(f + n) / (f - n);
	return r;
}

mat4 mat4_look_at(vec3 eye, vec3 target, vec3 up)
{
	vec3 f = vec3_normalize(vec3_sub(target, eye));
	vec3 s = vec3_normalize(vec3_cross(f, up));
	vec3 u = vec3_cross(s, f);
	mat4 r = mat4_identity();
	r.m[0] = s.x; r.m[4] = s.y; r.m[8] = s.z;
	r.m[1] = u.x; r.m[5] = u.y; r.m[9] = u.z;
	r.m[2] = -f.x; r.m[6] = -f.y; r.m[10] = -f.z;
	r.m[12] = -vec3_dot(s, eye);
	r.m[13] = -vec3_dot(u, eye);
	r.m[14] = vec3_dot(f, eye);
	return r;
}

mat4 mat4_rotate_z90(int quarter_turns)
{
	static const float c[4] = { 1, 0, -1, 0 }, s[4] = { 0, 1, 0, -1 };
	int q = ((quarter_turns % 4) + 4) % 4;
	mat4 r = mat4_identity();
	r.m[0] = c[q]; r.m[1] = s[q];
	r.m[4] = -s[q]; r.m[5] = c[q];
	return r;
}

vec3 mat4_transform_point(const mat4 *a, vec3 p)
{
	const float *m = a->m;
	float w = m[3] * p.x + m[7] * p.y + m[11] * p.z + m[15];
	vec3 r = vec3_make(m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
			   m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
			   m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]);
	return w != 0.0f ? vec3_scale(r, 1.0f / w) : r;
}
