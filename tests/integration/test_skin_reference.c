/* Acceptance: the skinning kernels (through skin_run, so the SIMD ones when
 * built) agree with an independent double-precision implementation on the
 * generated body of CMU subject 02 over every frame of 02_01.amc, and on the
 * synthetic twist/bend scenes: LBS and DQBS within 1e-5 of the model's
 * height, fixed-point DQBS within 1e-4. The reference shares only loading
 * with app/ (ASF/AMC parsers, FK, mannequin, automatic weights): bone
 * transforms from the contract R = G_pose G_bind^T, t = head_pose - R
 * head_bind, 3x4 LBS and dual quaternion blending are its own, in double.
 * The kernels skin_run picks (SIMD where the board builds them) also
 * agree with the portable ones on every pose: float within 1e-5 of the
 * height, fixed point bit for bit; the compact streams the float ones'.
 * `skintool skin`'s output: test_skin_reference_tool.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "skin.h"
#include "skin_compact.h"
#include "scene.h"
#include "test_parse.h"
#include "test_paths.h"
#include "test_skinref.h"

#define PI 3.14159265358979323846

/* ---- the reference, in double ---- */

typedef struct rbone {
	double r[3][3], t[3];   /* p' = r p + t */
	double q[4], d[4];      /* unit dual quaternion (w x y z): real, dual */
} rbone;

static void q_of(quat f, double q[4])
{
	double n = sqrt((double)f.w * f.w + (double)f.x * f.x + (double)f.y * f.y + (double)f.z * f.z);
	q[0] = f.w / n; q[1] = f.x / n; q[2] = f.y / n; q[3] = f.z / n;
}

static void q_mul(const double a[4], const double b[4], double o[4])
{
	o[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
	o[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
	o[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
	o[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

static void q_to_m(const double q[4], double m[3][3])
{
	double w = q[0], x = q[1], y = q[2], z = q[3];
	m[0][0] = 1 - 2 * (y * y + z * z); m[0][1] = 2 * (x * y - w * z); m[0][2] = 2 * (x * z + w * y);
	m[1][0] = 2 * (x * y + w * z); m[1][1] = 1 - 2 * (x * x + z * z); m[1][2] = 2 * (y * z - w * x);
	m[2][0] = 2 * (x * z - w * y); m[2][1] = 2 * (y * z + w * x); m[2][2] = 1 - 2 * (x * x + y * y);
}

static void m_apply(const double m[3][3], const double v[3], double o[3])
{
	for (int i = 0; i < 3; i++)
		o[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

static void ref_bone(const skel_pose *bind, const skel_pose *pose, int b, rbone *o)
{
	double qb[4], qp[4], gb[3][3], gp[3][3], hb[3], hp[3], rh[3];
	q_of(bind->rot[b], qb);
	q_of(pose->rot[b], qp);
	q_to_m(qb, gb);
	q_to_m(qp, gp);
	for (int i = 0; i < 3; i++)   /* R = G_pose G_bind^T */
		for (int j = 0; j < 3; j++)
			o->r[i][j] = gp[i][0] * gb[j][0] + gp[i][1] * gb[j][1] + gp[i][2] * gb[j][2];
	skinref_d3(bind->head[b], hb);
	skinref_d3(pose->head[b], hp);
	m_apply(o->r, hb, rh);
	for (int i = 0; i < 3; i++)
		o->t[i] = hp[i] - rh[i];
	double cb[4] = { qb[0], -qb[1], -qb[2], -qb[3] }, t[4] = { 0, o->t[0], o->t[1], o->t[2] };
	q_mul(qp, cb, o->q);
	q_mul(t, o->q, o->d);
	for (int i = 0; i < 4; i++)
		o->d[i] *= 0.5;
}

static void normalize3(double v[3])
{
	double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
	if (n > 0)
		for (int i = 0; i < 3; i++)
			v[i] /= n;
}

static const rbone identity = { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, { 0, 0, 0 },
				{ 1, 0, 0, 0 }, { 0, 0, 0, 0 } };

/* Influences of v; none: the identity with weight 1. */
static int influences(const skin_weights *w, int v, const rbone *bones, const rbone **b, double *wt)
{
	int n = w->count[v];
	for (int k = 0; k < n; k++) {
		b[k] = &bones[w->bone[v][k]];
		wt[k] = w->weight[v][k];
	}
	if (n == 0) {
		b[0] = &identity;
		wt[0] = 1;
		n = 1;
	}
	return n;
}

static void ref_lbs(const rbone *bones, const skin_weights *w, int v, const double p[3],
		    const double n[3], double op[3], double on[3])
{
	const rbone *b[SKP_MAX_INFLUENCES];
	double wt[SKP_MAX_INFLUENCES], m[3][4] = { { 0 } };
	int cnt = influences(w, v, bones, b, wt);
	for (int k = 0; k < cnt; k++)
		for (int i = 0; i < 3; i++) {
			for (int j = 0; j < 3; j++)
				m[i][j] += wt[k] * b[k]->r[i][j];
			m[i][3] += wt[k] * b[k]->t[i];
		}
	for (int i = 0; i < 3; i++) {
		op[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
		on[i] = m[i][0] * n[0] + m[i][1] * n[1] + m[i][2] * n[2];
	}
	normalize3(on);
}

static void ref_dqbs(const rbone *bones, const skin_weights *w, int v, const double p[3],
		     const double n[3], double op[3], double on[3])
{
	const rbone *b[SKP_MAX_INFLUENCES];
	double wt[SKP_MAX_INFLUENCES], q[4] = { 0 }, d[4] = { 0 };
	int cnt = influences(w, v, bones, b, wt), pivot = 0;
	for (int k = 1; k < cnt; k++)
		if (wt[k] > wt[pivot])
			pivot = k;
	for (int k = 0; k < cnt; k++) {
		const double *pq = b[pivot]->q, *bq = b[k]->q;
		double dot = pq[0] * bq[0] + pq[1] * bq[1] + pq[2] * bq[2] + pq[3] * bq[3];
		double s = dot < 0 ? -wt[k] : wt[k];
		for (int i = 0; i < 4; i++) {
			q[i] += s * bq[i];
			d[i] += s * b[k]->d[i];
		}
	}
	double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
	for (int i = 0; i < 4; i++) {
		q[i] /= len;
		d[i] /= len;
	}
	double m[3][3], rp[3], cq[4] = { q[0], -q[1], -q[2], -q[3] }, t[4];
	q_to_m(q, m);
	q_mul(d, cq, t);   /* translation: 2 dual conj(real), vector part */
	m_apply(m, p, rp);
	for (int i = 0; i < 3; i++)
		op[i] = rp[i] + 2 * t[i + 1];
	m_apply(m, n, on);
}

/* ---- comparing the kernels with it ---- */


static skinref_kernels kern;
static rbone rbones[SKP_MAX_BONES];

static void load_body(skinref_body *b)
{
	skp_error err;
	assert_true(skin_soa_bytes(b->mesh->vert_count) <= sizeof kern.block);
	skin_soa_attach(&kern.soa, kern.block, b->mesh->vert_count);
	assert_int_equal(skin_soa_load(&kern.soa, b->mesh, b->w, b->skel->count, &err), SKP_OK);
	memset(b->pos_err, 0, sizeof b->pos_err);
	memset(b->nrm_err, 0, sizeof b->nrm_err);
	memset(b->simd_err, 0, sizeof b->simd_err);
	memset(b->compact_err, 0, sizeof b->compact_err);
	memset(b->compact_nrm_err, 0, sizeof b->compact_nrm_err);
	skin_compact_attach(&kern.compact, kern.compact_block, b->mesh->vert_count);
	skin_compact_load(&kern.compact, &kern.soa);
	b->poses = 0;
}

static void note(skinref_body *b, int a, const float *p, const float *n, const double rp[3], const double rn[3])
{
	b->pos_err[a] = fmax(b->pos_err[a], skinref_err3(p, rp));
	b->nrm_err[a] = fmax(b->nrm_err[a], skinref_err3(n, rn));
}

static void compare_pose(skinref_body *b, const skel_pose *pose)
{
	const mesh *m = b->mesh;
	skinref_run_kernels(&kern, b, pose, m->vert_count);
	for (int i = 0; i < b->skel->count; i++)
		ref_bone(b->bind, pose, i, &rbones[i]);
	for (int v = 0; v < m->vert_count; v++) {
		double p[3], n[3], lp[3], ln[3], dp[3], dn[3];
		skinref_d3(m->pos[v], p);
		skinref_d3(m->normal[v], n);
		ref_lbs(rbones, b->w, v, p, n, lp, ln);
		ref_dqbs(rbones, b->w, v, p, n, dp, dn);
		note(b, SKIN_LBS, &kern.pos[SKIN_LBS][3 * v], &kern.nrm[SKIN_LBS][3 * v], lp, ln);
		note(b, SKIN_DQBS, &kern.pos[SKIN_DQBS][3 * v], &kern.nrm[SKIN_DQBS][3 * v], dp, dn);
		note(b, SKIN_DQBS_FIXED, &kern.pos[SKIN_DQBS_FIXED][3 * v], &kern.nrm[SKIN_DQBS_FIXED][3 * v], dp, dn);
	}
	b->poses++;
}

/* Positions within 1e-5 (float) / 1e-4 (fixed) of the height; normals
 * (unit vectors) within 1e-4 / 1e-3. */
static void check(const skinref_body *b, const char *what)
{
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		double rel = b->pos_err[a] / b->height;
		print_message("%s, %ld poses, %-10s max position error %.3g (%.3g of height %.4g), max normal error %.3g\n",
			      what, b->poses, skin_algo_name((skin_algo)a), b->pos_err[a], rel, b->height,
			      b->nrm_err[a]);
	}
	print_message("%s: %s kernels against the portable ones: LBS %.3g, DQBS %.3g (%.3g, %.3g of height), "
		      "fixed DQBS %.0f LSB\n", what, skin_simd_name(), b->simd_err[SKIN_LBS], b->simd_err[SKIN_DQBS],
		      b->simd_err[SKIN_LBS] / b->height, b->simd_err[SKIN_DQBS] / b->height,
		      b->simd_err[SKIN_DQBS_FIXED]);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		double tol = a == SKIN_DQBS_FIXED ? 1e-4 : 1e-5;
		assert_true(b->pos_err[a] / b->height < tol);
		assert_true(b->nrm_err[a] < 10 * tol);
	}
	print_message("%s: compact streams (positions within %.3g by quantisation alone): LBS %.3g (%.3g of height), "
		      "DQBS %.3g (%.3g); normals LBS %.3g, DQBS %.3g\n", what,
		      (double)skin_compact_position_bound(&kern.compact), b->compact_err[SKIN_LBS],
		      b->compact_err[SKIN_LBS] / b->height, b->compact_err[SKIN_DQBS], b->compact_err[SKIN_DQBS] / b->height,
		      b->compact_nrm_err[SKIN_LBS], b->compact_nrm_err[SKIN_DQBS]);
	for (int a = SKIN_LBS; a <= SKIN_DQBS; a++) {
		assert_true(b->compact_err[a] / b->height <= 1e-4);
		assert_true(b->compact_nrm_err[a] <= 2e-4 || (a == SKIN_LBS && b->lbs_collapses));
	}
	assert_true(b->simd_err[SKIN_LBS] / b->height < 1e-5);
	assert_true(b->simd_err[SKIN_DQBS] / b->height < 1e-5);
	assert_true(b->simd_err[SKIN_DQBS_FIXED] == 0);
}

/* ---- the CMU body ---- */

static skinref_cmu02 cmu;

static int setup(void **state)
{
	(void)state;
	return skinref_cmu02_setup(&cmu);
}

/* Every frame natively; under the sanitizers or qemu-user (the arm64
 * build's arithmetic, checked in CI's rpi4 tier) every 16th, 22 frames
 * across the walk (every 4th: 13 s in all under qemu): the native run
 * covers the rest. */
static void on_frame(const amc_frame *f, void *ctx)
{
	static skel_pose pose;
	static long seen;
	skinref_body *b = ctx;
	if (test_slow() && seen++ % 16)
		return;
	fk_pose(b->skel, f->value, &pose);
	compare_pose(b, &pose);
}

static void test_cmu_walk_every_frame(void **state)
{
	(void)state;
	const char *amc = test_data_path("mocap/cmu/02_01.amc");
	if (!cmu.have || !amc)
		skip();
	static skinref_body b;
	b = (skinref_body){ .skel = &cmu.skel, .bind = &cmu.rest, .mesh = &cmu.body, .w = &cmu.w,
			    .height = skinref_height_of(&cmu.body) };
	load_body(&b);
	size_t len;
	char *text = test_read_file(amc, &len);
	assert_non_null(text);
	skp_error err;
	long frames = test_stream_amc(text, len, &cmu.skel, &err, on_frame, &b);
	free(text);
	assert_int_equal(frames, 343);
	print_message("02.asf mannequin: %d vertices, %d triangles\n", cmu.body.vert_count, cmu.body.tri_count);
	check(&b, "02_01.amc");
}

/* ---- the synthetic scene ---- */

static void test_scenes(void **state)
{
	(void)state;
	static scene_rig sc;
	static skel_pose pose;
	static skinref_body b;
	scene_build(&sc);
	b = (skinref_body){ .skel = &sc.skel, .bind = &sc.bind, .mesh = &sc.mesh, .w = &sc.weights, .height = 2.0,
		    .lbs_collapses = 1 /* the 180-degree twist */ };
	load_body(&b);
	for (int k = 0; k < SCENE_KIND_COUNT; k++)
		for (int deg = -180; deg <= 360; deg += 15) {
			scene_pose(&sc, (scene_kind)k, (float)(deg * PI / 180), &pose);
			compare_pose(&b, &pose);
		}
	check(&b, "twist and bend scenes, -180..360 degrees");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cmu_walk_every_frame),
		cmocka_unit_test(test_scenes),
	};
	return cmocka_run_group_tests_name("skin_reference", tests, setup, NULL);
}
