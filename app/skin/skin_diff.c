#include "skin_diff.h"

#include <math.h>
#include <string.h>

static int nearest_joint(const skel *s, const skel_pose *bind, vec3 p)
{
	int at = 0;
	float best = INFINITY;
	for (int b = 0; b < s->count; b++) {
		vec3 d = vec3_sub(p, bind->head[b]);
		float d2 = vec3_dot(d, d);
		if (d2 < best)
			best = d2, at = b;
	}
	return at;
}

/* Distance from p to the segment head..tip. */
static float to_segment(vec3 p, vec3 head, vec3 tip)
{
	vec3 ab = vec3_sub(tip, head), ap = vec3_sub(p, head);
	float len2 = vec3_dot(ab, ab), t = len2 > 0.0f ? vec3_dot(ap, ab) / len2 : 0.0f;
	t = t < 0.0f ? 0.0f : t > 1.0f ? 1.0f : t;
	return vec3_length(vec3_sub(ap, vec3_scale(ab, t)));
}

void skin_diff_init(skin_diff *d, const skel *s, const skel_pose *bind, const skel_joints *joints,
		    const skin_soa *soa)
{
	d->count = soa->count;
	d->bone_count = s->count;
	memset(d->score, 0, sizeof d->score);
	d->joints = joints;
	for (int v = 0; v < soa->count; v++) {
		vec3 p = vec3_make(soa->px[v], soa->py[v], soa->pz[v]);
		int b = soa->bone[0][v]; /* the largest weight comes first */
		d->joint[v] = (uint8_t)nearest_joint(s, bind, p);
		d->bone[v] = (uint8_t)(b < s->count ? b : SKP_MAX_BONES);
		d->radius[v] = b < s->count ? to_segment(p, bind->head[b], bind->tip[b]) : 0.0f;
	}
}

float skin_diff_between(skin_diff *d, const float *a, const float *b, float *dist)
{
	float most = 0.0f;
	memset(d->score, 0, sizeof d->score);
	/* squared per joint, the root taken once a joint: a vertex costs no
	 * square root unless its distance is asked for */
	for (int v = 0; v < d->count; v++) {
		float dx = a[3 * v] - b[3 * v], dy = a[3 * v + 1] - b[3 * v + 1], dz = a[3 * v + 2] - b[3 * v + 2];
		float e2 = dx * dx + dy * dy + dz * dz;
		float *s = &d->score[d->joint[v]];
		*s = e2 > *s ? e2 : *s;
	}
	if (dist)
		for (int v = 0; v < d->count; v++) {
			float dx = a[3 * v] - b[3 * v], dy = a[3 * v + 1] - b[3 * v + 1], dz = a[3 * v + 2] - b[3 * v + 2];
			dist[v] = sqrtf(dx * dx + dy * dy + dz * dz);
		}
	for (int j = 0; j < d->bone_count; j++) {
		d->score[j] = sqrtf(d->score[j]);
		most = fmaxf(most, d->score[j]);
	}
	return most;
}

/* Vertex v's distance to its bone in pose less the bound one. */
static float moved_from_bone(const skin_diff *d, const skel_pose *pose, const float *pos, int v)
{
	int b = d->bone[v];
	if (b >= d->bone_count)
		return 0.0f;
	vec3 p = vec3_make(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
	return to_segment(p, pose->head[b], pose->tip[b]) - d->radius[v];
}

float skin_diff_from_bind(skin_diff *d, const skel_pose *pose, const float *pos, float *dist)
{
	float most = 0.0f;
	memset(d->score, 0, sizeof d->score);
	for (int v = 0; v < d->count; v++) {
		float e = moved_from_bone(d, pose, pos, v);
		if (dist)
			dist[v] = e;
		if (fabsf(e) > d->score[d->joint[v]])
			d->score[d->joint[v]] = fabsf(e);
	}
	for (int j = 0; j < d->bone_count; j++)
		most = fmaxf(most, d->score[j]);
	return most;
}

vec3 skin_fold_outside(vec3 axis, vec3 parent)
{
	float la = vec3_length(axis), lp = vec3_length(parent);
	if (la <= 0.0f || lp <= 0.0f || vec3_dot(axis, parent) >= SKIN_FOLD_COS * la * lp)
		return vec3_make(0.0f, 0.0f, 0.0f);
	return vec3_normalize(vec3_sub(vec3_scale(parent, 1.0f / lp), vec3_scale(axis, 1.0f / la)));
}

/* The weights' sum, the weighted midpoints and their squared lengths:
 * the centroid and the spread round it from the one pass. */
typedef struct focus_sum {
	double w, m[3], m2;
} focus_sum;

static void focus_add(focus_sum *s, double e, const double mid[3], double mid2)
{
	s->w += e;
	for (int k = 0; k < 3; k++)
		s->m[k] += e * mid[k];
	s->m2 += e * mid2;
}

static vec3 focus_centre(const focus_sum *s, float *reach)
{
	double w = s->w;
	double spread = s->m2 / w - (s->m[0] * s->m[0] + s->m[1] * s->m[1] + s->m[2] * s->m[2]) / (w * w);
	*reach = spread > 0.0 ? (float)sqrt(spread) : 0.0f;
	return vec3_make((float)(s->m[0] / w), (float)(s->m[1] / w), (float)(s->m[2] / w));
}

/* The way out of the fold of joint, a human's elbow or knee, in pose
 * (skin_fold_outside); zero for any other joint, or any joint of a
 * skeleton that is not a human's (its limbs need not hinge). */
static vec3 fold_outward(const skin_diff *d, const skel_pose *pose, int joint)
{
	const skel_joints *j = d->joints;
	vec3 none = vec3_make(0.0f, 0.0f, 0.0f);
	if (!j || !j->biped || (j->kind[joint] != JOINT_ELBOW && j->kind[joint] != JOINT_KNEE))
		return none;
	int up = j->skel->bone[joint].parent;
	if (up < 0)
		return none;
	return skin_fold_outside(vec3_sub(pose->tip[joint], pose->head[joint]), vec3_sub(pose->tip[up], pose->head[up]));
}

/* A vertex's weight in the focus, the squared distance between p and q,
 * and their midpoint with its squared length. */
static double parting(const float *p, const float *q, double mid[3], double *mid2)
{
	double e2 = 0.0;
	*mid2 = 0.0;
	for (int k = 0; k < 3; k++) {
		double dk = (double)p[k] - q[k];
		mid[k] = 0.5 * ((double)p[k] + q[k]);
		e2 += dk * dk;
		*mid2 += mid[k] * mid[k];
	}
	return e2;
}

static int beyond(vec3 head, vec3 outward, const double mid[3])
{
	return (mid[0] - head.x) * outward.x + (mid[1] - head.y) * outward.y + (mid[2] - head.z) * outward.z > 0.0;
}

skin_focus skin_diff_focus(const skin_diff *d, const skel_pose *pose, const float *a, const float *b, int joint)
{
	skin_focus f = { 0 };
	if (joint < 0 || joint >= d->bone_count)
		return f;
	f.head = pose->head[joint];
	f.outward = fold_outward(d, pose, joint);
	focus_sum all = { 0 }, outside = { 0 };
	for (int v = 0; v < d->count; v++) {
		if (d->joint[v] != joint)
			continue;
		double mid[3], mid2, e = parting(a + 3 * v, b + 3 * v, mid, &mid2);
		focus_add(&all, e, mid, mid2);
		if (beyond(f.head, f.outward, mid))
			focus_add(&outside, e, mid, mid2);
	}
	f.found = all.w > 0.0;
	f.at = f.head;
	if (!f.found)
		return f;
	if (outside.w < SKIN_FOLD_SHARE_MIN * all.w)
		f.outward = vec3_make(0.0f, 0.0f, 0.0f);
	f.at = focus_centre(vec3_dot(f.outward, f.outward) > 0.0f ? &outside : &all, &f.reach);
	return f;
}

int skin_focus_counts(const skin_focus *f, const float *a, const float *b, int v)
{
	if (vec3_dot(f->outward, f->outward) <= 0.0f)
		return 1;
	double mid[3], mid2;
	parting(a + 3 * v, b + 3 * v, mid, &mid2);
	return beyond(f->head, f->outward, mid);
}

int skin_diff_worst(const skin_diff *d)
{
	int at = -1;
	float best = 0.0f;
	for (int j = 0; j < d->bone_count; j++)
		if (d->score[j] > best)
			best = d->score[j], at = j;
	return at;
}
