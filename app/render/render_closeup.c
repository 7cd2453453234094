#include "render_closeup.h"

#include <math.h>

#include "camera.h"

#define CLOSEUP_FOVY 0.6f
#define CLOSEUP_PITCH 0.25f      /* a little from above */

void closeup_pick_init(closeup_pick *c)
{
	c->joint = -1;
	c->held = 0.0f;
}

int closeup_pick_update(closeup_pick *c, const float *score, int n, float dt)
{
	int best = -1;
	for (int j = 0; j < n; j++)
		if (score[j] > 0.0f && (best < 0 || score[j] > score[best]))
			best = j;
	c->held += dt;
	if (best < 0 || best == c->joint)
		return c->joint;
	if (c->joint < 0 || c->joint >= n ||
	    (c->held >= CLOSEUP_HOLD_S && score[best] > CLOSEUP_SWITCH * score[c->joint])) {
		c->joint = best;
		c->held = 0.0f;
	}
	return c->joint;
}

/* The view of a bent joint: square to the plane of the bend (the crease
 * in profile), from the main camera's side of it; none (0) for a joint
 * nearly straight, or bent in a plane seen from high above or below (a
 * raised arm's shoulder: that view shows the face, not the armpit). */
static vec3 bend_normal(vec3 axis, vec3 parent, vec3 d)
{
	vec3 n = vec3_cross(parent, axis);
	float len = vec3_length(n);
	if (len < 0.35f * vec3_length(axis) * vec3_length(parent))
		return vec3_make(0.0f, 0.0f, 0.0f);
	n = vec3_scale(n, 1.0f / len);
	if (fabsf(n.y) > 0.7f)
		return vec3_make(0.0f, 0.0f, 0.0f);
	return vec3_dot(n, d) < 0.0f ? vec3_scale(n, -1.0f) : n;
}

/* Towards d (the main camera's direction, unit) until within about 60
 * degrees of it: the close-up sees the joint from the visitor's side, not
 * through the body from behind. */
static vec3 near_view(vec3 v, vec3 d)
{
	for (int i = 0; i < 4 && vec3_dot(v, d) < 0.5f; i++)
		v = vec3_normalize(vec3_add(v, d));
	return v;
}

/* Where the close-up looks from: across the bend of a bent joint, else
 * the main camera's direction (from the target towards the eye) with its
 * part along the bone taken out, the nearest view across the bone; the
 * main camera's when it already looks nearly along the bone, or the bone
 * is too short to have a direction. */
static vec3 across(vec3 axis, vec3 parent, float main_azimuth)
{
	vec3 d = vec3_make(sinf(main_azimuth) * cosf(CLOSEUP_PITCH), sinf(CLOSEUP_PITCH),
			   cosf(main_azimuth) * cosf(CLOSEUP_PITCH));
	float len = vec3_length(axis);
	if (len < 1e-6f)
		return d;
	vec3 bent = bend_normal(axis, parent, d);
	if (vec3_dot(bent, bent) > 0.0f)
		return near_view(bent, d);
	vec3 u = vec3_scale(axis, 1.0f / len), side = vec3_madd(d, u, -vec3_dot(d, u));
	return vec3_length(side) < 0.2f ? d : near_view(vec3_normalize(side), d);
}

void closeup_camera_follow(closeup_camera *c, vec3 at, vec3 axis, vec3 parent, float main_azimuth, float dt,
			   int immediate)
{
	vec3 d = across(axis, parent, main_azimuth);
	float az = atan2f(d.x, d.z), pitch = fmaxf(-0.35f, fminf(0.9f, asinf(fmaxf(-1.0f, fminf(1.0f, d.y)))));
	if (!c->started || immediate) {
		c->started = 1;
		c->target = at;
		c->azimuth = az;
		c->pitch = pitch;
		return;
	}
	float k = camera_ease_in(dt, CLOSEUP_EASE_S);
	c->target = vec3_add(c->target, vec3_scale(vec3_sub(at, c->target), k));
	c->azimuth += remainderf(az - c->azimuth, 6.2831853f) * k;
	c->pitch += (pitch - c->pitch) * k;
}

float closeup_span_want(float reach, vec3 axis, vec3 parent, float height)
{
	float want = reach > 0.0f ? CLOSEUP_REACH * reach : CLOSEUP_SPAN * height;
	float la = vec3_length(axis), lp = vec3_length(parent);
	if (la > 0.0f && lp > 0.0f && vec3_dot(axis, parent) < 0.5f * la * lp)
		want = fmaxf(want, CLOSEUP_FOLD_SHOWN * fminf(la, lp));
	return fmaxf(CLOSEUP_SPAN_MIN * height, fminf(CLOSEUP_SPAN_MAX * height, want));
}

mat4 closeup_camera_matrix(const closeup_camera *c, float span, float aspect)
{
	float fit = aspect < 1.0f ? aspect : 1.0f;
	float d = span / (sinf(0.5f * CLOSEUP_FOVY) * fit);
	vec3 dir = vec3_make(sinf(c->azimuth) * cosf(c->pitch), sinf(c->pitch), cosf(c->azimuth) * cosf(c->pitch));
	mat4 view = mat4_look_at(vec3_madd(c->target, dir, d), c->target, vec3_make(0, 1, 0));
	mat4 proj = mat4_perspective(CLOSEUP_FOVY, aspect, 0.3f * d, 40.0f * d);
	return mat4_mul(&proj, &view);
}
