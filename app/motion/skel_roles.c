#include "skel_roles.h"

#include <math.h>
#include <string.h>

static vec3 min3(vec3 a, vec3 b)
{
	return vec3_make(fminf(a.x, b.x), fminf(a.y, b.y), fminf(a.z, b.z));
}

static vec3 max3(vec3 a, vec3 b)
{
	return vec3_make(fmaxf(a.x, b.x), fmaxf(a.y, b.y), fmaxf(a.z, b.z));
}

static void find_extent(const skel *s, const skel_pose *p, skel_roles *r)
{
	vec3 lo = p->tip[0], hi = lo;
	for (int b = 1; b < s->count; b++) {
		lo = min3(lo, min3(p->head[b], p->tip[b]));
		hi = max3(hi, max3(p->head[b], p->tip[b]));
	}
	r->ymin = lo.y;
	r->ymax = hi.y;
	vec3 ext = vec3_sub(hi, lo);
	r->H = fmaxf(ext.y, 0.5f * fmaxf(ext.x, fmaxf(ext.y, ext.z)));
}

static void find_spine(const skel *s, const skel_pose *p, skel_roles *r)
{
	r->head_bone = 1;
	for (int b = 2; b < s->count; b++)
		if (p->tip[b].y > p->tip[r->head_bone].y)
			r->head_bone = b;
	for (int b = r->head_bone; b > 0; b = s->bone[b].parent)
		r->spine[b] = 1;
}

int skel_branch_start(const skel *s, const skel_roles *r, int b)
{
	while (s->bone[b].parent > 0 && !r->spine[s->bone[b].parent])
		b = s->bone[b].parent;
	return b;
}

static void find_limbs(const skel *s, const skel_pose *p, skel_roles *r)
{
	float low[SKP_MAX_BONES];
	for (int b = 0; b < s->count; b++)
		low[b] = INFINITY;
	for (int b = 1; b < s->count; b++) {
		int st = skel_branch_start(s, r, b);
		low[st] = fminf(low[st], fminf(p->head[b].y, p->tip[b].y));
	}
	for (int b = 1; b < s->count; b++) {
		if (r->spine[b])
			continue;
		r->leg[b] = low[skel_branch_start(s, r, b)] < r->ymin + 0.25f * r->H;
		r->arm[b] = !r->leg[b];
	}
}

/* Children come after their parents in eval_order: walk it backwards. */
static void find_reach(const skel *s, const skel_pose *p, skel_roles *r)
{
	for (int k = s->count - 1; k >= 1; k--) {
		int b = s->eval_order[k], par = s->bone[b].parent;
		float len = vec3_length(vec3_sub(p->tip[b], p->head[b])) + r->reach[b];
		if (par > 0 && len > r->reach[par])
			r->reach[par] = len;
	}
}

static void find_axes(const skel *s, const skel_pose *p, skel_roles *r)
{
	float sx = 0.0f, sz = 0.0f, mx = 0.0f, mz = 0.0f;
	int n = s->count;
	for (int b = 0; b < n; b++) {
		mx += p->tip[b].x / (float)n;
		mz += p->tip[b].z / (float)n;
	}
	for (int b = 0; b < n; b++) {
		sx += (p->tip[b].x - mx) * (p->tip[b].x - mx);
		sz += (p->tip[b].z - mz) * (p->tip[b].z - mz);
	}
	r->up = vec3_make(0.0f, 1.0f, 0.0f);
	r->depth = sz <= sx ? vec3_make(0.0f, 0.0f, 1.0f) : vec3_make(1.0f, 0.0f, 0.0f);
	r->side = sz <= sx ? vec3_make(1.0f, 0.0f, 0.0f) : vec3_make(0.0f, 0.0f, 1.0f);
}

void skel_find_roles(const skel *s, const skel_pose *p, skel_roles *out)
{
	memset(out, 0, sizeof *out);
	find_extent(s, p, out);
	find_spine(s, p, out);
	find_limbs(s, p, out);
	find_reach(s, p, out);
	find_axes(s, p, out);
}

int skel_roles_biped(const skel *s, const skel_roles *r)
{
	int legs = 0, arms = 0;
	for (int b = 1; b < s->count; b++)
		if (skel_branch_start(s, r, b) == b) {
			legs += r->leg[b];
			arms += r->arm[b];
		}
	return legs >= 2 && arms >= 2;
}
