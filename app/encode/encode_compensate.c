/* Quantising a clip's tracks with their ancestors' rounding taken up: a
 * joint with three rotational dofs gets the angles that put it where the
 * source has it in the world, given its parent as decoded (in double,
 * then on its grid), so a limb's error is each joint's own rounding, not
 * the sum of its ancestors'. */
#include <math.h>
#include <string.h>

#include "encode_work.h"

typedef double mat3[9];

static void mat_mul(const double *a, const double *b, double *out)
{
	double r[9];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			r[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
	memcpy(out, r, sizeof r);
}

static void mat_transpose(const double *a, double *out)
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			out[3 * j + i] = a[3 * i + j];
}

static void mat_of_quat(quat q, double *m)
{
	double w = q.w, x = q.x, y = q.y, z = q.z;
	m[0] = 1 - 2 * (y * y + z * z); m[1] = 2 * (x * y - w * z); m[2] = 2 * (x * z + w * y);
	m[3] = 2 * (x * y + w * z); m[4] = 1 - 2 * (x * x + z * z); m[5] = 2 * (y * z - w * x);
	m[6] = 2 * (x * z - w * y); m[7] = 2 * (y * z + w * x); m[8] = 1 - 2 * (x * x + y * y);
}

static void mat_axis(int axis, double a, double *m)
{
	double c = cos(a), s = sin(a);
	static const int other[3][2] = { { 1, 2 }, { 2, 0 }, { 0, 1 } };
	int i = other[axis][0], j = other[axis][1];
	memset(m, 0, 9 * sizeof(double));
	m[4 * axis] = 1;
	m[3 * i + i] = c; m[3 * i + j] = -s;
	m[3 * j + i] = s; m[3 * j + j] = c;
}

/* The bone's world rotation from its parent's and its values: parent C M
 * C^T, M its rotational channels, first listed applied first (fk.c). */
static void world_rot(const skel_bone *b, const double *parent, const float *v, double *g)
{
	double m[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }, r[9], c[9], ct[9];
	for (int i = 0; i < b->channel_count; i++)
		if (b->channel[i] <= SKEL_RZ) {
			mat_axis(b->channel[i] - SKEL_RX, v[i], r);
			mat_mul(r, m, m);
		}
	mat_of_quat(b->axis_rot, c);
	mat_transpose(c, ct);
	mat_mul(c, m, m);
	mat_mul(m, ct, m);
	mat_mul(parent, m, g);
}

static const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };

static const double *parent_of(const double *all, const skel *s, int b, long f)
{
	int p = s->bone[b].parent;
	return p < 0 ? identity : all + ((size_t)f * (size_t)s->count + (size_t)p) * 9;
}

static void mat_apply(const double *m, const double *v, double *out)
{
	double r[3];
	for (int i = 0; i < 3; i++)
		r[i] = m[3 * i] * v[0] + m[3 * i + 1] * v[1] + m[3 * i + 2] * v[2];
	memcpy(out, r, sizeof r);
}

static double *pos_at(double *all, const skel *s, int b, long f)
{
	return all + ((size_t)f * (size_t)s->count + (size_t)b) * 6;
}

/* Where bone b's head and tip are (pos: head xyz, tip xyz), from its
 * parent's rotation gp and tip, its own rotation g and values v: fk.c's
 * steps in double. */
static void place(const skel *s, int b, const double *gp, const double *ptip, const double *g, const float *v,
		  double *pos)
{
	const skel_bone *bone = &s->bone[b];
	double t[3] = { 0, 0, 0 }, stretch = 0, x[3], c[9], gc[9];
	for (int i = 0; i < bone->channel_count; i++) {
		int ch = bone->channel[i];
		if (ch >= SKEL_TX && ch <= SKEL_TZ)
			t[ch - SKEL_TX] = v[i];
		else if (ch == SKEL_L)
			stretch = v[i];
	}
	if (b == 0) {
		double root[3] = { s->root_position.x, s->root_position.y, s->root_position.z };
		for (int i = 0; i < 3; i++)
			pos[i] = pos[3 + i] = root[i] + t[i];
		return;
	}
	double off[3] = { bone->offset.x, bone->offset.y, bone->offset.z };
	double dir[3] = { bone->direction.x, bone->direction.y, bone->direction.z };
	mat_apply(gp, off, x);
	mat_of_quat(bone->axis_rot, c);
	mat_mul(gp, c, gc);
	for (int i = 0; i < 3; i++)
		pos[i] = ptip[i] + x[i];
	mat_apply(gc, t, x);
	for (int i = 0; i < 3; i++)
		pos[i] += x[i];
	mat_apply(g, dir, x);
	for (int i = 0; i < 3; i++)
		pos[3 + i] = pos[i] + x[i] * (bone->length + stretch);
}

static void place_frame_bone(const enc_work *w, double *rots, double *poss, const float *values, int b, long f)
{
	const skel *s = w->s;
	static const double origin[6] = { 0, 0, 0, 0, 0, 0 };
	int p = s->bone[b].parent;
	place(s, b, parent_of(rots, s, b, f), p < 0 ? origin + 3 : pos_at(poss, s, p, f) + 3,
	      rots + ((size_t)f * (size_t)s->count + (size_t)b) * 9, values + s->bone[b].dof_offset, pos_at(poss, s, b, f));
}


void enc_comp_prepare(enc_work *w)
{
	const skel *s = w->s;
	for (int b = 0; b < s->count; b++) {
		const skel_bone *bone = &s->bone[b];
		int rot = 0;
		for (int i = 0; i < bone->channel_count; i++)
			rot += bone->channel[i] <= SKEL_RZ;
		int distinct = bone->channel_count == 3 && bone->channel[0] != bone->channel[1] &&
			       bone->channel[1] != bone->channel[2] && bone->channel[0] != bone->channel[2];
		w->comp[b] = b != 0 && rot == 3 && distinct;
	}
	for (long f = 0; f < w->n; f++)
		for (int k = 0; k < s->count; k++) {
			int b = s->eval_order[k];
			const float *frame = w->src + (size_t)f * (size_t)w->dofs;
			world_rot(&s->bone[b], parent_of(w->gsrc, s, b, f), frame + s->bone[b].dof_offset,
				  w->gsrc + ((size_t)f * (size_t)s->count + (size_t)b) * 9);
			place_frame_bone(w, w->gsrc, w->psrc, frame, b, f);
		}
}

/* Tait-Bryan angles of m = R(third) R(second) R(first), axes i j k
 * distinct (the sign flips with the permutation's parity). */
static void euler(const double *m, int i, int j, int k, double out[3])
{
	int even = (j == (i + 1) % 3) && (k == (j + 1) % 3);
	double sg = even ? -1 : 1;
	out[1] = asin(fmax(-1, fmin(1, sg * m[3 * k + i])));
	out[0] = atan2(-sg * m[3 * k + j], m[3 * k + k]);
	out[2] = atan2(-sg * m[3 * j + i], m[3 * i + i]);
}

/* The bone's local motion matrix C^T (Gp^T G) C that the source's world
 * rotation g asks for under the decoded parent. */
/* The rotation (Rodrigues) taking unit vector a to unit vector b. */
static void turn_between(const double *a, const double *b, double *m)
{
	double v[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
	double c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2], k = c > -0.999999 ? 1 / (1 + c) : 0;
	double x[9] = { 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0 }, xx[9];
	mat_mul(x, x, xx);
	for (int i = 0; i < 9; i++)
		m[i] = identity[i] + x[i] + xx[i] * k;
}

/* The source's world rotation of bone b in frame f, turned the little it
 * takes to point the bone from its decoded head at the source's tip: the
 * rounding above it then does not move the joints below (a joint's
 * position is its ancestors' business, not its own rotation's). */
static void aimed(const enc_work *w, int b, long f, double *g)
{
	const skel *s = w->s;
	const skel_bone *bone = &s->bone[b];
	const double *src = w->gsrc + ((size_t)f * (size_t)s->count + (size_t)b) * 9;
	memcpy(g, src, 9 * sizeof(double));
	if (!(bone->length > 0))
		return;
	double head[6], dir[3] = { bone->direction.x, bone->direction.y, bone->direction.z }, u[3], t[3], turn[9];
	const float *v = w->src + (size_t)f * (size_t)w->dofs;
	/* the decoded head: where the decoded parent puts it (the head does
	 * not depend on the bone's own rotation) */
	int p = bone->parent;
	place(s, b, parent_of(w->gdec, s, b, f), pos_at(w->pdec, s, p, f) + 3, src, v + bone->dof_offset, head);
	const double *tip = pos_at(w->psrc, s, b, f) + 3;
	double len = 0;
	for (int i = 0; i < 3; i++) {
		t[i] = tip[i] - head[i];
		len += t[i] * t[i];
	}
	len = sqrt(len);
	if (!(len > 0))
		return;
	for (int i = 0; i < 3; i++)
		t[i] /= len;
	mat_apply(src, dir, u);
	turn_between(u, t, turn);
	mat_mul(turn, src, g);
}

static void wanted_local(const enc_work *w, int b, long f, double *m)
{
	const skel_bone *bone = &w->s->bone[b];
	double c[9], ct[9], pt[9], g[9];
	aimed(w, b, f, g);
	mat_of_quat(bone->axis_rot, c);
	mat_transpose(c, ct);
	mat_transpose(parent_of(w->gdec, w->s, b, f), pt);
	mat_mul(ct, pt, m);
	mat_mul(m, g, m);
	mat_mul(m, c, m);
}

/* Bone b's target values in frame f: the source's, or for a compensating
 * bone the angles that give the source's world rotation under the decoded
 * parent, each as near its source value as a turn allows. (Fitting the
 * nearest rotation fewer angles reach did not pay: the fits' jitter cost
 * more bits than the error they took away.) */
static void targets(const enc_work *w, int b, long f, double *t)
{
	const skel_bone *bone = &w->s->bone[b];
	const float *v = w->src + (size_t)f * (size_t)w->dofs + bone->dof_offset;
	for (int i = 0; i < bone->channel_count; i++)
		t[i] = v[i];
	if (!w->comp[b])
		return;
	double m[9], a[3];
	wanted_local(w, b, f, m);
	euler(m, bone->channel[0] - SKEL_RX, bone->channel[1] - SKEL_RX, bone->channel[2] - SKEL_RX, a);
	for (int i = 0; i < 3; i++)
		t[i] = v[i] + remainder(a[i] - v[i], 2 * 3.14159265358979323846);
}

/* Track d's grid over the targets of every frame (t: n values). */
static int quantise_track(enc_work *w, int d, const double *t)
{
	double lo = t[0];
	for (long f = 1; f < w->n; f++)
		lo = fmin(lo, t[f]);
	codec_track *tr = &w->track[d];
	tr->base = (float)lo;
	tr->step = w->step[d];
	int32_t top = 0;
	for (long f = 0; f < w->n; f++) {
		double x = tr->step > 0 ? floor((t[f] - tr->base) / tr->step + 0.5) : 0;
		if (x >= (double)(1 << CODEC_MAX_BITS))
			return -1;
		int32_t q = x > 0 ? (int32_t)x : 0;
		w->q[(size_t)f * (size_t)w->dofs + (size_t)d] = q;
		w->dec[(size_t)f * (size_t)w->dofs + (size_t)d] = codec_value(tr, q);
		top = q > top ? q : top;
	}
	int bits = 0;
	while (top >> bits)
		bits++;
	tr->bits = (uint8_t)bits;
	return 0;
}

int enc_quantise(enc_work *w, int top)
{
	const skel *s = w->s;
	for (int k = 0; k < s->count; k++) {
		int b = s->eval_order[k];
		if (!enc_above(s, top, b))
			continue;
		const skel_bone *bone = &s->bone[b];
		double t[SKEL_MAX_CHANNELS];
		for (long f = 0; f < w->n; f++) {
			targets(w, b, f, t);
			for (int i = 0; i < bone->channel_count; i++)
				w->tbuf[(size_t)i * (size_t)w->n + (size_t)f] = t[i];
		}
		for (int i = 0; i < bone->channel_count; i++)
			if (quantise_track(w, bone->dof_offset + i, w->tbuf + (size_t)i * (size_t)w->n))
				return -1;
		for (long f = 0; f < w->n; f++) {
			const float *frame = w->dec + (size_t)f * (size_t)w->dofs;
			world_rot(bone, parent_of(w->gdec, s, b, f), frame + bone->dof_offset,
				  w->gdec + ((size_t)f * (size_t)s->count + (size_t)b) * 9);
			place_frame_bone(w, w->gdec, w->pdec, frame, b, f);
		}
	}
	return 0;
}
