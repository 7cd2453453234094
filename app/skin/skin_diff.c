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

vec3 skin_diff_focus(const skin_diff *d, const float *a, const float *b, int joint, int *found, float *reach)
{
	/* the weights' sum, the weighted midpoints and their squared lengths:
	 * the centroid and the spread round it from the one pass */
	double w = 0.0, m[3] = { 0.0, 0.0, 0.0 }, m2 = 0.0;
	for (int v = 0; v < d->count; v++) {
		if (d->joint[v] != joint)
			continue;
		const float *p = a + 3 * v, *q = b + 3 * v;
		double e = 0.0, mid2 = 0.0, mid[3];
		for (int k = 0; k < 3; k++) {
			double dk = (double)p[k] - q[k];
			mid[k] = 0.5 * ((double)p[k] + q[k]);
			e += dk * dk;
			mid2 += mid[k] * mid[k];
		}
		w += e;
		for (int k = 0; k < 3; k++)
			m[k] += e * mid[k];
		m2 += e * mid2;
	}
	*found = w > 0.0;
	if (!*found) {
		if (reach)
			*reach = 0.0f;
		return vec3_make(0.0f, 0.0f, 0.0f);
	}
	vec3 at = vec3_make((float)(m[0] / w), (float)(m[1] / w), (float)(m[2] / w));
	if (reach) {
		double spread = m2 / w - (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) / (w * w);
		*reach = spread > 0.0 ? (float)sqrt(spread) : 0.0f;
	}
	return at;
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
