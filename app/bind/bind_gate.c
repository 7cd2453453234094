#include "bind_gate.h"

#include <math.h>
#include <string.h>

#include "skel_roles.h"

const bind_gate_limits bind_gate_default_limits = {
	.stretch_ratio = 3.0f,
	.stretch_extent = 0.30f,
	.drift = 0.12f,
	.root_share = 0.25f,
	.follow_min = 0.35f,
	.region_min = 20,
};

/* A vertex displaced by less than this share of the extent (by its bone's
 * move, or in the body's own frame) does not count as moving. */
#define GATE_MOVING 0.02f
/* Vertices whose projection on their region's bone falls in its first
 * quarter are joint skin (a hip, a robot's torso beside its thigh): the
 * root and rigid checks judge the limb by the rest. */
#define GATE_INNER 0.25f

static vec3 vertex(const float *xyz, int v)
{
	return vec3_make(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
}

static void set_segments(bind_gate_work *w, const skel_pose *p)
{
	w->seg_count = 0;
	for (int b = 1; b < w->skel->count; b++) {
		vec3 d = vec3_sub(p->tip[b], p->head[b]);
		float len = vec3_length(d);
		if (!(len > 1e-6f * w->extent))
			continue;
		bind_segment *g = &w->seg[w->seg_count];
		memset(g, 0, sizeof *g);
		g->head = p->head[b];
		g->dir = vec3_scale(d, 1.0f / len);
		g->length = len;
		w->seg_bone[w->seg_count++] = b;
	}
}

/* Distance to the nearest bone of the current segments; *bone gets it (0: none). */
static float nearest(const bind_gate_work *w, vec3 q, int *bone)
{
	float d;
	int k = bind_segment_nearest(w->seg, w->seg_count, q, &d);
	*bone = k < 0 ? 0 : w->seg_bone[k];
	return w->seg_count ? d : 0.0f;
}

static float extent_of(const skel *s, const skel_pose *p)
{
	vec3 lo = p->head[0], hi = lo;
	for (int b = 0; b < s->count; b++) {
		const vec3 pt[2] = { p->head[b], p->tip[b] };
		for (int k = 0; k < 2; k++) {
			lo = vec3_make(fminf(lo.x, pt[k].x), fminf(lo.y, pt[k].y), fminf(lo.z, pt[k].z));
			hi = vec3_make(fmaxf(hi.x, pt[k].x), fmaxf(hi.y, pt[k].y), fmaxf(hi.z, pt[k].z));
		}
	}
	return fmaxf(hi.x - lo.x, fmaxf(hi.y - lo.y, hi.z - lo.z));
}

/* Where along its nearest bone the point projects, 0 at the head, 1 at the tip. */
static float along(const bind_gate_work *w, int bone, vec3 q)
{
	for (int k = 0; k < w->seg_count; k++)
		if (w->seg_bone[k] == bone)
			return vec3_dot(vec3_sub(q, w->seg[k].head), w->seg[k].dir) / w->seg[k].length;
	return 0.0f;
}

static void worst_reset(bind_gate_worst *b, float value)
{
	b->value = value;
	b->region = -1;
	b->move = -1;
	b->frame = 0;
	b->vertex = -1;
}

static void worst_note(bind_gate_worst *b, float value, int region, int move, long frame, int vertex)
{
	b->value = value;
	b->region = region;
	b->move = move;
	b->frame = frame;
	b->vertex = vertex;
}

/* The weighted distance to the vertex's own bones (a zero-length one: to
 * its point), in the current pose. */
static float own_distance(const bind_gate_work *w, const skel_pose *p, const skin_weights *wt, int v)
{
	float d = 0.0f;
	for (int k = 0; k < wt->count[v]; k++) {
		int b = wt->bone[v][k];
		bind_segment g;
		memset(&g, 0, sizeof g);
		g.head = p->head[b];
		vec3 axis = vec3_sub(p->tip[b], p->head[b]);
		g.length = vec3_length(axis);
		g.dir = g.length > 0.0f ? vec3_scale(axis, 1.0f / g.length) : vec3_make(1.0f, 0.0f, 0.0f);
		d += wt->weight[v][k] * bind_segment_distance(&g, w->mesh->pos[v]);
	}
	return d;
}

/* Whether the vertex is judged with its region: unless its heaviest bone
 * belongs to another branch (neither the region's bone, above it nor
 * below it) and holds it near (within 2.5 times its distance to the
 * region's bone: a big head beside an upper arm is the head's skin; a
 * whole body weighted to one foot is no foot's). */
static int in_limb(const bind_gate_work *w, const skin_weights *wt, int v, int region)
{
	int best = 0;
	for (int k = 1; k < wt->count[v]; k++)
		if (wt->weight[v][k] > wt->weight[v][best])
			best = k;
	int b = wt->count[v] ? wt->bone[v][best] : 0;
	if (bind_rom_below(w->skel, region, b) || bind_rom_below(w->skel, b, region))
		return 1;
	vec3 axis = vec3_sub(w->bind->tip[b], w->bind->head[b]);
	bind_segment g;
	memset(&g, 0, sizeof g);
	g.head = w->bind->head[b];
	g.length = vec3_length(axis);
	g.dir = g.length > 0.0f ? vec3_scale(axis, 1.0f / g.length) : vec3_make(1.0f, 0.0f, 0.0f);
	return bind_segment_distance(&g, w->mesh->pos[v]) > 2.5f * w->bind_dist[v] + 1e-3f * w->extent;
}

static int root_alone(const skin_weights *wt, int v)
{
	float other = 0.0f;
	for (int k = 0; k < wt->count[v]; k++)
		if (wt->bone[v][k] != 0)
			other += wt->weight[v][k];
	return !(other > 1e-3f);
}

void bind_gate_start(bind_gate_work *w, const skel *s, const skel_pose *bind, const mesh *m,
		     const skin_weights *wt, const uint8_t *orphan, const uint8_t *held,
		     const bind_gate_limits *lim)
{
	w->skel = s;
	w->bind = bind;
	w->mesh = m;
	w->lim = lim ? *lim : bind_gate_default_limits;
	w->extent = extent_of(s, bind);
	memset(&w->res, 0, sizeof w->res);
	w->res.extent = w->extent;
	worst_reset(&w->res.stretch, 1.0f);
	worst_reset(&w->res.drift, 0.0f);
	worst_reset(&w->res.grow, 0.0f);
	worst_reset(&w->res.closer, 0.0f);
	worst_reset(&w->res.root, 0.0f);
	worst_reset(&w->res.rigid, 1.0f);
	memset(w->region_verts, 0, sizeof w->region_verts);
	skel_roles roles;
	skel_find_roles(s, bind, &roles);
	for (int b = 0; b < s->count; b++)
		w->limb[b] = roles.arm[b] || roles.leg[b];
	memset(w->follow_num, 0, sizeof w->follow_num);
	memset(w->follow_den, 0, sizeof w->follow_den);
	set_segments(w, bind);
	for (int v = 0; v < m->vert_count; v++) {
		int r;
		w->bind_dist[v] = nearest(w, m->pos[v], &r);
		w->own_dist[v] = fmaxf(w->bind_dist[v], own_distance(w, bind, wt, v));
		w->region[v] = (int16_t)r;
		w->inner[v] = along(w, r, m->pos[v]) >= GATE_INNER && in_limb(w, wt, v, r) && !(held && held[v]);
		w->region_verts[r] += w->inner[v];
		w->root_only[v] = (uint8_t)(orphan ? orphan[v] != 0 : root_alone(wt, v));
		w->drifted[v] = 0;
	}
	for (int t = 0; t < m->tri_count; t++) {
		w->torn[t] = 0;
		for (int k = 0; k < 3; k++)
			w->bind_edge[t][k] = vec3_length(vec3_sub(m->pos[m->tri[t][k]], m->pos[m->tri[t][(k + 1) % 3]]));
	}
}

static void measure_edges(bind_gate_work *w, const float *xyz, int move, long frame)
{
	const mesh *m = w->mesh;
	float min_len = 1e-4f * w->extent;
	for (int t = 0; t < m->tri_count; t++)
		for (int k = 0; k < 3; k++) {
			int a = (int)m->tri[t][k], b = (int)m->tri[t][(k + 1) % 3];
			float bind_len = w->bind_edge[t][k];
			if (!(bind_len > min_len))
				continue;
			float len = vec3_length(vec3_sub(vertex(xyz, a), vertex(xyz, b)));
			float ratio = len / bind_len;
			if (ratio > w->res.stretch.value)
				worst_note(&w->res.stretch, ratio, w->region[a], move, frame, a);
			if ((len - bind_len) / w->extent > w->res.grow.value)
				worst_note(&w->res.grow, (len - bind_len) / w->extent, w->region[a], move, frame, a);
			if (ratio > 2.0f && !(w->torn[t] >> (k + 3) & 1)) {
				w->torn[t] |= (uint8_t)(1u << (k + 3));
				w->res.doubled_edges++;
			}
			if (ratio > w->lim.stretch_ratio && len - bind_len > w->lim.stretch_extent * w->extent &&
			    !(w->torn[t] >> k & 1)) {
				w->torn[t] |= (uint8_t)(1u << k);
				w->res.torn_edges++;
			}
		}
}

/* A vertex in the body's own frame (the root's), to tell whether it moved. */
static vec3 in_body(quat rot, vec3 origin, vec3 p)
{
	return quat_rotate(quat_conj(rot), vec3_sub(p, origin));
}

/* Only vertices that moved can leave their bones: one left behind as a
 * limb swings away (a robot's torso corner beside its shoulder) keeps
 * its place, however far the skeleton goes. */
static void measure_drift(bind_gate_work *w, const skel_pose *pose, const float *xyz, int move, long frame)
{
	float moving = GATE_MOVING * w->extent;
	for (int v = 0; v < w->mesh->vert_count; v++) {
		int r;
		vec3 q = vertex(xyz, v);
		vec3 shift = vec3_sub(in_body(pose->rot[0], pose->head[0], q),
				      in_body(w->bind->rot[0], w->bind->head[0], w->mesh->pos[v]));
		float now = nearest(w, q, &r), change = (now - w->bind_dist[v]) / w->extent;
		/* a part far from its bone (a robot's big head, a strap on a
		 * forearm) that keeps to it leaves nothing */
		float left = (now - w->own_dist[v]) / w->extent;
		if (change > 0.0f && (!(vec3_length(shift) > moving) || left < change))
			change = fmaxf(0.0f, vec3_length(shift) > moving ? left : 0.0f);
		if (-change > w->res.closer.value)
			worst_note(&w->res.closer, -change, w->region[v], move, frame, v);
		if (change > w->res.drift.value)
			worst_note(&w->res.drift, change, w->region[v], move, frame, v);
		if (change > w->lim.drift && !w->drifted[v]) {
			w->drifted[v] = 1;
			w->res.drifting++;
		}
	}
}

/* Vertices of the regions the move turns: their displacement against the
 * one the turn gives them (a limb's moves only: the spine bends its own
 * way, as a robot's one-piece torso does), and root-only ones seen moving. */
static void measure_follow(bind_gate_work *w, const float *xyz, const bind_rom_move *mv)
{
	const mesh *m = w->mesh;
	vec3 pivot = w->bind->head[mv->bone];
	float moving = GATE_MOVING * w->extent;
	for (int v = 0; v < m->vert_count; v++) {
		int r = w->region[v];
		if (r <= 0 || !w->inner[v] || !bind_rom_below(w->skel, r, mv->bone))
			continue;
		vec3 rel = vec3_sub(m->pos[v], pivot);
		vec3 e = vec3_sub(quat_rotate(mv->turn, rel), rel);
		float e2 = vec3_dot(e, e);
		if (!(e2 > moving * moving))
			continue;
		if (w->root_only[v] == 1) {
			w->root_only[v] = 2;
			w->res.root_moving++;
		}
		if (!w->limb[mv->bone])
			continue;
		vec3 a = vec3_sub(vertex(xyz, v), m->pos[v]);
		w->follow_num[r] += vec3_dot(a, e);
		w->follow_den[r] += e2;
	}
}

void bind_gate_add(bind_gate_work *w, const skel_pose *pose, const float *xyz, const bind_rom_move *move,
		   int move_index, long frame)
{
	int idx = move ? move_index : -1;
	set_segments(w, pose);
	measure_edges(w, xyz, idx, frame);
	measure_drift(w, pose, xyz, idx, frame);
	if (move) {
		measure_follow(w, xyz, move);
		w->res.moves++;
	} else {
		w->res.frames++;
	}
}

/* Per region: the share of root-only vertices seen moving, and how well
 * the region follows its bone. */
static void judge_regions(bind_gate_work *w)
{
	int moving_root[SKP_MAX_BONES];
	memset(moving_root, 0, sizeof moving_root);
	for (int v = 0; v < w->mesh->vert_count; v++)
		moving_root[w->region[v]] += w->root_only[v] == 2 && w->inner[v];
	for (int r = 1; r < w->skel->count; r++) {
		if (w->region_verts[r] < w->lim.region_min)
			continue;
		/* a bone starting at the root joint holds pelvis skin, which the
		 * root may own, and a rig with fewer spine joints than the
		 * skeleton leaves its bend to the bones above */
		if (!(vec3_length(vec3_sub(w->bind->head[r], w->bind->head[0])) > 1e-3f * w->extent))
			continue;
		float share = (float)moving_root[r] / (float)w->region_verts[r];
		if (share > w->res.root.value)
			worst_note(&w->res.root, share, r, -1, 0, -1);
		if (w->follow_den[r] > 0.0 && w->limb[r]) {
			float follow = (float)(w->follow_num[r] / w->follow_den[r]);
			if (follow < w->res.rigid.value)
				worst_note(&w->res.rigid, follow, r, -1, 0, -1);
		}
	}
}

void bind_gate_finish(bind_gate_work *w, bind_gate_result *out)
{
	judge_regions(w);
	bind_gate_result *r = &w->res;
	r->failed = 0;
	if (r->torn_edges)
		r->failed |= BIND_GATE_TEARS;
	if (r->drifting)
		r->failed |= BIND_GATE_DRIFT;
	if (r->root.value > w->lim.root_share)
		r->failed |= BIND_GATE_ROOT;
	if (r->rigid.region >= 0 && r->rigid.value < w->lim.follow_min)
		r->failed |= BIND_GATE_RIGID;
	*out = *r;
}
