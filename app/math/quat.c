#include "quat.h"

#include <math.h>

quat quat_mul(quat a, quat b)
{
	quat r = {
		a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
		a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
		a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
		a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
	};
	return r;
}

quat quat_from_axis_angle(vec3 unit_axis, float radians)
{
	/* Half angles in double: wound-up mocap angles (1251 degrees) would
	 * otherwise lose bits in the argument reduction. */
	double h = 0.5 * (double)radians;
	float s = (float)sin(h);
	quat q = { (float)cos(h), unit_axis.x * s, unit_axis.y * s, unit_axis.z * s };
	return q;
}

quat quat_from_basis_angle(int axis, float radians)
{
	vec3 a = vec3_make(axis == 0, axis == 1, axis == 2);
	return quat_from_axis_angle(a, radians);
}

quat quat_normalize(quat q)
{
	float n = sqrtf(quat_dot(q, q));
	if (n <= 0.0f)
		return quat_identity();
	float inv = 1.0f / n;
	quat r = { q.w * inv, q.x * inv, q.y * inv, q.z * inv };
	return r;
}

vec3 quat_rotate(quat q, vec3 v)
{
	/* v + 2w (u x v) + 2 u x (u x v): 15 multiplies instead of two products */
	vec3 u = vec3_make(q.x, q.y, q.z);
	vec3 t = vec3_scale(vec3_cross(u, v), 2.0f);
	return vec3_add(vec3_madd(v, t, q.w), vec3_cross(u, t));
}

void quat_to_mat3(quat q, float m[3][3])
{
	float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
	float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
	float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;

	m[0][0] = 1 - 2 * (yy + zz); m[0][1] = 2 * (xy - wz);     m[0][2] = 2 * (xz + wy);
	m[1][0] = 2 * (xy + wz);     m[1][1] = 1 - 2 * (xx + zz); m[1][2] = 2 * (yz - wx);
	m[2][0] = 2 * (xz - wy);     m[2][1] = 2 * (yz + wx);     m[2][2] = 1 - 2 * (xx + yy);
}

quat quat_from_mat3(const float m[3][3])
{
	float tr = m[0][0] + m[1][1] + m[2][2];
	quat q;

	if (tr > 0.0f) {
		float s = sqrtf(tr + 1.0f) * 2.0f;
		q.w = 0.25f * s;
		q.x = (m[2][1] - m[1][2]) / s;
		q.y = (m[0][2] - m[2][0]) / s;
		q.z = (m[1][0] - m[0][1]) / s;
	} else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
		float s = sqrtf(1.0f + m[0][0] - m[1][1] - m[2][2]) * 2.0f;
		q.w = (m[2][1] - m[1][2]) / s;
		q.x = 0.25f * s;
		q.y = (m[0][1] + m[1][0]) / s;
		q.z = (m[0][2] + m[2][0]) / s;
	} else if (m[1][1] > m[2][2]) {
		float s = sqrtf(1.0f + m[1][1] - m[0][0] - m[2][2]) * 2.0f;
		q.w = (m[0][2] - m[2][0]) / s;
		q.x = (m[0][1] + m[1][0]) / s;
		q.y = 0.25f * s;
		q.z = (m[1][2] + m[2][1]) / s;
	} else {
		float s = sqrtf(1.0f + m[2][2] - m[0][0] - m[1][1]) * 2.0f;
		q.w = (m[1][0] - m[0][1]) / s;
		q.x = (m[0][2] + m[2][0]) / s;
		q.y = (m[1][2] + m[2][1]) / s;
		q.z = 0.25f * s;
	}
	return quat_normalize(q);
}
