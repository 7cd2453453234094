#include "skel_tpose.h"

#include <math.h>
#include <string.h>

#include "skel_roles.h"

#define TPOSE_ITERATIONS 40
#define TPOSE_STEP       1e-3f   /* radians, for the numeric Jacobian */
#define TPOSE_MAX_MOVE   0.5f    /* radians per iteration */

typedef struct tpose_solve {
	const skel *s;
	int bone;
	vec3 target;
	float *values;
	skel_pose *work;
	int n;
	int dof[SKEL_MAX_CHANNELS];
} tpose_solve;

static vec3 bone_dir(tpose_solve *t)
{
	fk_pose(t->s, t->values, t->work);
	return vec3_normalize(vec3_sub(t->work->tip[t->bone], t->work->head[t->bone]));
}

/* Gaussian elimination with partial pivoting on the n x n system a x = b
 * (n <= SKEL_MAX_CHANNELS); 0 when singular. */
static int solve_linear(int n, float a[][SKEL_MAX_CHANNELS], float *b)
{
	for (int c = 0; c < n; c++) {
		int p = c;
		for (int r = c + 1; r < n; r++)
			if (fabsf(a[r][c]) > fabsf(a[p][c]))
				p = r;
		if (!(fabsf(a[p][c]) > 1e-12f))
			return 0;
		for (int k = 0; k < n; k++) {
			float tmp = a[c][k]; a[c][k] = a[p][k]; a[p][k] = tmp;
		}
		float tb = b[c]; b[c] = b[p]; b[p] = tb;
		for (int r = c + 1; r < n; r++) {
			float f = a[r][c] / a[c][c];
			for (int k = c; k < n; k++)
				a[r][k] -= f * a[c][k];
			b[r] -= f * b[c];
		}
	}
	for (int c = n - 1; c >= 0; c--) {
		for (int k = c + 1; k < n; k++)
			b[c] -= a[c][k] * b[k];
		b[c] /= a[c][c];
	}
	return 1;
}

/* One damped Gauss-Newton step on |direction - target|^2; 0 when done. */
static int tpose_step(tpose_solve *t)
{
	vec3 d = bone_dir(t), r = vec3_sub(d, t->target);
	if (vec3_dot(r, r) < 1e-12f)
		return 0;
	vec3 J[SKEL_MAX_CHANNELS];
	for (int j = 0; j < t->n; j++) {
		t->values[t->dof[j]] += TPOSE_STEP;
		J[j] = vec3_scale(vec3_sub(bone_dir(t), d), 1.0f / TPOSE_STEP);
		t->values[t->dof[j]] -= TPOSE_STEP;
	}
	float a[SKEL_MAX_CHANNELS][SKEL_MAX_CHANNELS], g[SKEL_MAX_CHANNELS];
	for (int i = 0; i < t->n; i++) {
		for (int j = 0; j < t->n; j++)
			a[i][j] = vec3_dot(J[i], J[j]) + (i == j ? 1e-4f : 0.0f);
		g[i] = -vec3_dot(J[i], r);
	}
	if (!solve_linear(t->n, a, g))
		return 0;
	for (int j = 0; j < t->n; j++)
		t->values[t->dof[j]] += fmaxf(-TPOSE_MAX_MOVE, fminf(TPOSE_MAX_MOVE, g[j]));
	return 1;
}

float skel_aim(const skel *s, int bone, vec3 target, float *values, skel_pose *work)
{
	tpose_solve t = { s, bone, vec3_normalize(target), values, work, 0, { 0 } };
	const skel_bone *b = &s->bone[bone];
	for (int i = 0; i < b->channel_count; i++)
		if (b->channel[i] <= SKEL_RZ)
			t.dof[t.n++] = b->dof_offset + i;
	for (int k = 0; t.n > 0 && k < TPOSE_ITERATIONS && tpose_step(&t); k++)
		;
	return vec3_dot(bone_dir(&t), t.target);
}

/* Straight out sideways, on the side of the spine the bone starts on. */
static vec3 outward(const skel *s, const skel_roles *r, const skel_pose *p, int b)
{
	int from = s->bone[skel_branch_start(s, r, b)].parent;
	float side = vec3_dot(vec3_sub(p->head[b], p->tip[from]), r->side);
	return vec3_scale(r->side, side < 0.0f ? -1.0f : 1.0f);
}

int skel_tpose(const skel *s, float *values, skel_pose *work)
{
	skel_roles roles;
	uint8_t moved[SKP_MAX_BONES] = { 0 };
	int raised = 0;
	memset(values, 0, (size_t)s->dof_count * sizeof *values);
	if (s->count < 2)
		return 0;
	fk_pose(s, NULL, work);
	skel_find_roles(s, work, &roles);
	for (int k = 1; k < s->count; k++) {
		int b = s->eval_order[k], par = s->bone[b].parent;
		moved[b] = par > 0 && moved[par];
		vec3 axis = vec3_sub(work->tip[b], work->head[b]);
		float len = vec3_length(axis);
		if (moved[b] || !roles.arm[b] || !(len > 1e-6f * roles.H) || axis.y / len > -0.5f)
			continue;
		skel_aim(s, b, outward(s, &roles, work, b), values, work);
		moved[b] = 1;
		raised++;
	}
	fk_pose(s, values, work);
	return raised;
}
