#include "bind_gate.h"

#include <math.h>
#include <string.h>

const bind_gate_limits bind_gate_default_limits = {
	.stretch_ratio = 3.0f,
	.stretch_extent = 0.30f,
	.drift = 0.12f,
	.root_share = 0.25f,
	.follow_min = 0.35f,
	.region_min = 20,
};

/* A vertex displaced by less than this share of the extent by its bone's
 * move does not count as moving (for the root check and the follow sums). */
#define GATE_MOVING 0.02f

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
	float best = INFINITY;
	*bone = 0;
	for (int k = 0; k < w->seg_count; k++) {
		float d = bind_segment_distance(&w->seg[k], q);
		if (d < best) {
			best = d;
			*bone = w->seg_bone[k];
		}
	}
	return w->seg_count ? best : 0.0f;
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

static int root_alone(const skin_weights *wt, int v)
{
	float other = 0.0f;
	for (int k = 0; k < wt->count[v]; k++)
		if (wt->bone[v][k] != 0)
			other += wt->weight[v][k];
	return !(other > 1e-3f);
}

void bind_gate_start(bind_gate_work *w, const skel *s, const skel_pose *bind, const mesh *m,
		     const skin_weights *wt, const bind_gate_limits *lim)
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
	memset(w->follow_num, 0, sizeof w->follow_num);
	memset(w->follow_den, 0, sizeof w->follow_den);
	set_segments(w, bind);
	for (int v = 0; v < m->vert_count; v++) {
		int r;
		w->bind_dist[v] = nearest(w, m->pos[v], &r);
		w->region[v] = (int16_t)r;
		w->region_verts[r]++;
		w->root_only[v] = (uint8_t)root_alone(wt, v);
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
			if (ratio > w->lim.stretch_ratio && len - bind_len > w->lim.stretch_extent * w->extent &&
			    !(w->torn[t] >> k & 1)) {
				w->torn[t] |= (uint8_t)(1u << k);
				w->res.torn_edges++;
			}
		}
}

static void measure_drift(bind_gate_work *w, const float *xyz, int move, long frame)
{
	for (int v = 0; v < w->mesh->vert_count; v++) {
		int r;
		float change = (nearest(w, vertex(xyz, v), &r) - w->bind_dist[v]) / w->extent;
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
 * one the turn gives them. */
static void measure_follow(bind_gate_work *w, const float *xyz, const bind_rom_move *mv)
{
	const mesh *m = w->mesh;
	vec3 pivot = w->bind->head[mv->bone];
	float moving = GATE_MOVING * w->extent;
	for (int v = 0; v < m->vert_count; v++) {
		int r = w->region[v];
		if (r <= 0 || !bind_rom_below(w->skel, r, mv->bone))
			continue;
		vec3 rel = vec3_sub(m->pos[v], pivot);
		vec3 e = vec3_sub(quat_rotate(mv->turn, rel), rel);
		float e2 = vec3_dot(e, e);
		if (!(e2 > moving * moving))
			continue;
		vec3 a = vec3_sub(vertex(xyz, v), m->pos[v]);
		w->follow_num[r] += vec3_dot(a, e);
		w->follow_den[r] += e2;
		if (w->root_only[v] == 1) {
			w->root_only[v] = 2;
			w->res.root_moving++;
		}
	}
}

void bind_gate_add(bind_gate_work *w, const skel_pose *pose, const float *xyz, const bind_rom_move *move,
		   int move_index, long frame)
{
	int idx = move ? move_index : -1;
	set_segments(w, pose);
	measure_edges(w, xyz, idx, frame);
	measure_drift(w, xyz, idx, frame);
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
		moving_root[w->region[v]] += w->root_only[v] == 2;
	for (int r = 1; r < w->skel->count; r++) {
		if (w->region_verts[r] < w->lim.region_min)
			continue;
		float share = 0.0f;
		/* a bone starting at the root joint holds pelvis skin, which the root may own */
		if (vec3_length(vec3_sub(w->bind->head[r], w->bind->head[0])) > 1e-3f * w->extent)
			share = (float)moving_root[r] / (float)w->region_verts[r];
		if (share > w->res.root.value)
			worst_note(&w->res.root, share, r, -1, 0, -1);
		if (w->follow_den[r] > 0.0) {
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
