#include "rig_map.h"

#include <math.h>
#include <string.h>

#include "skel_roles.h"

static float bone_length(const skel_pose *p, int b)
{
	return vec3_length(vec3_sub(p->tip[b], p->head[b]));
}

static int child_count(const skel *s, int b)
{
	int n = 0;
	for (int c = 1; c < s->count; c++)
		n += s->bone[c].parent == b;
	return n;
}

/* From the branch start, the child reaching furthest each time. */
static int branch_chain(const skel *s, const skel_pose *p, const skel_roles *r, int start, int *chain)
{
	int n = 0;
	for (int b = start; b > 0;) {
		chain[n++] = b;
		int next = -1;
		float best = -1.0f;
		for (int c = 1; c < s->count; c++)
			if (s->bone[c].parent == b && bone_length(p, c) + r->reach[c] > best) {
				best = bone_length(p, c) + r->reach[c];
				next = c;
			}
		b = next;
	}
	return n;
}

/* The next bone of the chain after index i with a length, or -1. */
static int next_long(const skel_pose *p, const int *chain, int n, int *i, float min_len)
{
	for ((*i)++; *i < n; (*i)++)
		if (bone_length(p, chain[*i]) > min_len)
			return chain[*i];
	return -1;
}

/* The first bone after index from that branches (a hand into fingers), or -1. */
static int first_branching(const skel *s, const int *chain, int n, int from)
{
	for (int k = from + 1; k < n; k++)
		if (child_count(s, chain[k]) >= 2)
			return k;
	return -1;
}

/* Legs: thigh (the first bone at least 0.6 of the longest), then shin,
 * foot and toes. Arms: the upper arm is the first bone at least 0.3 of
 * the longest whose head is out to the side by 0.3 of its own length or
 * more (a clavicle starts at the spine and can be the longest bone:
 * HDM05; endorphin puts a dummy before it), the clavicle the bone before
 * it, the forearm the bone after it, the hand the first bone that
 * branches, unless that is a short wrist the thumb hangs from (CMU's
 * lwrist): then the one after it, which the fingers follow; the fingers
 * the next bone on from that hand. */
static void limb_parts(const skel *s, const skel_pose *p, const skel_roles *r, const int *chain, int n,
		       int leg, float min_len, int *slot_bone)
{
	float longest = 0.0f;
	int hand = leg ? -1 : first_branching(s, chain, n, 0), end = hand >= 0 ? hand : n;
	for (int i = 0; i < end; i++)
		longest = fmaxf(longest, bone_length(p, chain[i]));
	int u = 0;
	for (; u < end; u++) {
		float len = bone_length(p, chain[u]);
		float out = fabsf(vec3_dot(vec3_sub(p->head[chain[u]], p->head[0]), r->side));
		if (leg ? len >= 0.6f * longest : len >= 0.3f * longest && out >= 0.3f * len)
			break;
	}
	if (u == end)
		return;
	slot_bone[leg ? RIG_THIGH : RIG_UPPER_ARM] = chain[u];
	for (int k = u - 1; k >= 0 && !leg; k--)
		if (bone_length(p, chain[k]) > min_len) {
			slot_bone[RIG_CLAVICLE] = chain[k];
			break;
		}
	slot_bone[leg ? RIG_SHIN : RIG_FOREARM] = next_long(p, chain, n, &u, min_len);
	if (leg) {
		slot_bone[RIG_FOOT] = next_long(p, chain, n, &u, min_len);
		slot_bone[RIG_TOE] = next_long(p, chain, n, &u, min_len);
		return;
	}
	if (hand >= 0 && hand + 2 < n && bone_length(p, chain[hand]) < 0.6f * bone_length(p, chain[u]))
		hand++;
	if (hand <= u) {
		slot_bone[RIG_HAND] = next_long(p, chain, n, &u, min_len);
		return;
	}
	slot_bone[RIG_HAND] = chain[hand];
	/* a hand that branches holds its fingers: the next bone on */
	slot_bone[RIG_FINGERS] = next_long(p, chain, n, &hand, min_len);
}

/* Front: where the feet point, else the skeleton's depth axis. */
static void find_axes(const skel_pose *p, const skel_roles *r, rig_skel_parts *out)
{
	vec3 f = vec3_make(0.0f, 0.0f, 0.0f);
	for (int side = RIG_LEFT; side <= RIG_RIGHT; side++) {
		int b = out->bone[side][RIG_FOOT];
		if (b >= 0)
			f = vec3_add(f, vec3_sub(p->tip[b], p->head[b]));
	}
	out->up = r->up;
	f = vec3_sub(f, vec3_scale(r->up, vec3_dot(f, r->up)));
	out->front = vec3_length(f) > 1e-6f * r->H ? vec3_normalize(f) : r->depth;
	out->left = vec3_cross(out->up, out->front);
}

void rig_find_skel_parts(const skel *s, const skel_pose *p, rig_skel_parts *out)
{
	static skel_roles r;
	int chain[SKP_MAX_BONES], limb_bone[SKP_MAX_BONES][RIG_SLOT_COUNT];
	int limbs = 0;
	memset(out, 0xff, sizeof out->bone);
	skel_find_roles(s, p, &r);
	out->spine_count = 0;
	for (int b = r.head_bone; b >= 0; b = s->bone[b].parent)
		out->spine_count++;
	for (int b = r.head_bone, k = out->spine_count; b >= 0; b = s->bone[b].parent)
		out->spine[--k] = b;
	for (int b = 1; b < s->count; b++) {
		if (r.spine[b] || skel_branch_start(s, &r, b) != b)
			continue;
		memset(limb_bone[limbs], 0xff, sizeof limb_bone[limbs]);
		int n = branch_chain(s, p, &r, b, chain);
		limb_parts(s, p, &r, chain, n, r.leg[b], 1e-4f * r.H, limb_bone[limbs]);
		limbs++;
	}
	/* sides need the front, which needs the feet: legs first, by the
	 * skeleton's side axis, then every limb by the left found */
	out->left = r.side;
	for (int pass = 0; pass < 2; pass++) {
		memset(out->bone, 0xff, sizeof out->bone);
		for (int k = 0; k < limbs; k++) {
			int upper = limb_bone[k][RIG_UPPER_ARM] >= 0 ? limb_bone[k][RIG_UPPER_ARM]
								    : limb_bone[k][RIG_THIGH];
			if (upper < 0)
				continue;
			float d = vec3_dot(vec3_sub(p->tip[upper], p->head[0]), out->left);
			int side = d > 0.0f ? RIG_LEFT : RIG_RIGHT;
			for (int slot = RIG_CLAVICLE; slot < RIG_SLOT_COUNT; slot++)
				if (limb_bone[k][slot] >= 0 && out->bone[side][slot] < 0)
					out->bone[side][slot] = limb_bone[k][slot];
		}
		find_axes(p, &r, out);
	}
	out->bone[RIG_CENTRE][RIG_HEAD] = r.head_bone;
	int arm = out->bone[RIG_LEFT][RIG_CLAVICLE] >= 0 ? out->bone[RIG_LEFT][RIG_CLAVICLE]
							  : out->bone[RIG_LEFT][RIG_UPPER_ARM];
	out->chest = arm >= 0 ? s->bone[skel_branch_start(s, &r, arm)].parent : -1;
}
