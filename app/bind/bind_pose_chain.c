#include "bind_pose_chain.h"

#include <math.h>

#include "bind_pose_narrow.h"

#define CHAIN_MIN_VERTS 50
#define CHAIN_SWEEPS    6    /* per step size: a limb settles in two or three */
#define CHAIN_END_WEIGHT 1.0  /* the end's squared distance counts as much as the vertices' mean */
#define DEG             0.017453292519943295f

/* Steps tried on each channel, coarse to fine. */
static const float chain_step[] = { 8.0f * DEG, 4.0f * DEG, 2.0f * DEG, 1.0f * DEG, 0.5f * DEG };

static int in_limb(const skel *s, int start, int b)
{
	for (int guard = 0; b > 0 && guard < SKP_MAX_BONES; guard++, b = s->bone[b].parent)
		if (b == start)
			return 1;
	return 0;
}

static float seg_dist2(const skel_pose *p, int b, vec3 q)
{
	vec3 d = vec3_sub(p->tip[b], p->head[b]), r = vec3_sub(q, p->head[b]);
	float dd = vec3_dot(d, d), t = dd > 0.0f ? vec3_dot(r, d) / dd : 0.0f;
	vec3 e = vec3_madd(r, d, -fminf(1.0f, fmaxf(0.0f, t)));
	return vec3_dot(e, e);
}

static int nearest_bone(const skel *s, const skel_pose *p, vec3 q)
{
	int best = 0;
	float bd = INFINITY;
	for (int b = 1; b < s->count; b++) {
		float d = seg_dist2(p, b, q);
		if (d < bd) {
			bd = d;
			best = b;
		}
	}
	return best;
}

static int pick_verts(const skel *s, const mesh *m, int start, const skel_pose *pose, int *vert)
{
	int n = 0;
	for (int v = 0; v < m->vert_count; v++) {
		int b = nearest_bone(s, pose, m->pos[v]);
		if (b != start && in_limb(s, start, b))
			vert[n++] = v;
	}
	return n;
}

/* What the fit works with. */
typedef struct chain_ctx {
	const skel *s;
	const mesh *m;
	int start, n;
	const int *vert;
	skel_pose *pose;
	int end;     /* the bone whose tip is pulled to at, or -1 */
	vec3 at;
} chain_ctx;

/* The mean squared distance from the limb's vertices to its bones. */
static double chain_cost(const chain_ctx *c, const float *values)
{
	const skel *s = c->s;
	fk_pose(s, values, c->pose);
	double sum = 0.0;
	for (int i = 0; i < c->n; i++) {
		vec3 q = c->m->pos[c->vert[i]];
		float best = INFINITY;
		for (int b = c->start; b < s->count; b++)
			if (in_limb(s, c->start, b))
				best = fminf(best, seg_dist2(c->pose, b, q));
		sum += best;
	}
	double cost = sum / c->n;
	if (c->end > 0) {
		vec3 e = vec3_sub(c->pose->tip[c->end], c->at);
		cost += CHAIN_END_WEIGHT * vec3_dot(e, e);
	}
	return cost;
}

/* One channel tried a step each way: 1 when a step was kept. */
static int try_channel(const chain_ctx *c, float *v, float step, float *values, double *cost)
{
	float was = *v;
	for (int sign = -1; sign <= 1; sign += 2) {
		*v = was + (float)sign * step;
		double now = chain_cost(c, values);
		if (now < *cost) {
			*cost = now;
			return 1;
		}
	}
	*v = was;
	return 0;
}

int bind_guess_chain(const skel *s, const mesh *m, int start, const unsigned char *turn, int end, float *values,
		     skel_pose *pose, int *vert)
{
	if (start <= 0 || start >= s->count)
		return 0;
	fk_pose(s, values, pose);
	chain_ctx c = { s, m, start, pick_verts(s, m, start, pose, vert), vert, pose, -1, vec3_make(0.0f, 0.0f, 0.0f) };
	if (end > 0 && bind_guess_narrowest(m, pose, end, &c.at))
		c.end = end;
	if (c.n < CHAIN_MIN_VERTS)
		return 0;
	double cost = chain_cost(&c, values);
	int kept = 0;
	for (int k = 0; k < (int)(sizeof chain_step / sizeof chain_step[0]); k++)
		for (int sweep = 0, moved = 1; moved && sweep < CHAIN_SWEEPS; sweep++) {
			moved = 0;
			for (int b = start; b < s->count; b++)
				for (int ch = 0; turn[b] && in_limb(s, start, b) && ch < s->bone[b].channel_count; ch++)
					if (s->bone[b].channel[ch] <= SKEL_RZ &&
					    try_channel(&c, &values[s->bone[b].dof_offset + ch], chain_step[k], values, &cost)) {
						moved = 1;
						kept++;
					}
		}
	fk_pose(s, values, pose);
	return kept;
}
