#include "dq.h"

#include <math.h>

static quat quat_scale(quat q, float s)
{
	quat r = { q.w * s, q.x * s, q.y * s, q.z * s };
	return r;
}

static quat quat_madd(quat a, quat b, float s)
{
	quat r = { a.w + b.w * s, a.x + b.x * s, a.y + b.y * s, a.z + b.z * s };
	return r;
}

dq dq_identity(void)
{
	dq d = { quat_identity(), { 0.0f, 0.0f, 0.0f, 0.0f } };
	return d;
}

dq dq_from_quat_trans(quat q, vec3 t)
{
	quat tq = { 0.0f, 0.5f * t.x, 0.5f * t.y, 0.5f * t.z };
	dq d = { q, quat_mul(tq, q) };
	return d;
}

dq dq_from_rigid(const rigid *m)
{
	return dq_from_quat_trans(quat_from_mat3(m->r), m->t);
}

vec3 dq_translation(const dq *d)
{
	quat t = quat_mul(d->dual, quat_conj(d->real));
	return vec3_make(2.0f * t.x, 2.0f * t.y, 2.0f * t.z);
}

rigid dq_to_rigid(const dq *d)
{
	return rigid_from_quat_trans(d->real, dq_translation(d));
}

dq dq_mul(const dq *a, const dq *b)
{
	quat ad_br = quat_mul(a->dual, b->real);
	quat ar_bd = quat_mul(a->real, b->dual);
	dq r = { quat_mul(a->real, b->real), quat_madd(ar_bd, ad_br, 1.0f) };
	return r;
}

dq dq_normalize(dq d)
{
	float n2 = quat_dot(d.real, d.real);
	if (n2 <= 0.0f)
		return dq_identity();
	float inv = 1.0f / sqrtf(n2);
	dq r = { quat_scale(d.real, inv), quat_scale(d.dual, inv) };

	r.dual = quat_madd(r.dual, r.real, -quat_dot(r.real, r.dual));
	return r;
}

vec3 dq_transform_point(const dq *d, vec3 p)
{
	vec3 rv = vec3_make(d->real.x, d->real.y, d->real.z);
	vec3 dv = vec3_make(d->dual.x, d->dual.y, d->dual.z);
	float rw = d->real.w, dw = d->dual.w;

	/* Kavan et al.: rotation and translation straight from the dq, cheaper
	 * than building the matrix when every vertex has its own dq. */
	vec3 a = vec3_madd(vec3_cross(rv, p), p, rw);
	vec3 rot = vec3_madd(p, vec3_cross(rv, a), 2.0f);
	vec3 t = vec3_add(vec3_madd(vec3_scale(dv, rw), rv, -dw), vec3_cross(rv, dv));
	return vec3_madd(rot, t, 2.0f);
}

vec3 dq_transform_normal(const dq *d, vec3 n)
{
	vec3 rv = vec3_make(d->real.x, d->real.y, d->real.z);
	vec3 a = vec3_madd(vec3_cross(rv, n), n, d->real.w);
	return vec3_madd(n, vec3_cross(rv, a), 2.0f);
}

quat dq_blend_pivot(const dq *bone_dqs, const uint16_t *bone_idx,
		    const float *weights, int count)
{
	int best = 0;

	for (int i = 1; i < count; i++)
		if (weights[i] > weights[best])
			best = i;
	return count > 0 ? bone_dqs[bone_idx[best]].real : quat_identity();
}

dq dq_blend(const dq *bone_dqs, const uint16_t *bone_idx, const float *weights,
	    int count, quat pivot)
{
	dq b = { { 0.0f, 0.0f, 0.0f, 0.0f }, { 0.0f, 0.0f, 0.0f, 0.0f } };

	for (int i = 0; i < count; i++) {
		const dq *d = &bone_dqs[bone_idx[i]];
		/* q and -q are the same rotation; summing across hemispheres
		 * would take the long way round (or cancel out). */
		float w = quat_dot(d->real, pivot) < 0.0f ? -weights[i] : weights[i];

		b.real = quat_madd(b.real, d->real, w);
		b.dual = quat_madd(b.dual, d->dual, w);
	}
	return b;
}

dq dq_blend_normalized(const dq *bone_dqs, const uint16_t *bone_idx,
		       const float *weights, int count, quat pivot)
{
	dq b = dq_blend(bone_dqs, bone_idx, weights, count, pivot);
	float n2 = quat_dot(b.real, b.real);

	if (!(n2 > 0.0f))
		return dq_identity();
	float inv = 1.0f / sqrtf(n2);
	b.real = quat_scale(b.real, inv);
	b.dual = quat_scale(b.dual, inv);
	return b;
}
