#include "rig_align.h"

#include <math.h>
#include <string.h>

#define SNAP_DEG 20.0

/* Eigen decomposition of a symmetric 4x4 matrix (cyclic Jacobi): a is
 * destroyed, its diagonal left holding the eigenvalues, v the vectors as
 * columns. */
static void jacobi4(double a[4][4], double v[4][4])
{
	memset(v, 0, 16 * sizeof(double));
	for (int i = 0; i < 4; i++)
		v[i][i] = 1.0;
	for (int sweep = 0; sweep < 50; sweep++) {
		double off = 0.0;
		for (int p = 0; p < 4; p++)
			for (int q = p + 1; q < 4; q++)
				off += a[p][q] * a[p][q];
		if (off < 1e-30)
			return;
		for (int p = 0; p < 4; p++)
			for (int q = p + 1; q < 4; q++) {
				if (fabs(a[p][q]) < 1e-300)
					continue;
				double th = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
				double t = (th >= 0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
				double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
				for (int k = 0; k < 4; k++) {
					double akp = a[k][p], akq = a[k][q];
					a[k][p] = c * akp - s * akq;
					a[k][q] = s * akp + c * akq;
				}
				for (int k = 0; k < 4; k++) {
					double apk = a[p][k], aqk = a[q][k];
					a[p][k] = c * apk - s * aqk;
					a[q][k] = s * apk + c * aqk;
				}
				for (int k = 0; k < 4; k++) {
					double vkp = v[k][p], vkq = v[k][q];
					v[k][p] = c * vkp - s * vkq;
					v[k][q] = s * vkp + c * vkq;
				}
			}
	}
}

/* Horn's N from S[i][j] = sum from_i * to_j (centred). */
static quat horn_rotation(double S[3][3])
{
	double N[4][4] = {
		{ S[0][0] + S[1][1] + S[2][2], S[1][2] - S[2][1], S[2][0] - S[0][2], S[0][1] - S[1][0] },
		{ S[1][2] - S[2][1], S[0][0] - S[1][1] - S[2][2], S[0][1] + S[1][0], S[2][0] + S[0][2] },
		{ S[2][0] - S[0][2], S[0][1] + S[1][0], -S[0][0] + S[1][1] - S[2][2], S[1][2] + S[2][1] },
		{ S[0][1] - S[1][0], S[2][0] + S[0][2], S[1][2] + S[2][1], -S[0][0] - S[1][1] + S[2][2] },
	};
	double V[4][4];
	jacobi4(N, V);
	int best = 0;
	for (int k = 1; k < 4; k++)
		if (N[k][k] > N[best][best])
			best = k;
	quat q = { (float)V[0][best], (float)V[1][best], (float)V[2][best], (float)V[3][best] };
	return quat_normalize(q);
}

static float angle_deg(quat q)
{
	double w = fabs((double)q.w);
	return (float)(2.0 * acos(w > 1.0 ? 1.0 : w) * 180.0 / M_PI);
}

/* The nearest of the 24 turns by quarter turns about the axes. */
static quat nearest_axis_turn(quat q)
{
	float r[3][3], best_m[3][3];
	double best = -4.0;
	quat_to_mat3(q, r);
	static const int perm[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
	for (int p = 0; p < 6; p++)
		for (int signs = 0; signs < 8; signs++) {
			float m[3][3] = { { 0 } };
			for (int i = 0; i < 3; i++)
				m[i][perm[p][i]] = (signs >> i) & 1 ? -1.0f : 1.0f;
			double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
				     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
				     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
			double tr = 0.0;
			for (int i = 0; i < 3; i++)
				for (int j = 0; j < 3; j++)
					tr += m[i][j] * r[i][j];
			if (det > 0.0 && tr > best) {
				best = tr;
				memcpy(best_m, m, sizeof m);
			}
		}
	return quat_normalize(quat_from_mat3(best_m));
}

static vec3 centroid(const vec3 *p, int n)
{
	vec3 c = vec3_make(0.0f, 0.0f, 0.0f);
	for (int i = 0; i < n; i++)
		c = vec3_add(c, p[i]);
	return vec3_scale(c, 1.0f / (float)n);
}

/* Scale, offset and residual for a given rotation. */
static void fit_rest(const vec3 *from, const vec3 *to, int n, vec3 cf, vec3 ct, rig_align *out)
{
	double num = 0.0, den = 0.0, res = 0.0;
	for (int i = 0; i < n; i++) {
		vec3 a = quat_rotate(out->rot, vec3_sub(from[i], cf)), b = vec3_sub(to[i], ct);
		num += vec3_dot(a, b);
		den += vec3_dot(a, a);
	}
	out->scale = (float)(num / den);
	out->offset = vec3_sub(ct, vec3_scale(quat_rotate(out->rot, cf), out->scale));
	for (int i = 0; i < n; i++) {
		vec3 d = vec3_sub(rig_align_point(out, from[i]), to[i]);
		res += vec3_dot(d, d);
	}
	out->rms = (float)sqrt(res / n);
	out->turn_deg = angle_deg(out->rot);
}

vec3 rig_align_point(const rig_align *a, vec3 p)
{
	return vec3_add(vec3_scale(quat_rotate(a->rot, p), a->scale), a->offset);
}

skp_status rig_align_fit(const vec3 *from, const vec3 *to, int n, rig_align *out, skp_error *err)
{
	memset(out, 0, sizeof *out);
	if (n < 3)
		return skp_fail(err, SKP_ERR_RANGE, 0, "%d matching joints, at least 3 needed", n);
	vec3 cf = centroid(from, n), ct = centroid(to, n);
	double S[3][3] = { { 0 } }, spread = 0.0;
	for (int i = 0; i < n; i++) {
		vec3 a = vec3_sub(from[i], cf), b = vec3_sub(to[i], ct);
		float av[3] = { a.x, a.y, a.z }, bv[3] = { b.x, b.y, b.z };
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
				S[r][c] += (double)av[r] * bv[c];
		spread += vec3_dot(a, a);
	}
	if (!(spread > 0.0) || !isfinite(spread))
		return skp_fail(err, SKP_ERR_RANGE, 0, "the matching joints are all at one place");
	out->rot = horn_rotation(S);
	quat snap = nearest_axis_turn(out->rot);
	out->snap_deg = angle_deg(quat_mul(snap, quat_conj(out->rot)));
	if (out->snap_deg <= SNAP_DEG) {
		out->rot = snap;
		out->snapped = 1;
	}
	fit_rest(from, to, n, cf, ct, out);
	if (!(out->scale > 0.0f) || !isfinite(out->scale))
		return skp_fail(err, SKP_ERR_RANGE, 0, "the matching joints give no scale (all on a line?)");
	return SKP_OK;
}
