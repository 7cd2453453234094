#include "bind_pose_guess.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bind_pose_chain.h"
#include "bind_pose_ends.h"
#include "skel_roles.h"
#include "skel_tpose.h"

#define GUESS_OUT          0.35f  /* arm vertices: this far out past the shoulder, of the arm's length */
#define GUESS_MIN_VERTS    50
#define GUESS_RING_ROUNDS  3      /* a ring centred on the bone's axis is pulled to the limb's: repeat */
#define GUESS_MIN_TURN_DEG 8.0f   /* smaller differences are left as the skeleton has them */
#define DEG                0.017453292519943295f

typedef struct guess_ctx {
	const skel *s;
	const mesh *m;
	bind_guess_work *w;
	skel_roles roles;
	float height;
} guess_ctx;

static float bone_len(const skel_pose *p, int b)
{
	return vec3_length(vec3_sub(p->tip[b], p->head[b]));
}

/* The limb's upper bone: along its longest reach, the first bone about as
 * long as the longest (a collar bone is shorter, a forearm comes after);
 * *lower gets the bone after it on that path, or -1. */
static int upper_bone(const guess_ctx *c, int start, int *lower)
{
	const skel *s = c->s;
	const skel_pose *p = &c->w->pose;
	int chain[SKP_MAX_BONES], n = 0;
	float longest = 0.0f;
	for (int b = start; b > 0 && n < SKP_MAX_BONES;) {
		chain[n++] = b;
		longest = fmaxf(longest, bone_len(p, b));
		int next = -1;
		float best = -1.0f;
		for (int k = 1; k < s->count; k++)
			if (s->bone[k].parent == b && bone_len(p, k) + c->roles.reach[k] > best) {
				best = bone_len(p, k) + c->roles.reach[k];
				next = k;
			}
		b = next;
	}
	for (int i = 0; i < n; i++)
		if (bone_len(p, chain[i]) >= 0.9f * longest) {
			*lower = i + 1 < n ? chain[i + 1] : -1;
			return chain[i];
		}
	*lower = -1;
	return start;
}

static float elevation_deg(vec3 d, vec3 up)
{
	return asinf(fmaxf(-1.0f, fminf(1.0f, vec3_dot(vec3_normalize(d), up)))) / DEG;
}

/* The side of the spine the bone is on (+1 or -1 along roles.side). */
static float side_of(const guess_ctx *c, int b)
{
	const skel_pose *p = &c->w->pose;
	return vec3_dot(vec3_sub(p->head[b], p->head[0]), c->roles.side) < 0.0f ? -1.0f : 1.0f;
}

static int cmp_float(const void *a, const void *b)
{
	float x = *(const float *)a, y = *(const float *)b;
	return x < y ? -1 : x > y;
}

/* Is mesh point d (relative to the limb's first joint) part of the limb
 * rather than the torso or the other limb? An arm's is well out past the
 * shoulder; a leg's well below the hip, on the hip's side of the body. */
static int on_limb(const guess_ctx *c, int leg, vec3 d, vec3 from_root, float sgn, float len)
{
	if (vec3_length(d) > 1.2f * len || fabsf(vec3_dot(d, c->roles.depth)) > 0.5f * len)
		return 0;
	if (!leg)
		return sgn * vec3_dot(d, c->roles.side) > GUESS_OUT * len;
	return -vec3_dot(d, c->roles.up) > GUESS_OUT * len && sgn * vec3_dot(from_root, c->roles.side) > 0.0f;
}

/* The mesh's limb elevation seen from u's head: the median elevation, in
 * the frontal plane, of the limb's vertices. */
static int mesh_elevation(const guess_ctx *c, int leg, int u, float *deg)
{
	const skel_pose *p = &c->w->pose;
	vec3 joint = p->head[u];
	float sgn = side_of(c, u), len = bone_len(p, u) + c->roles.reach[u];
	float *e = c->w->elevation;
	int n = 0;
	for (int v = 0; v < c->m->vert_count && n < GUESS_MAX_SAMPLES; v++) {
		vec3 d = vec3_sub(c->m->pos[v], joint);
		if (on_limb(c, leg, d, vec3_sub(c->m->pos[v], p->head[0]), sgn, len))
			e[n++] = atan2f(vec3_dot(d, c->roles.up), sgn * vec3_dot(d, c->roles.side)) / DEG;
	}
	if (n < GUESS_MIN_VERTS)
		return 0;
	qsort(e, (size_t)n, sizeof *e, cmp_float);
	*deg = e[n / 2];
	return 1;
}

/* Where the lower bone l should point: from its head to the centroid of
 * the mesh's vertices past it along the upper bone u (forearm and hand,
 * or shin and foot). */
static int mesh_lower_dir(const guess_ctx *c, int leg, int u, int l, vec3 *dir)
{
	const skel_pose *p = &c->w->pose;
	vec3 joint = p->head[l], along = vec3_normalize(vec3_sub(p->tip[u], p->head[u]));
	float sgn = side_of(c, u), len = bone_len(p, l) + c->roles.reach[l];
	vec3 sum = vec3_make(0.0f, 0.0f, 0.0f);
	int n = 0;
	for (int v = 0; v < c->m->vert_count; v++) {
		vec3 d = vec3_sub(c->m->pos[v], joint);
		if (vec3_dot(d, along) < 0.2f * len || vec3_length(d) > 1.1f * len ||
		    (leg && sgn * vec3_dot(vec3_sub(c->m->pos[v], p->head[0]), c->roles.side) <= 0.0f))
			continue;
		sum = vec3_add(sum, d);
		n++;
	}
	return bind_guess_mean_dir(sum, n, GUESS_MIN_VERTS, dir);
}

static void turn_upper(guess_ctx *c, int leg, int u, float *values, bind_guess_arm *out)
{
	bind_guess_work *w = c->w;
	vec3 d = vec3_sub(w->pose.tip[u], w->pose.head[u]);
	out->bone = u;
	out->from_deg = out->to_deg = elevation_deg(d, c->roles.up);
	float want;
	if (!mesh_elevation(c, leg, u, &want))
		return;
	/* the mesh's elevation, measured in the frontal plane, replaces the
	 * bone's own there: its lateral part keeps its sign and its depth */
	float lat = vec3_dot(d, c->roles.side), dep = vec3_dot(d, c->roles.depth), len = vec3_length(d);
	float now = atan2f(vec3_dot(d, c->roles.up), fabsf(lat)) / DEG;
	if (fabsf(want - now) < GUESS_MIN_TURN_DEG)
		return;
	float sgn = side_of(c, u), planar = sqrtf(fmaxf(0.0f, len * len - dep * dep));
	vec3 target = vec3_add(vec3_add(vec3_scale(c->roles.side, sgn * planar * cosf(want * DEG)),
					vec3_scale(c->roles.up, planar * sinf(want * DEG))),
			       vec3_scale(c->roles.depth, dep));
	skel_aim(c->s, u, target, values, &w->pose);
	out->to_deg = elevation_deg(vec3_sub(w->pose.tip[u], w->pose.head[u]), c->roles.up);
}

/* The bones below the lower bone l: hands, thumbs, feet, toes. */
static void turn_ends(guess_ctx *c, int l, float *values, bind_guess_arm *out)
{
	for (int k = 1; k < c->s->count; k++)
		if (c->s->bone[k].parent == l)
			out->ends += bind_guess_ends(c->s, &c->roles, c->m, k, values, &c->w->pose);
}

static void guess_limb(guess_ctx *c, int start, float *values, bind_guess_arm *out)
{
	bind_guess_work *w = c->w;
	int leg = c->roles.leg[start], l;
	fk_pose(c->s, values, &w->pose);
	int u = upper_bone(c, start, &l);
	turn_upper(c, leg, u, values, out);
	fk_pose(c->s, values, &w->pose);
	vec3 dir;
	out->lower = l;
	out->lower_turn_deg = 0.0f;
	if (l < 0 || !mesh_lower_dir(c, leg, u, l, &dir))
		return;
	vec3 now = vec3_normalize(vec3_sub(w->pose.tip[l], w->pose.head[l]));
	float turn = acosf(fmaxf(-1.0f, fminf(1.0f, vec3_dot(now, dir)))) / DEG;
	if (turn >= GUESS_MIN_TURN_DEG) {
		skel_aim(c->s, l, dir, values, &w->pose);
		out->lower_turn_deg = turn;
	}
	/* the silhouette gives elevations; the limb's cross-sections at the
	 * knee and ankle (elbow and wrist) say where its middle is */
	for (int k = 0; k < GUESS_RING_ROUNDS; k++) {
		out->ends += bind_guess_ring(c->s, c->m, u, values, &w->pose);
		out->ends += bind_guess_ring(c->s, c->m, l, values, &w->pose);
	}
	turn_ends(c, l, values, out);
	/* then the chain from the collar bone (hip joint) to the lower bone
	 * through the middle of the limb, and the ends once more from there */
	unsigned char on_chain[SKP_MAX_BONES] = { 0 };
	for (int b = l, guard = 0; b > 0 && guard < SKP_MAX_BONES; b = c->s->bone[b].parent, guard++) {
		on_chain[b] = 1;
		if (b == start)
			break;
	}
	if (bind_guess_chain(c->s, c->m, start, on_chain, leg ? -1 : l, values, &w->pose, w->chain_vert) > 0) {
		out->ends++;
		turn_ends(c, l, values, out);
	}
}

void bind_guess_pose(const skel *s, const mesh *m, float *values, bind_guess_work *w,
		     bind_guess_result *out)
{
	guess_ctx c;
	memset(&c, 0, sizeof c);
	c.s = s;
	c.m = m;
	c.w = w;
	memset(out, 0, sizeof *out);
	if (s->count < 2 || m->vert_count == 0)
		return;
	fk_pose(s, values, &w->pose);
	skel_find_roles(s, &w->pose, &c.roles);
	c.height = c.roles.H;
	if (!(c.height > 0.0f))
		return;
	for (int b = 1; b < s->count && out->arm_count < BIND_GUESS_MAX_ARMS; b++) {
		if ((!c.roles.arm[b] && !c.roles.leg[b]) || skel_branch_start(s, &c.roles, b) != b)
			continue;
		bind_guess_arm *a = &out->arm[out->arm_count++];
		guess_limb(&c, b, values, a);
		out->turned += a->to_deg != a->from_deg || a->lower_turn_deg != 0.0f || a->ends;
	}
}
