#include "image_accept.h"

#include <math.h>

static int finite3(vec3 v)
{
	return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

static double length3(vec3 v)
{
	return sqrt((double)v.x * v.x + (double)v.y * v.y + (double)v.z * v.z);
}

static skp_status check_bone(const skel_bone *b, skp_error *err)
{
	const char *n = b->name;
	double q = (double)b->axis_rot.w * b->axis_rot.w + (double)b->axis_rot.x * b->axis_rot.x +
		   (double)b->axis_rot.y * b->axis_rot.y + (double)b->axis_rot.z * b->axis_rot.z;
	if (!finite3(b->direction) || !finite3(b->offset) || !finite3(b->axis_angle) || !isfinite(b->length) ||
	    !(b->length >= 0))
		return skp_fail(err, SKP_ERR_RANGE, 0, "skeleton: bone '%s': geometry not finite or a negative length", n);
	if (b->length > 0 && !(length3(b->direction) > 1e-6))
		return skp_fail(err, SKP_ERR_RANGE, 0, "skeleton: bone '%s': length %g along no direction", n,
				(double)b->length);
	if (!(fabs(q - 1.0) <= 1e-3))
		return skp_fail(err, SKP_ERR_RANGE, 0, "skeleton: bone '%s': axis rotation of length %g, not a unit quaternion",
				n, sqrt(q));
	return SKP_OK;
}

skp_status skp_accept_skel(const skel *s, skp_error *err)
{
	if (!finite3(s->root_position))
		return skp_fail(err, SKP_ERR_RANGE, 0, "skeleton: root position not finite");
	for (int i = 0; i < s->count; i++)
		if (check_bone(&s->bone[i], err) != SKP_OK)
			return SKP_ERR_RANGE;
	double reach = skel_reach(s);
	if (!(reach <= SKP_ACCEPT_REACH))
		return skp_fail(err, SKP_ERR_RANGE, 0,
				"skeleton: reaches %g units from the origin (bone lengths, offsets and the root's "
				"position); the fixed-point range is %g", reach, SKP_ACCEPT_REACH);
	return SKP_OK;
}

static void bounds(const mesh *m, vec3 *lo, vec3 *hi)
{
	*lo = *hi = m->pos[0];
	for (int v = 1; v < m->vert_count; v++) {
		vec3 p = m->pos[v];
		*lo = vec3_make(fminf(lo->x, p.x), fminf(lo->y, p.y), fminf(lo->z, p.z));
		*hi = vec3_make(fmaxf(hi->x, p.x), fmaxf(hi->y, p.y), fmaxf(hi->z, p.z));
	}
}

/* Triangles with an area: at least (size x 1e-6)^2 on a body of that size. */
static int with_area(const mesh *m, double size)
{
	int n = 0;
	for (int t = 0; t < m->tri_count; t++) {
		vec3 a = m->pos[m->tri[t][0]], b = m->pos[m->tri[t][1]], c = m->pos[m->tri[t][2]];
		n += length3(vec3_cross(vec3_sub(b, a), vec3_sub(c, a))) > 2e-12 * size * size;
	}
	return n;
}

/* Every joint within the body's bounds grown by grow on each side; the
 * first bone outside, or -1. */
static int joint_outside(const skel *s, const skel_pose *bind, vec3 lo, vec3 hi, float grow)
{
	for (int b = 0; b < s->count; b++) {
		vec3 p[2] = { bind->head[b], bind->tip[b] };
		for (int k = 0; k < 2; k++)
			if (!(p[k].x >= lo.x - grow && p[k].x <= hi.x + grow && p[k].y >= lo.y - grow &&
			      p[k].y <= hi.y + grow && p[k].z >= lo.z - grow && p[k].z <= hi.z + grow))
				return b;
	}
	return -1;
}

static skp_status check_place(const skel *s, const skel_pose *bind, vec3 lo, vec3 hi, float size, skp_error *err)
{
	int b = joint_outside(s, bind, lo, hi, size);
	if (b >= 0)
		return skp_fail(err, SKP_ERR_RANGE, 0,
				"body: bone '%s' of the bind pose lies more than the body's size (%g units) outside it: "
				"the skeleton does not fit this body", s->bone[b].name, (double)size);
	vec3 c = fk_tip_centre(bind, s->count);
	float h = 0.5f * size;
	if (!(c.x >= lo.x - h && c.x <= hi.x + h && c.y >= lo.y - h && c.y <= hi.y + h && c.z >= lo.z - h &&
	      c.z <= hi.z + h))
		return skp_fail(err, SKP_ERR_RANGE, 0,
				"body: the skeleton's centre (%g %g %g), where the camera looks, is off the body (%g units)",
				(double)c.x, (double)c.y, (double)c.z, (double)size);
	return SKP_OK;
}

skp_status skp_accept_body(const skel *s, const skel_pose *bind, const mesh *m, skp_error *err)
{
	vec3 lo, hi;
	if (m->vert_count < 3 || m->tri_count < 1)
		return skp_fail(err, SKP_ERR_RANGE, 0, "body: %d vertices and %d triangles: nothing to show",
				m->vert_count, m->tri_count);
	bounds(m, &lo, &hi);
	vec3 d = vec3_sub(hi, lo);
	float size = fmaxf(d.x, fmaxf(d.y, d.z));
	if (!(fminf(d.x, fminf(d.y, d.z)) > 1e-4f * size))
		return skp_fail(err, SKP_ERR_RANGE, 0, "body: %g x %g x %g units: flat, not a body", (double)d.x,
				(double)d.y, (double)d.z);
	int n = with_area(m, size);
	if (2 * n < m->tri_count)
		return skp_fail(err, SKP_ERR_RANGE, 0, "body: %d of %d triangles have no area (degenerate)",
				m->tri_count - n, m->tri_count);
	return check_place(s, bind, lo, hi, size, err);
}

/* The bone a dof belongs to, and its channel. */
static int dof_channel(const skel *s, int dof)
{
	for (int b = 0; b < s->count; b++) {
		const skel_bone *bone = &s->bone[b];
		if (dof >= bone->dof_offset && dof < bone->dof_offset + bone->channel_count)
			return bone->channel[dof - bone->dof_offset];
	}
	return -1;
}

skp_status skp_accept_clip(const skel *s, const skp_image_clip *c, const float *qmin, const float *qstep,
			   skp_error *err)
{
	if (!(c->fps >= SKP_ACCEPT_MIN_FPS && c->fps <= SKP_ACCEPT_MAX_FPS))
		return skp_fail(err, SKP_ERR_RANGE, 0, "a rate of %g frames a second (expected %g to %g)", (double)c->fps,
				SKP_ACCEPT_MIN_FPS, SKP_ACCEPT_MAX_FPS);
	if (c->frame_count == 0)
		return skp_fail(err, SKP_ERR_RANGE, 0, "it has no frames");
	double reach = skel_reach(s);
	for (int d = 0; d < c->dofs; d++) {
		double lo = qmin[d], hi = lo + (double)SKP_IMAGE_QMAX * qstep[d];
		if (!isfinite(lo) || !isfinite(hi) || !(qstep[d] >= 0))
			return skp_fail(err, SKP_ERR_RANGE, 0, "value %d: quantisation not finite or a negative step", d + 1);
		int ch = dof_channel(s, d);
		double travel = fmax(fabs(lo), fabs(hi));
		if (ch >= SKEL_TX && travel + reach > SKP_ACCEPT_REACH)
			return skp_fail(err, SKP_ERR_RANGE, 0,
					"value %d: a translation of up to %g units takes the skeleton beyond the "
					"fixed-point range (%g)", d + 1, travel, SKP_ACCEPT_REACH);
		if (ch >= 0 && ch < SKEL_TX && travel > SKP_ACCEPT_ANGLE)
			return skp_fail(err, SKP_ERR_RANGE, 0,
					"value %d: a rotation of up to %g, beyond %g either way (a float angle that "
					"large is noise)", d + 1, travel, SKP_ACCEPT_ANGLE);
	}
	return SKP_OK;
}
