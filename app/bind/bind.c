#include "bind.h"

#include <math.h>
#include <string.h>

const bind_params bind_default_params = {
	.radius = 0.35f,
	.radius_min = 0.05f,
	.radius_max = 0.10f,
	.radius_cap = 1.0f,
	.blend = 0.20f,
};

/* |d_parent + d_child| below this (bones folded back by more than about
 * 150 degrees) leaves the child's own direction: the bisector turns too
 * fast there to mean anything. */
#define BIND_MITRE_MIN 0.5f

/* Outside every box, boxes grow to this many times the distance to the
 * nearest bone. Measured on the generated body: 1.0 leaves a crease across
 * the belly of a bent back; 1.25 lets the shoulders take chest skin, and
 * DQBS's worst volume loss grows (kick 0.59% -> 0.84%, endorphin walk
 * 3.4% -> 3.7%); 1.1 is smooth and costs little. */
#define BIND_REACH 1.1f

static float clampf(float x, float lo, float hi)
{
	return x < lo ? lo : (x > hi ? hi : x);
}

/* Largest side of the bounding box of every joint of the pose. */
static float pose_size(const skel *s, const skel_pose *pose)
{
	vec3 lo = pose->head[0], hi = pose->head[0];
	for (int b = 0; b < s->count; b++) {
		const vec3 pt[2] = { pose->head[b], pose->tip[b] };
		for (int k = 0; k < 2; k++) {
			lo = vec3_make(fminf(lo.x, pt[k].x), fminf(lo.y, pt[k].y), fminf(lo.z, pt[k].z));
			hi = vec3_make(fmaxf(hi.x, pt[k].x), fmaxf(hi.y, pt[k].y), fmaxf(hi.z, pt[k].z));
		}
	}
	return fmaxf(hi.x - lo.x, fmaxf(hi.y - lo.y, hi.z - lo.z));
}

/* Nearest ancestor that has a box, or -1 when only zero-length bones (the
 * root) lie above: such bones all start at the root joint. */
static int boxed_ancestor(const skel *s, const bind_rig *rig, int b)
{
	int a = s->bone[b].parent;
	while (a > 0 && rig->seg[a].length <= 0.0f)
		a = s->bone[a].parent;
	return a > 0 ? a : -1;
}

static void set_near(bind_rig *rig, int a, int b)
{
	rig->near[a][b / 32] |= 1u << (b % 32);
	rig->near[b][a / 32] |= 1u << (a % 32);
}

static int is_near(const bind_rig *rig, int a, int b)
{
	return (rig->near[a][b / 32] >> (b % 32)) & 1u;
}

static int is_apart(const bind_rig *rig, int a, int b)
{
	return (rig->apart[a][b / 32] >> (b % 32)) & 1u;
}

/* Siblings pointing apart: same parent, same head, more than 90 degrees
 * between them (the lower back and a CMU hip bone, the two clavicles;
 * not the two hip bones at the crotch). */
static void find_apart(bind_rig *rig)
{
	for (int a = 1; a < rig->bone_count; a++)
		for (int b = 1; b < a; b++) {
			const bind_segment *g = &rig->seg[a], *n = &rig->seg[b];
			vec3 gap = vec3_sub(g->head, n->head);
			if (g->length > 0.0f && n->length > 0.0f && g->parent == n->parent &&
			    !(vec3_dot(gap, gap) > 0.0f) && vec3_dot(g->dir, n->dir) < 0.0f) {
				rig->apart[a][b / 32] |= 1u << (b % 32);
				rig->apart[b][a / 32] |= 1u << (a % 32);
			}
		}
}

/* Bones meeting at a joint: a bone and the one ending at its head, bones
 * starting at the same joint; the root (0) meets the bones starting at the
 * root joint. */
static void find_neighbours(bind_rig *rig, const skel *s, const int *anc)
{
	for (int b = 0; b < s->count; b++)
		set_near(rig, b, b);
	for (int b = 1; b < s->count; b++) {
		set_near(rig, b, anc[b] >= 0 ? anc[b] : 0);
		for (int c = 1; c < b; c++)
			if (anc[c] == anc[b])
				set_near(rig, b, c);
	}
}

/* Where a bone is its parent's only child, both ramps of the joint project
 * on the bisector of the two bones, so that the cross-fade's mid surface
 * cuts the joint like a mitre instead of square to the child: at an angled
 * joint (ankle, hip) a square cut leaves more flesh on one side of the
 * joint than the other, and a bend then changes the volume in proportion
 * to its angle. */
static void find_mitres(bind_rig *rig, const skel *s, const int *anc, const uint8_t *starting)
{
	for (int b = 1; b < s->count; b++) {
		bind_segment *g = &rig->seg[b];
		if (g->length <= 0.0f || anc[b] < 0 || starting[anc[b] + 1] != 1)
			continue;
		bind_segment *up = &rig->seg[anc[b]];
		vec3 m = vec3_add(g->dir, up->dir);
		float len = vec3_length(m);
		if (len > BIND_MITRE_MIN)
			g->head_n = up->tip_n = vec3_scale(m, 1.0f / len);
	}
}

/* A ramp is only needed where a neighbour takes over: count the boxed
 * bones meeting at each joint (keyed by the bone ending there, -1 for the
 * root joint). */
static void find_ramps(bind_rig *rig, const skel *s)
{
	int anc[SKP_MAX_BONES];
	uint8_t starting[SKP_MAX_BONES + 1];  /* [k + 1]: boxed bones starting at joint k */

	memset(starting, 0, sizeof starting);
	for (int b = 1; b < s->count; b++) {
		anc[b] = boxed_ancestor(s, rig, b);
		if (rig->seg[b].length > 0.0f && starting[anc[b] + 1] < 255)
			starting[anc[b] + 1]++;
	}
	find_neighbours(rig, s, anc);
	for (int b = 1; b < s->count; b++) {
		bind_segment *g = &rig->seg[b];
		if (g->length <= 0.0f)
			continue;
		int meeting = starting[anc[b] + 1] + (anc[b] >= 0);
		g->ramp_head = meeting >= 2;
		g->parent = (int16_t)(anc[b] >= 0 ? anc[b] : 0);
		g->ramp_tip = starting[b + 1] >= 1;
		g->head_n = g->tip_n = g->dir;
	}
	find_mitres(rig, s, anc, starting);
	find_apart(rig);
}

void bind_prepare(bind_rig *rig, const skel *s, const skel_pose *pose,
		  const bind_params *p)
{
	if (!p)
		p = &bind_default_params;
	memset(rig, 0, sizeof *rig);
	rig->bone_count = s->count;
	rig->size = pose_size(s, pose);
	float min_len = 1e-6f * rig->size;
	for (int b = 1; b < s->count; b++) {
		bind_segment *g = &rig->seg[b];
		vec3 axis = vec3_sub(pose->tip[b], pose->head[b]);
		float len = vec3_length(axis);
		g->head = pose->head[b];
		if (!(len > min_len))
			continue;
		g->length = len;
		g->dir = vec3_scale(axis, 1.0f / len);
		g->radius = fminf(clampf(p->radius * len, p->radius_min * rig->size,
					 p->radius_max * rig->size), p->radius_cap * len);
		g->half = p->blend * len;
		rig->boxed++;
	}
	find_ramps(rig, s);
}

/* Weight at distance x past a joint into the bone: 0.5 at the joint,
 * linear to 1 at x = h and to 0 at x = -h. h 0 means a hard step. */
static float ramp(float x, float h)
{
	if (h > 0.0f)
		return 0.5f + x / (2.0f * h);
	return x > 0.0f ? 1.0f : (x < 0.0f ? 0.0f : 0.5f);
}

/* The box weight, and in *head_share what the head ramp leaves for the
 * bone before the joint (1 - ramp, 0 past the ramp or outside the box).
 * The box reaches at least `reach` from the bone's line. */
static float segment_weight(const bind_segment *g, vec3 p, float reach, int *inside, float *head_share)
{
	*inside = 0;
	*head_share = 0.0f;
	if (g->length <= 0.0f)
		return 0.0f;
	vec3 q = vec3_sub(p, g->head);
	float s = vec3_dot(q, g->dir);
	if (s < -g->half || s > g->length + g->half)
		return 0.0f;
	vec3 perp = vec3_madd(q, g->dir, -s);
	float box_r = fmaxf(g->radius, reach);
	if (vec3_dot(perp, perp) > box_r * box_r)
		return 0.0f;
	*inside = 1;
	float w = 1.0f;
	if (g->ramp_head) {
		float r = ramp(vec3_dot(q, g->head_n), g->half);
		w = fminf(w, r);
		*head_share = clampf(1.0f - r, 0.0f, 1.0f);
	}
	if (g->ramp_tip)
		w = fminf(w, ramp(vec3_dot(vec3_sub(vec3_scale(g->dir, g->length), q), g->tip_n), g->half));
	return clampf(w, 0.0f, 1.0f);
}

float bind_segment_weight(const bind_segment *g, vec3 p, int *inside)
{
	int in;
	float share;
	float w = segment_weight(g, p, 0.0f, &in, &share);
	if (inside)
		*inside = in;
	return w;
}

float bind_segment_distance2(const bind_segment *g, vec3 p)
{
	vec3 q = vec3_sub(p, g->head);
	float s = clampf(vec3_dot(q, g->dir), 0.0f, g->length);
	vec3 r = vec3_madd(q, g->dir, -s);
	return vec3_dot(r, r);
}

float bind_segment_distance(const bind_segment *g, vec3 p)
{
	return sqrtf(bind_segment_distance2(g, p));
}

/* A segment whose square is not below the nearest's cannot be nearer
 * (sqrtf is monotonic); the others are compared by their roots, so that
 * segments whose roots tie keep the first. */
int bind_segment_nearest(const bind_segment *seg, int n, vec3 p, float *dist)
{
	int best = -1;
	float best_d = INFINITY, best_d2 = INFINITY;
	for (int k = 0; k < n; k++) {
		if (seg[k].length <= 0.0f)
			continue;
		float d2 = bind_segment_distance2(&seg[k], p), d;
		if (d2 < best_d2 && (d = sqrtf(d2)) < best_d) {
			best_d = d;
			best_d2 = d2;
			best = k;
		}
	}
	*dist = best_d;
	return best;
}

/* Bones starting where the nearest one starts and pointing away from it
 * (find_apart) cross-fade across the plane that bisects them: the
 * nearest-bone test alone cuts the skin where the nearest bone changes,
 * and the hip bone, pointing sideways, is nearest to the flanks above the
 * waist. Across that plane the sibling takes min(its head ramp, the
 * cross-fade) and the nearest bone gives way. */
static void sibling_cross_fade(const bind_rig *rig, int nearest, vec3 p, float *w)
{
	const bind_segment *n = &rig->seg[nearest];
	for (int b = 1; b < rig->bone_count; b++) {
		if (!is_apart(rig, nearest, b))
			continue;
		const bind_segment *g = &rig->seg[b];
		vec3 q = vec3_sub(p, g->head), m = vec3_sub(g->dir, n->dir);
		float across = ramp(vec3_dot(q, vec3_scale(m, 1.0f / vec3_length(m))), 0.5f * (g->half + n->half));
		float own = g->ramp_head ? ramp(vec3_dot(q, g->head_n), g->half) : 1.0f;
		across = clampf(across, 0.0f, 1.0f);
		w[b] = fmaxf(w[b], clampf(fminf(own, across), 0.0f, 1.0f));
		w[nearest] = fminf(w[nearest], 1.0f - across);
	}
}

/* The weights of the bones meeting the nearest one (w, indexed by bone);
 * their sum. */
static float near_weights(const bind_rig *rig, int nearest, vec3 p, float reach, float *w)
{
	for (int b = 0; b < rig->bone_count; b++)
		w[b] = 0.0f;
	for (int b = 1; b < rig->bone_count; b++) {
		if (!is_near(rig, nearest, b))
			continue;
		/* grown boxes: only along the nearest bone's chain, so that a
		 * sibling (the lower back, for a hip) does not take its skin */
		if (reach > 0.0f && b != nearest && rig->seg[b].parent != nearest && rig->seg[nearest].parent != b)
			continue;
		int in;
		float share;
		float wb = segment_weight(&rig->seg[b], p, reach, &in, &share);
		w[b] = fmaxf(w[b], wb);
		/* across the joint the bone before it takes the rest, even where
		 * its own box does not reach (a short bone, the root) */
		int up = rig->seg[b].parent;
		if (is_near(rig, nearest, up))
			w[up] = fmaxf(w[up], share);
	}
	float sum = 0.0f;
	for (int b = 0; b < rig->bone_count; b++)
		sum += w[b];
	return sum;
}

/* Returns 1 when the vertex lies outside every box. bone[b] = b. */
static int bind_vertex(const bind_rig *rig, const uint16_t *bone, vec3 p, skin_weights *out, int v)
{
	/* only bones meeting the nearest one at a joint share a vertex: across
	 * the crotch or the armpit a box may reach a limb the vertex does not
	 * belong to */
	float dist;
	int nearest = bind_segment_nearest(rig->seg + 1, rig->bone_count - 1, p, &dist) + 1; /* 0: none */
	float w[SKP_MAX_BONES];
	int outside = !(near_weights(rig, nearest, p, 0.0f, w) > 0.0f);
	/* beyond the boxes' radius (the flanks of a wide trunk around short
	 * spine bones) the ramps still cross-fade the bones meeting the nearest
	 * one, rather than cutting the skin where the nearest bone changes:
	 * the boxes grow to reach the vertex, but not much further, so that a
	 * bone pointing away (a clavicle, for the neck) stays out */
	if (outside)
		near_weights(rig, nearest, p, BIND_REACH * dist, w);
	sibling_cross_fade(rig, nearest, p, w);
	if (!(skin_weights_set_largest(out, v, bone, w, rig->bone_count) > 0.0f)) {
		out->count[v] = 1;
		out->bone[v][0] = (uint16_t)nearest;
		out->weight[v][0] = 1.0f;
	}
	return outside;
}

skp_status bind_weights(const bind_rig *rig, const vec3 *pos, int n,
			skin_weights *out, bind_info *info, skp_error *err)
{
	if (n < 0 || n > SKP_MAX_VERTS)
		return skp_fail(err, SKP_ERR_LIMIT, 0, "%d vertices: the board takes at most %d",
				n, SKP_MAX_VERTS);
	for (int v = 0; v < n; v++)
		if (!isfinite(pos[v].x) || !isfinite(pos[v].y) || !isfinite(pos[v].z))
			return skp_fail(err, SKP_ERR_RANGE, 0, "vertex %d has a non-finite position", v);
	bind_info local;
	if (!info)
		info = &local;
	memset(info, 0, sizeof *info);
	uint16_t bone[SKP_MAX_BONES];
	for (int b = 0; b < rig->bone_count; b++)
		bone[b] = (uint16_t)b;
	out->vert_count = n;
	for (int v = 0; v < n; v++) {
		info->fallback += bind_vertex(rig, bone, pos[v], out, v);
		if (out->count[v] > info->max_influences)
			info->max_influences = out->count[v];
	}
	return SKP_OK;
}
