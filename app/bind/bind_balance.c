#include "bind_balance.h"

#include <math.h>
#include <string.h>

#include "bind_balance_solve.h"

/* A share this close to 0 or 1 counts as outside the cross-fade. */
#define SHARE_EDGE 1e-6
/* Fewer cross-fade vertices than this: no joint to speak of. */
#define MIN_CROSS_FADE 10
#define THIRTY_DEGREES (3.14159265358979323846 / 6.0)

/* Neighbour lists in compressed rows: each triangle lists its other two
 * corners for each corner, so an inner edge appears twice (a uniform
 * weight, the same for every edge of a closed mesh). */
static skp_status build_adjacency(bind_balance_work *w, int n, const uint32_t (*tri)[3],
				  int tri_count, skp_error *err)
{
	memset(w->adj_start, 0, (size_t)(n + 1) * sizeof w->adj_start[0]);
	for (int t = 0; t < tri_count; t++)
		for (int k = 0; k < 3; k++) {
			if (tri[t][k] >= (uint32_t)n)
				return skp_fail(err, SKP_ERR_RANGE, 0,
						"triangle %d: vertex %lu, the mesh has %d",
						t, (unsigned long)tri[t][k], n);
			w->adj_start[tri[t][k] + 1] += 2;
		}
	for (int v = 0; v < n; v++)
		w->adj_start[v + 1] += w->adj_start[v];
	/* fill using slot as a cursor, then give slot back */
	for (int v = 0; v < n; v++)
		w->slot[v] = (int32_t)w->adj_start[v];
	for (int t = 0; t < tri_count; t++)
		for (int k = 0; k < 3; k++) {
			uint32_t v = tri[t][k];
			w->adj[w->slot[v]++] = tri[t][(k + 1) % 3];
			w->adj[w->slot[v]++] = tri[t][(k + 2) % 3];
		}
	for (int v = 0; v < n; v++)
		w->slot[v] = -1;
	return SKP_OK;
}

static void cross(const double a[3], const double b[3], double out[3])
{
	out[0] = a[1] * b[2] - a[2] * b[1];
	out[1] = a[2] * b[0] - a[0] * b[2];
	out[2] = a[0] * b[1] - a[1] * b[0];
}

static void to_double(vec3 p, double out[3])
{
	out[0] = p.x;
	out[1] = p.y;
	out[2] = p.z;
}

/* V = sum over triangles of a . (b x c) / 6, and its gradient per vertex. */
static double volume_gradient(bind_balance_work *w, const vec3 *pos, int n,
			      const uint32_t (*tri)[3], int tri_count)
{
	double volume = 0.0;
	memset(w->grad, 0, (size_t)n * sizeof w->grad[0]);
	for (int t = 0; t < tri_count; t++) {
		double p[3][3], g[3];
		for (int k = 0; k < 3; k++)
			to_double(pos[tri[t][k]], p[k]);
		for (int k = 0; k < 3; k++) {
			cross(p[(k + 1) % 3], p[(k + 2) % 3], g);
			double *dst = w->grad[tri[t][k]];
			for (int i = 0; i < 3; i++)
				dst[i] += g[i] / 6.0;
		}
		cross(p[1], p[2], g);
		volume += (p[0][0] * g[0] + p[0][1] * g[1] + p[0][2] * g[2]) / 6.0;
	}
	return volume;
}

static int rotates(const skel_bone *b)
{
	for (int k = 0; k < b->channel_count; k++)
		if (b->channel[k] <= SKEL_RZ)
			return 1;
	return 0;
}

static void mark_subtree(const skel *s, int joint, uint8_t *sub)
{
	for (int b = 0; b < s->count; b++) {
		int a = b;
		while (a > 0 && a != joint)
			a = s->bone[a].parent;
		sub[b] = (uint8_t)(a == joint);
	}
}

/* Shares, arms, which vertices the balancing may touch and the moment of
 * the joint at bone b's head; returns how many vertices lie in the
 * cross-fade. */
static int joint_moment(bind_balance_work *w, const skel_pose *pose, int b, const vec3 *pos,
			const skin_weights *sw, double moment[3])
{
	double c[3];
	int cross_fade = 0;
	to_double(pose->head[b], c);
	moment[0] = moment[1] = moment[2] = 0.0;
	for (int v = 0; v < sw->vert_count; v++) {
		float t = 0.0f;
		for (int k = 0; k < sw->count[v]; k++)
			if (w->subtree[sw->bone[v][k]])
				t += sw->weight[v][k];
		w->share[v] = t;
		int d = skin_weights_dominant(sw, v);
		w->reachable[v] = (uint8_t)(d >= 0 && (d == b || !w->subtree[d]));
		double p[3], r[3];
		to_double(pos[v], p);
		for (int i = 0; i < 3; i++)
			r[i] = p[i] - c[i];
		cross(r, w->grad[v], w->arm[v]);
		for (int i = 0; i < 3; i++)
			moment[i] += t * w->arm[v][i];
		cross_fade += t > SHARE_EDGE && t < 1.0 - SHARE_EDGE;
	}
	return cross_fade;
}

/* The cross-fade, then `rings` rings of neighbours around it; only
 * vertices mostly on the joint's own bone or outside its subtree: the
 * limb beyond (the upper arm, for a clavicle) must not take the body's
 * weight, nor the body's weight move onto it. */
static int grow_band(bind_balance_work *w, int n, int rings)
{
	int m = 0;
	for (int v = 0; v < n; v++) {
		w->slot[v] = -1;
		if (w->share[v] > SHARE_EDGE && w->share[v] < 1.0 - SHARE_EDGE && w->reachable[v]) {
			w->slot[v] = m;
			w->band[m++] = (uint32_t)v;
		}
	}
	for (int ring = 0, from = 0; ring < rings; ring++) {
		int to = m;
		for (int i = from; i < to; i++) {
			uint32_t v = w->band[i];
			for (uint32_t k = w->adj_start[v]; k < w->adj_start[v + 1]; k++) {
				uint32_t u = w->adj[k];
				if (w->slot[u] < 0 && w->reachable[u]) {
					w->slot[u] = m;
					w->band[m++] = u;
				}
			}
		}
		from = to;
	}
	return m;
}

static double norm3(const double v[3])
{
	return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/* Gives vertex v the subtree share t1: the side that loses keeps its
 * bones' proportions; what the other side gains goes to the bone next to
 * the joint (the joint's own bone, or its parent), not to a bone that
 * merely had a trace of weight there (a forearm vertex with 1e-4 on the
 * clavicle would otherwise take the forearm's share to the clavicle). */
static void reshare(skin_weights *sw, int v, const uint8_t *sub, int joint, int parent, float t0, float t1)
{
	uint16_t bone[SKP_MAX_INFLUENCES + 1] = { 0 };
	float weight[SKP_MAX_INFLUENCES + 1] = { 0 };
	int count = sw->count[v], gainer = t1 > t0 ? joint : parent;
	float keep_in = t1 < t0 ? t1 / t0 : 1.0f;
	float keep_out = t1 > t0 ? (1.0f - t1) / (1.0f - t0) : 1.0f;
	for (int k = 0; k < count; k++) {
		bone[k] = sw->bone[v][k];
		weight[k] = sw->weight[v][k] * (sub[bone[k]] ? keep_in : keep_out);
	}
	int k = 0;
	while (k < count && bone[k] != gainer)
		k++;
	if (k == count) {
		bone[count] = (uint16_t)gainer;
		weight[count++] = 0.0f;
	}
	weight[k] += fabsf(t1 - t0);
	skin_weights_set_largest(sw, v, bone, weight, count);
}

static void apply_change(bind_balance_work *w, int m, const skel *s, int b, skin_weights *sw)
{
	for (int i = 0; i < m; i++) {
		if (w->change[i] == 0.0)
			continue;
		int v = (int)w->band[i];
		float t0 = w->share[v];
		float t1 = (float)fmin(1.0, fmax(0.0, t0 + w->change[i]));
		reshare(sw, v, w->subtree, b, s->bone[b].parent, t0, t1);
	}
}

/* Scales the change down to the largest share change allowed; the moment
 * left scales with it. */
static void cap_change(bind_balance_work *w, int m, const double moment[3], double left[3], double most)
{
	double f = BIND_BALANCE_MAX_CHANGE / most;
	for (int i = 0; i < m; i++)
		w->change[i] *= f;
	for (int k = 0; k < 3; k++)
		left[k] = moment[k] + f * (left[k] - moment[k]);
}

/* The smallest band (by rings of two) whose change stays within
 * BIND_BALANCE_AIM, else the widest, its change capped at
 * BIND_BALANCE_MAX_CHANGE; applied. */
static void balance_joint(bind_balance_work *w, const skel *s, const skel_pose *pose, int b,
			  const vec3 *pos, skin_weights *sw, double volume, bind_balance_info *info)
{
	double moment[3], left[3], most = 0.0;
	mark_subtree(s, b, w->subtree);
	int cross_fade = joint_moment(w, pose, b, pos, sw, moment);
	double scale = THIRTY_DEGREES / fabs(volume);
	info->moment[b] = (float)(norm3(moment) * scale);
	if (cross_fade < MIN_CROSS_FADE)
		return;
	info->outcome[b] = BIND_BALANCE_NEEDLESS;
	if (norm3(moment) * scale < BIND_BALANCE_MIN_MOMENT)
		return;
	int m = 0, rings = 2;
	for (;; rings += 2) {
		m = grow_band(w, sw->vert_count, rings);
		most = balance_solve(w, m, moment, left);
		if (most <= BIND_BALANCE_AIM || rings + 2 > BIND_BALANCE_MAX_RINGS)
			break;
	}
	info->outcome[b] = BIND_BALANCE_DONE;
	if (most > BIND_BALANCE_MAX_CHANGE) {
		cap_change(w, m, moment, left, most);
		most = BIND_BALANCE_MAX_CHANGE;
		info->outcome[b] = BIND_BALANCE_PARTLY;
	}
	info->change[b] = (float)most;
	info->rings[b] = (uint8_t)rings;
	info->moment_after[b] = (float)(norm3(left) * scale);
	apply_change(w, m, s, b, sw);
}

static skp_status check_bones(const skel *s, const skin_weights *sw, skp_error *err)
{
	for (int v = 0; v < sw->vert_count; v++)
		for (int k = 0; k < sw->count[v]; k++)
			if (sw->bone[v][k] >= s->count)
				return skp_fail(err, SKP_ERR_RANGE, 0, "vertex %d: bone %d, the skeleton has %d",
						v, sw->bone[v][k], s->count);
	return SKP_OK;
}

skp_status bind_balance(const skel *s, const skel_pose *pose, const vec3 *pos, int n,
			const uint32_t (*tri)[3], int tri_count, skin_weights *w,
			bind_balance_work *work, bind_balance_info *info, skp_error *err)
{
	return bind_balance_watched(s, pose, pos, n, tri, tri_count, w, work, info, NULL, err);
}

skp_status bind_balance_watched(const skel *s, const skel_pose *pose, const vec3 *pos, int n,
				const uint32_t (*tri)[3], int tri_count, skin_weights *w,
				bind_balance_work *work, bind_balance_info *info,
				const bind_progress *progress, skp_error *err)
{
	bind_balance_info local;
	if (!info)
		info = &local;
	memset(info, 0, sizeof *info);
	if (n != w->vert_count || n < 0 || n > SKP_MAX_VERTS || tri_count < 0 || tri_count > SKP_MAX_TRIS)
		return skp_fail(err, SKP_ERR_RANGE, 0, "%d vertices, %d weighted, %d triangles",
				n, w->vert_count, tri_count);
	skp_status rc = check_bones(s, w, err);
	if (rc == SKP_OK)
		rc = build_adjacency(work, n, tri, tri_count, err);
	if (rc != SKP_OK)
		return rc;
	info->volume = volume_gradient(work, pos, n, tri, tri_count);
	if (!(fabs(info->volume) > 0.0))
		return SKP_OK;
	for (int b = 1; b < s->count; b++) {
		if (rotates(&s->bone[b]))
			balance_joint(work, s, pose, b, pos, w, info->volume, info);
		if (progress)
			progress->step(progress->ctx, b, s->count - 1);
	}
	return SKP_OK;
}
