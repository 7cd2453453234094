#include "rigid.h"

rigid rigid_identity(void)
{
	rigid m = { { { 1.0f, 0.0f, 0.0f }, { 0.0f, 1.0f, 0.0f }, { 0.0f, 0.0f, 1.0f } },
		    { 0.0f, 0.0f, 0.0f } };
	return m;
}

rigid rigid_from_quat_trans(quat q, vec3 t)
{
	rigid m;

	quat_to_mat3(q, m.r);
	m.t = t;
	return m;
}

static vec3 mat3_apply(const float r[3][3], vec3 v)
{
	return vec3_make(r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z,
			 r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
			 r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z);
}

rigid rigid_mul(const rigid *a, const rigid *b)
{
	rigid m;

	/* Built in a local so that rigid_mul(x, x) style aliasing is harmless. */
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			m.r[i][j] = a->r[i][0] * b->r[0][j] + a->r[i][1] * b->r[1][j] +
				    a->r[i][2] * b->r[2][j];
	m.t = vec3_add(mat3_apply(a->r, b->t), a->t);
	return m;
}

rigid rigid_inverse(const rigid *a)
{
	rigid m;

	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			m.r[i][j] = a->r[j][i];
	m.t = vec3_scale(mat3_apply(m.r, a->t), -1.0f);
	return m;
}

vec3 rigid_apply_point(const rigid *a, vec3 p)
{
	return vec3_add(mat3_apply(a->r, p), a->t);
}

vec3 rigid_apply_normal(const rigid *a, vec3 n)
{
	return mat3_apply(a->r, n);
}
