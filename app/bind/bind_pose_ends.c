#include "bind_pose_ends.h"

#include <math.h>

#include "skel_tpose.h"

#define ENDS_MIN_VERTS  20
#define ENDS_MIN_TURN   0.98769f  /* cos 8 degrees */
#define ENDS_CONE       0.5f      /* cos 60 degrees */
#define ENDS_SIDE_CONE  0.7071f   /* cos 45 degrees, about the square to the main chain */
#define RING_MIN_TURN   0.99939f  /* cos 2 degrees: a ring's centroid is precise */

int bind_guess_mean_dir(vec3 sum, int n, int min_n, vec3 *out)
{
	if (n < min_n || !(vec3_length(sum) > 0.0f))
		return 0;
	*out = vec3_normalize(sum);
	return 1;
}

static float len_of(const skel_pose *p, int b)
{
	return vec3_length(vec3_sub(p->tip[b], p->head[b]));
}

static vec3 dir_of(const skel_pose *p, int b)
{
	return vec3_normalize(vec3_sub(p->tip[b], p->head[b]));
}

/* The child reaching furthest, or -1. */
static int main_child(const skel *s, const skel_roles *r, const skel_pose *p, int b)
{
	int best = -1;
	for (int c = 1; c < s->count; c++)
		if (s->bone[c].parent == b && (best < 0 || len_of(p, c) + r->reach[c] > len_of(p, best) + r->reach[best]))
			best = c;
	return best;
}

/* The centroid direction of the vertices ahead of bone b; avoid >= 0: a
 * main-chain bone whose direction the vertices must be farther from, and
 * then the cone's axis itself once the vertices say there is flesh. */
static int cone_dir(const skel *s, const skel_roles *r, const mesh *m, const skel_pose *p, int b, int avoid,
		    vec3 *out)
{
	vec3 head = p->head[b], d = dir_of(p, b), sum = vec3_make(0.0f, 0.0f, 0.0f);
	vec3 up_chain = s->bone[b].parent > 0 ? dir_of(p, s->bone[b].parent) : d;
	float reach = 1.1f * (len_of(p, b) + r->reach[b]), cone = avoid >= 0 ? ENDS_SIDE_CONE : ENDS_CONE;
	vec3 other = avoid >= 0 ? dir_of(p, avoid) : d;
	if (avoid >= 0) {
		/* a side branch (a thumb) may start far off its mesh (the rest
		 * pose's roll of the hand is kept): look square to the main chain,
		 * toward the body's front or back as the branch leans now */
		vec3 across = vec3_madd(r->depth, other, -vec3_dot(r->depth, other));
		if (vec3_length(across) > 0.0f)
			d = vec3_scale(vec3_normalize(across), vec3_dot(d, across) < 0.0f ? -1.0f : 1.0f);
	}
	int n = 0;
	for (int v = 0; v < m->vert_count; v++) {
		vec3 q = vec3_sub(m->pos[v], head);
		float dist = vec3_length(q);
		if (!(dist > 0.0f) || dist > reach || vec3_dot(q, d) < cone * dist || vec3_dot(q, up_chain) < 0.0f)
			continue;
		if (avoid >= 0 && vec3_dot(q, other) >= vec3_dot(q, d))
			continue;
		sum = vec3_add(sum, q);
		n++;
	}
	/* a side branch leaves the main chain square to it (toward the side
	 * it leans to, flesh there): the centroid would lean back toward the
	 * main chain, as the cone is cut by the plane through the joint (the
	 * flesh behind it is the parent's) */
	return bind_guess_mean_dir(avoid >= 0 ? d : sum, n, ENDS_MIN_VERTS, out);
}

static int turn(const skel *s, const skel_roles *r, const mesh *m, int b, int avoid, float *values, skel_pose *p)
{
	vec3 to;
	fk_pose(s, values, p);
	if (!cone_dir(s, r, m, p, b, avoid, &to) || vec3_dot(to, dir_of(p, b)) > ENDS_MIN_TURN)
		return 0;
	skel_aim(s, b, to, values, p);
	return 1;
}

/* The direction from bone b's head to the middle of the mesh's limb
 * short of where b ends: the centroid of the ring of vertices around it at
 * 80% of its length (within 5% of its length along it and 30% across),
 * clear of the joint's bulges (a heel, a knee cap). */
static int ring_dir(const mesh *m, const skel_pose *p, int b, vec3 *out)
{
	vec3 head = p->head[b], d = dir_of(p, b), sum = vec3_make(0.0f, 0.0f, 0.0f);
	float len = len_of(p, b);
	int n = 0;
	for (int v = 0; v < m->vert_count; v++) {
		vec3 q = vec3_sub(m->pos[v], head);
		float along = vec3_dot(q, d);
		if (fabsf(along - 0.8f * len) > 0.05f * len || vec3_length(vec3_madd(q, d, -along)) > 0.3f * len)
			continue;
		sum = vec3_add(sum, q);
		n++;
	}
	return bind_guess_mean_dir(sum, n, ENDS_MIN_VERTS, out);
}

int bind_guess_ring(const skel *s, const mesh *m, int b, float *values, skel_pose *pose)
{
	vec3 to;
	fk_pose(s, values, pose);
	if (b <= 0 || !ring_dir(m, pose, b, &to) || vec3_dot(to, dir_of(pose, b)) > RING_MIN_TURN)
		return 0;
	skel_aim(s, b, to, values, pose);
	return 1;
}

int bind_guess_ends(const skel *s, const skel_roles *roles, const mesh *m, int start, float *values,
		    skel_pose *pose)
{
	int turned = 0;
	fk_pose(s, values, pose);
	float limb = start > 0 && start < s->count ? len_of(pose, start) + roles->reach[start] : 0.0f;
	for (int b = start, guard = 0; b > 0 && guard < SKP_MAX_BONES; guard++) {
		int next = main_child(s, roles, pose, b);
		if (len_of(pose, b) >= 0.03f * limb)
			turned += turn(s, roles, m, b, -1, values, pose);
		for (int c = 1; next >= 0 && c < s->count; c++)
			if (s->bone[c].parent == b && c != next && len_of(pose, c) >= 0.03f * limb)
				turned += turn(s, roles, m, c, next, values, pose);
		fk_pose(s, values, pose);
		b = next;
	}
	return turned;
}
