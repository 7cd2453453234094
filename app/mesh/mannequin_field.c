/* The mannequin's implicit field: a smooth union of squashed, tapered
 * capsules. Signed distances are only approximate once squashed, which is
 * fine: only the zero set and the sign matter to the polygoniser. */
#include <math.h>

#include "mannequin.h"

static float clampf(float v, float lo, float hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

static float part_field(const manq_part *q, vec3 p)
{
	vec3 ap = vec3_sub(p, q->a);
	float t = q->len > 0.0f ? clampf(vec3_dot(ap, q->axis) / q->len, 0.0f, 1.0f) : 0.0f;
	vec3 d = vec3_madd(ap, q->axis, -t * q->len);
	/* beyond the ends d has an axial part: squashing it flattens the caps */
	if (q->cap_scale != 1.0f)
		d = vec3_madd(d, q->axis, vec3_dot(d, q->axis) * (q->cap_scale - 1.0f));
	if (q->flat_scale != 1.0f)
		d = vec3_madd(d, q->flat, vec3_dot(d, q->flat) * (q->flat_scale - 1.0f));
	return vec3_length(d) - (q->ra + (q->rb - q->ra) * t);
}

/* Polynomial smooth minimum: equal to min(a, b) once they differ by k. */
static float smooth_min(float a, float b, float k)
{
	float h = clampf(0.5f + 0.5f * (b - a) / k, 0.0f, 1.0f);
	return b + (a - b) * h - k * h * (1.0f - h);
}

static float outside(float v, float lo, float hi)
{
	return v < lo ? lo - v : v > hi ? v - hi : 0.0f;
}

/* Squashing only lengthens d, so a part whose segment box is further than
 * its radius plus the blend width from p cannot lower the union. */
static float box_gap(const manq_part *q, vec3 p)
{
	float gx = outside(p.x, q->box_lo.x, q->box_hi.x);
	float gy = outside(p.y, q->box_lo.y, q->box_hi.y);
	float gz = outside(p.z, q->box_lo.z, q->box_hi.z);
	return sqrtf(gx * gx + gy * gy + gz * gz) - q->r_max;
}

float manq_field_of(const manq_body *b, const uint16_t *which, int n, float far, vec3 p)
{
	float f = INFINITY;
	for (int k = 0; k < n; k++) {
		const manq_part *q = &b->part[which[k]];
		if (f != INFINITY && box_gap(q, p) >= f + b->blend)
			continue;
		float d = part_field(q, p);
		f = f == INFINITY ? d : smooth_min(f, d, b->blend);
	}
	return n > 0 ? f : far;
}

float manq_field(const manq_body *b, vec3 p)
{
	float f = INFINITY;
	for (int i = 0; i < b->count; i++) {
		const manq_part *q = &b->part[i];
		if (f != INFINITY && box_gap(q, p) >= f + b->blend)
			continue;
		float d = part_field(q, p);
		f = f == INFINITY ? d : smooth_min(f, d, b->blend);
	}
	return f;
}

vec3 manq_field_normal(const manq_body *b, vec3 p, float step)
{
	vec3 g;
	g.x = manq_field(b, vec3_make(p.x + step, p.y, p.z)) - manq_field(b, vec3_make(p.x - step, p.y, p.z));
	g.y = manq_field(b, vec3_make(p.x, p.y + step, p.z)) - manq_field(b, vec3_make(p.x, p.y - step, p.z));
	g.z = manq_field(b, vec3_make(p.x, p.y, p.z + step)) - manq_field(b, vec3_make(p.x, p.y, p.z - step));
	return vec3_normalize(g);
}
