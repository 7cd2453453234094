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

void skin_diff_init(skin_diff *d, const skel *s, const skel_pose *bind, const skin_soa *soa)
{
	d->count = soa->count;
	d->bone_count = s->count;
	memset(d->score, 0, sizeof d->score);
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

void skin_diff_joint_change(const skin_diff *d, const skel_pose *pose, const float *pos, int joint, float *thinner,
			    float *thicker)
{
	float lo = 0.0f, hi = 0.0f;
	for (int v = 0; v < d->count; v++)
		if (d->joint[v] == joint) {
			float e = moved_from_bone(d, pose, pos, v);
			lo = fminf(lo, e);
			hi = fmaxf(hi, e);
		}
	*thinner = -lo;
	*thicker = hi;
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

vec3 skin_diff_focus(const skin_diff *d, const float *a, const float *b, int joint, int *found)
{
	double w = 0.0, x = 0.0, y = 0.0, z = 0.0;
	for (int v = 0; v < d->count; v++) {
		if (d->joint[v] != joint)
			continue;
		const float *p = a + 3 * v, *q = b + 3 * v;
		double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2], e = dx * dx + dy * dy + dz * dz;
		w += e;
		x += e * 0.5 * (p[0] + q[0]);
		y += e * 0.5 * (p[1] + q[1]);
		z += e * 0.5 * (p[2] + q[2]);
	}
	*found = w > 0.0;
	return w > 0.0 ? vec3_make((float)(x / w), (float)(y / w), (float)(z / w)) : vec3_make(0.0f, 0.0f, 0.0f);
}

float skin_diff_reach(const skin_diff *d, const float *a, const float *b, int joint, vec3 at)
{
	double w = 0.0, r2 = 0.0;
	for (int v = 0; v < d->count; v++) {
		if (d->joint[v] != joint)
			continue;
		const float *p = a + 3 * v, *q = b + 3 * v;
		double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2], e = dx * dx + dy * dy + dz * dz;
		double mx = 0.5 * (p[0] + q[0]) - at.x, my = 0.5 * (p[1] + q[1]) - at.y, mz = 0.5 * (p[2] + q[2]) - at.z;
		w += e;
		r2 += e * (mx * mx + my * my + mz * mz);
	}
	return w > 0.0 ? (float)sqrt(r2 / w) : 0.0f;
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
