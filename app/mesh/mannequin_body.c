/* Mannequin parts from a skeleton, by the bones' roles in the pose the body
 * is built around (skel_roles.h). Limb thickness follows
 * the distance to the branch's far end, as a fraction of the body height H:
 * fingertips and toes are thin, shoulders and thighs thick. */
#include <math.h>
#include <string.h>

#include "mannequin.h"
#include "skel_roles.h"

typedef struct body_ctx {
	const skel *s;
	const skel_pose *p;
	manq_body *out;
	skel_roles r;
	float shoulder_y;
} body_ctx;

typedef struct profile_pt {
	float e, r;   /* distance to the far end, radius: both in units of H */
} profile_pt;

static const profile_pt arm_profile[] = {
	{ 0.00f, 0.013f }, { 0.05f, 0.020f }, { 0.09f, 0.019f }, { 0.24f, 0.025f },
	{ 0.40f, 0.033f }, { 0.55f, 0.040f },
};
static const profile_pt leg_profile[] = {
	{ 0.00f, 0.018f }, { 0.05f, 0.024f }, { 0.11f, 0.028f }, { 0.36f, 0.031f },
	{ 0.60f, 0.050f }, { 0.70f, 0.056f },
};

static float profile(const profile_pt *pt, int n, float e)
{
	if (e <= pt[0].e)
		return pt[0].r;
	for (int i = 1; i < n; i++)
		if (e <= pt[i].e)
			return pt[i - 1].r + (pt[i].r - pt[i - 1].r) * (e - pt[i - 1].e) / (pt[i].e - pt[i - 1].e);
	return pt[n - 1].r;
}

static float bone_len(const body_ctx *c, int b)
{
	return vec3_length(vec3_sub(c->p->tip[b], c->p->head[b]));
}

/* The shoulders are the highest arm joint, kept below the head. */
static void find_shoulders(body_ctx *c)
{
	float arm_top = -INFINITY;
	for (int b = 1; b < c->s->count; b++)
		if (c->r.arm[b])
			arm_top = fmaxf(arm_top, fmaxf(c->p->head[b].y, c->p->tip[b].y));
	c->shoulder_y = fminf(arm_top, c->r.ymax - 0.12f * c->r.H);
	if (arm_top == -INFINITY)
		c->shoulder_y = c->r.ymax - 0.18f * c->r.H;
}

static manq_part *add_part(body_ctx *c, vec3 a, vec3 b, float ra, float rb)
{
	manq_part *q = &c->out->part[c->out->count++];
	memset(q, 0, sizeof *q);
	q->a = a;
	q->b = b;
	q->len = vec3_length(vec3_sub(b, a));
	q->axis = q->len > 0.0f ? vec3_scale(vec3_sub(b, a), 1.0f / q->len) : q->axis;
	q->ra = ra * c->r.H;
	q->rb = rb * c->r.H;
	q->cap_scale = 1.0f;
	q->flat = c->r.up;
	q->flat_scale = 1.0f;
	return q;
}

/* The point where the spine (root, then the spine bones' tips) first
 * reaches height y; its top when it never does. */
static vec3 spine_at(const body_ctx *c, float y)
{
	int chain[SKP_MAX_BONES], n = 0;
	for (int b = c->r.head_bone; b > 0; b = c->s->bone[b].parent)
		chain[n++] = b;
	vec3 prev = c->p->tip[0];
	if (prev.y >= y)
		return prev;
	for (int i = n - 1; i >= 0; i--) {
		vec3 cur = c->p->tip[chain[i]];
		if (cur.y >= y) {
			float t = (y - prev.y) / (cur.y - prev.y);
			return vec3_add(prev, vec3_scale(vec3_sub(cur, prev), t));
		}
		prev = cur;
	}
	return prev;
}

/* Wider than deep, with flat ends at the crotch and below the shoulders. */
static void add_trunk(body_ctx *c)
{
	float H = c->r.H;
	vec3 chest = spine_at(c, c->shoulder_y - 0.07f * H);
	vec3 pelvis = spine_at(c, fminf(fmaxf(c->p->tip[0].y, c->r.ymin + 0.4f * H), chest.y));
	manq_part *t = add_part(c, pelvis, chest, 0.095f, 0.10f);
	t->cap_scale = 0.10f / 0.07f;
	t->flat = c->r.depth;
	t->flat_scale = 1.5f;

	const skel_pose *p = c->p;
	vec3 skull = p->head[c->r.head_bone];
	add_part(c, chest, skull.y > chest.y ? skull : chest, 0.032f, 0.028f);
}

/* Crown at the head bone's tip; deeper than wide. */
static void add_head(body_ctx *c)
{
	const skel_pose *p = c->p;
	float H = c->r.H, r = 0.054f;
	vec3 top = p->tip[c->r.head_bone];
	vec3 u = vec3_normalize(vec3_sub(top, p->head[c->r.head_bone]));
	if (u.y < 0.5f)
		u = c->r.up;
	vec3 a = vec3_madd(top, u, -r * H);
	vec3 b = vec3_madd(top, u, -(0.125f - r) * H);
	manq_part *h = add_part(c, b, a, r, r);
	h->flat = c->r.side;
	h->flat_scale = 0.054f / 0.044f;
}

/* Hands and feet are flattened vertically (palms down in the rest pose of
 * the T-posed mocap skeletons). */
static void add_limb(body_ctx *c, int b)
{
	float e0 = (bone_len(c, b) + c->r.reach[b]) / c->r.H, e1 = c->r.reach[b] / c->r.H;
	const profile_pt *pr = c->r.leg[b] ? leg_profile : arm_profile;
	int n = c->r.leg[b] ? (int)(sizeof leg_profile / sizeof leg_profile[0])
			  : (int)(sizeof arm_profile / sizeof arm_profile[0]);
	manq_part *q = add_part(c, c->p->head[b], c->p->tip[b], profile(pr, n, e0), profile(pr, n, e1));
	if (c->r.leg[b] && e0 <= 0.13f)
		q->flat_scale = 1.25f;
	else if (!c->r.leg[b] && e0 <= 0.09f)
		q->flat_scale = 1.6f;
}

static vec3 min3(vec3 a, vec3 b)
{
	return vec3_make(fminf(a.x, b.x), fminf(a.y, b.y), fminf(a.z, b.z));
}

static vec3 max3(vec3 a, vec3 b)
{
	return vec3_make(fmaxf(a.x, b.x), fmaxf(a.y, b.y), fmaxf(a.z, b.z));
}

/* Each part's segment box (the field culls with it) and the whole body's. */
static void find_bounds(manq_body *body)
{
	body->lo = vec3_make(INFINITY, INFINITY, INFINITY);
	body->hi = vec3_make(-INFINITY, -INFINITY, -INFINITY);
	for (int i = 0; i < body->count; i++) {
		manq_part *q = &body->part[i];
		q->r_max = fmaxf(q->ra, q->rb);
		q->box_lo = min3(q->a, q->b);
		q->box_hi = max3(q->a, q->b);
		vec3 r = vec3_make(q->r_max, q->r_max, q->r_max);
		body->lo = min3(body->lo, vec3_sub(q->box_lo, r));
		body->hi = max3(body->hi, vec3_add(q->box_hi, r));
	}
}

static int finite3(vec3 v)
{
	return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

skp_status manq_body_from_skel(const skel *s, const skel_pose *rest, manq_body *out, skp_error *err)
{
	static body_ctx ctx_zero;
	body_ctx c = ctx_zero;
	c.s = s;
	c.p = rest;
	c.out = out;
	out->count = 0;
	if (s->count < 2)
		return skp_fail(err, SKP_ERR_RANGE, 0, "the skeleton has no bones");
	for (int b = 0; b < s->count; b++)
		if (!finite3(rest->head[b]) || !finite3(rest->tip[b]))
			return skp_fail(err, SKP_ERR_RANGE, 0, "bone '%s' has no finite rest position",
					s->bone[b].name);
	skel_find_roles(s, rest, &c.r);
	if (!(c.r.H > 0.0f))
		return skp_fail(err, SKP_ERR_RANGE, 0, "the skeleton has no extent in its rest pose");
	/* squared distances must not overflow a float */
	if (!(c.r.H < 1e15f))
		return skp_fail(err, SKP_ERR_RANGE, 0, "the skeleton is %g units tall: too large", (double)c.r.H);
	find_shoulders(&c);
	out->height = c.r.H;
	out->blend = 0.02f * c.r.H;
	add_trunk(&c);
	add_head(&c);
	for (int b = 1; b < s->count; b++)
		if (!c.r.spine[b])
			add_limb(&c, b);
	find_bounds(out);
	return SKP_OK;
}
