#include "rig_topology.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PAIR_REACH   0.25f  /* a limb reaches this share of the skeleton's size */
#define PAIR_RATIO   0.75f  /* the two of a pair reach within this ratio */
#define LEG_UPPER    0.6f   /* the thigh: the first bone this share of the leg's longest */
#define ARM_UPPER    0.3f
#define ARM_OUT      0.3f   /* the upper arm starts this share of its length out from the spine */

typedef struct topo {
	const rig_scene *r;
	int size[RIG_MAX_JOINTS];       /* joints in the subtree */
	int depth[RIG_MAX_JOINTS];
	float reach[RIG_MAX_JOINTS];    /* longest path from the head down to a descendant's head */
	float extent;
	int leg[2], arm[2];             /* first joints of the limbs */
	int hips, chest, head;
	vec3 up, left;
} topo;

static float dist(const rig_scene *r, int a, int b)
{
	return vec3_length(vec3_sub(r->joint[a].head, r->joint[b].head));
}

static void measure(topo *t, int j, int depth)
{
	const rig_scene *r = t->r;
	t->size[j] = 1;
	t->depth[j] = depth;
	t->reach[j] = 0.0f;
	for (int c = 0; c < r->joint_count && depth < RIG_MAX_JOINTS; c++)
		if (r->joint[c].parent == j && c != j) {
			measure(t, c, depth + 1);
			t->size[j] += t->size[c];
			t->reach[j] = fmaxf(t->reach[j], dist(r, j, c) + t->reach[c]);
		}
}

static float extent_of(const rig_scene *r)
{
	vec3 lo = r->joint[0].head, hi = lo;
	for (int j = 1; j < r->joint_count; j++) {
		vec3 p = r->joint[j].head;
		lo = vec3_make(fminf(lo.x, p.x), fminf(lo.y, p.y), fminf(lo.z, p.z));
		hi = vec3_make(fmaxf(hi.x, p.x), fmaxf(hi.y, p.y), fmaxf(hi.z, p.z));
	}
	return fmaxf(hi.x - lo.x, fmaxf(hi.y - lo.y, hi.z - lo.z));
}

static int mirror(const topo *t, int a, int b)
{
	float lo = fminf(t->reach[a], t->reach[b]), hi = fmaxf(t->reach[a], t->reach[b]);
	return abs(t->size[a] - t->size[b]) <= 1 && lo >= PAIR_REACH * t->extent && lo >= PAIR_RATIO * hi;
}

/* The two mirror pairs reaching furthest: legs (the shallower parent) and arms. */
static int find_limbs(topo *t)
{
	const rig_scene *r = t->r;
	int pair[2][2], found = 0;
	float best[2] = { 0.0f, 0.0f };
	for (int a = 0; a < r->joint_count; a++)
		for (int b = a + 1; b < r->joint_count; b++) {
			if (r->joint[a].parent != r->joint[b].parent || r->joint[a].parent < 0 || !mirror(t, a, b))
				continue;
			float reach = t->reach[a] + t->reach[b];
			int k = reach > best[0] ? 0 : reach > best[1] ? 1 : 2;
			if (k == 2)
				continue;
			if (k == 0) {
				memcpy(pair[1], pair[0], sizeof pair[0]);
				best[1] = best[0];
			}
			pair[k][0] = a;
			pair[k][1] = b;
			best[k] = reach;
			found += found < 2;
		}
	if (found < 2)
		return 0;
	int legs = t->depth[pair[0][0]] <= t->depth[pair[1][0]] ? 0 : 1;
	memcpy(t->leg, pair[legs], sizeof t->leg);
	memcpy(t->arm, pair[1 - legs], sizeof t->arm);
	t->hips = r->joint[t->leg[0]].parent;
	t->chest = r->joint[t->arm[0]].parent;
	return 1;
}

/* From the chest, the child that is no arm and reaches furthest, down its
 * single-child chain to where it ends or branches. */
static int find_head(const topo *t)
{
	const rig_scene *r = t->r;
	int j = -1;
	for (int c = 0; c < r->joint_count; c++)
		if (r->joint[c].parent == t->chest && c != t->arm[0] && c != t->arm[1] && (j < 0 || t->reach[c] > t->reach[j]))
			j = c;
	for (int guard = 0; j >= 0 && guard < RIG_MAX_JOINTS; guard++) {
		int only = -1, n = 0;
		for (int c = 0; c < r->joint_count; c++)
			if (r->joint[c].parent == j)
				only = c, n++;
		if (n != 1)
			break;
		j = only;
	}
	return j;
}

/* The chain from start along the child reaching furthest. */
static int chain_of(const topo *t, int start, int *chain)
{
	int n = 0;
	for (int j = start; j >= 0 && n < RIG_MAX_JOINTS;) {
		chain[n++] = j;
		int next = -1;
		for (int c = 0; c < t->r->joint_count; c++)
			if (t->r->joint[c].parent == j && (next < 0 || t->reach[c] + dist(t->r, j, c) >
								      t->reach[next] + dist(t->r, j, next)))
				next = c;
		j = next;
	}
	return n;
}

/* A side word anywhere in the name (leg_joint_L_1, arm_joint_R): +1 left,
 * -1 right, 0 none. */
static int side_word(const char *name)
{
	char w[RIG_NAME];
	int side = 0;
	for (const char *p = name; *p;) {
		size_t n = 0;
		while (*p && !isalpha((unsigned char)*p))
			p++;
		while (*p && isalpha((unsigned char)*p) && !(n && isupper((unsigned char)*p) && islower((unsigned char)w[n - 1])))
			w[n < RIG_NAME - 1 ? n++ : n] = (char)tolower((unsigned char)*p), p++;
		w[n] = '\0';
		if (!strcmp(w, "l") || !strcmp(w, "left"))
			side = 1;
		else if (!strcmp(w, "r") || !strcmp(w, "right"))
			side = -1;
	}
	return side;
}

/* Left: up x front, front the way the feet point; the joints' own side
 * words when they say it. Returns 1 when pair[0] is the left one. */
static int first_is_left(const topo *t, const int *pair, vec3 front)
{
	int s0 = side_word(t->r->joint[pair[0]].name), s1 = side_word(t->r->joint[pair[1]].name);
	if (s0 && s0 == -s1)
		return s0 > 0;
	vec3 gap = vec3_sub(t->r->joint[pair[0]].head, t->r->joint[pair[1]].head);
	return vec3_dot(gap, vec3_cross(t->up, front)) >= 0.0f;
}

static vec3 feet_front(const topo *t)
{
	vec3 f = vec3_make(0.0f, 0.0f, 0.0f);
	for (int k = 0; k < 2; k++) {
		int chain[RIG_MAX_JOINTS], n = chain_of(t, t->leg[k], chain);
		if (n >= 3)
			f = vec3_add(f, vec3_sub(t->r->joint[chain[n - 1]].head, t->r->joint[chain[n - 2]].head));
	}
	f = vec3_sub(f, vec3_scale(t->up, vec3_dot(f, t->up)));
	return vec3_length(f) > 1e-6f * t->extent ? vec3_normalize(f) : vec3_make(0.0f, 0.0f, 1.0f);
}

static float lateral(const topo *t, int j)
{
	vec3 d = vec3_sub(t->r->joint[j].head, t->r->joint[t->hips].head);
	return vec3_length(vec3_sub(d, vec3_scale(t->up, vec3_dot(d, t->up))));
}

static void name_limb(const topo *t, int start, int leg, rig_side side, rig_name *names)
{
	int chain[RIG_MAX_JOINTS], n = chain_of(t, start, chain), u = 0;
	float longest = 0.0f;
	for (int i = 0; i + 1 < n; i++)
		longest = fmaxf(longest, dist(t->r, chain[i], chain[i + 1]));
	for (; u + 1 < n; u++) {
		float seg = dist(t->r, chain[u], chain[u + 1]);
		if (leg ? seg >= LEG_UPPER * longest : seg >= ARM_UPPER * longest && lateral(t, chain[u]) >= ARM_OUT * seg)
			break;
	}
	if (u + 1 >= n)
		return;
	static const rig_slot legs[] = { RIG_THIGH, RIG_SHIN, RIG_FOOT, RIG_TOE };
	static const rig_slot arms[] = { RIG_UPPER_ARM, RIG_FOREARM, RIG_HAND };
	for (int k = 0; k < (leg ? 4 : 3) && u + k < n; k++) {
		rig_name *nm = &names[chain[u + k]];
		nm->slot = leg ? legs[k] : arms[k];
		nm->side = side;
		nm->rig = RIG_FAMILY_SHAPE;
	}
	if (!leg && u > 0)
		names[chain[u - 1]] = (rig_name){ RIG_CLAVICLE, side, RIG_FAMILY_SHAPE };
}

/* The pairs, hips, chest and head; 0 when the shape has no two limb pairs. */
static int find_shape(topo *t, const rig_scene *r)
{
	memset(t, 0, sizeof *t);
	t->r = r;
	if (r->joint_count < 5)
		return 0;
	t->extent = extent_of(r);
	for (int j = 0; j < r->joint_count; j++)
		if (r->joint[j].parent < 0)
			measure(t, j, 0);
	if (!(t->extent > 0.0f) || !find_limbs(t) || (t->head = find_head(t)) < 0)
		return 0;
	vec3 up = vec3_sub(r->joint[t->head].head, r->joint[t->hips].head);
	if (!(vec3_length(up) > 0.0f))
		return 0;
	t->up = vec3_normalize(up);
	return 1;
}

int rig_topology_parts(const rig_scene *r, rig_shape_parts *out)
{
	static topo t;
	memset(out, 0, sizeof *out);
	if (!find_shape(&t, r))
		return 0;
	for (int k = 0; k < 2; k++) {
		int chain[RIG_MAX_JOINTS] = { 0 };
		int n = chain_of(&t, t.leg[k], chain);
		out->leg_end[k] = chain[n > 0 ? n - 1 : 0];
		n = chain_of(&t, t.arm[k], chain);
		out->arm_end[k] = chain[n > 0 ? n - 1 : 0];
	}
	out->hips = t.hips;
	out->chest = t.chest;
	out->head = t.head;
	return 1;
}

int rig_topology_names(const rig_scene *r, rig_name *names)
{
	static topo t;
	memset(names, 0, sizeof *names * (size_t)r->joint_count);
	if (!find_shape(&t, r))
		return 0;
	vec3 front = feet_front(&t);
	int legs_left = first_is_left(&t, t.leg, front), arms_left = first_is_left(&t, t.arm, front);
	for (int k = 0; k < 2; k++) {
		name_limb(&t, t.leg[k], 1, (k == 0) == legs_left ? RIG_LEFT : RIG_RIGHT, names);
		name_limb(&t, t.arm[k], 0, (k == 0) == arms_left ? RIG_LEFT : RIG_RIGHT, names);
	}
	names[t.head] = (rig_name){ RIG_HEAD, RIG_CENTRE, RIG_FAMILY_SHAPE };
	return 4;
}
