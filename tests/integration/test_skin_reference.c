/* Acceptance: the skinning kernels (through skin_run, so the SIMD ones when
 * built) agree with an independent double-precision implementation on the
 * generated body of CMU subject 02 over every frame of 02_01.amc, and on the
 * synthetic twist/bend scenes: LBS and DQBS within 1e-5 of the model's
 * height, fixed-point DQBS within 1e-4. The reference shares only loading
 * with app/ (ASF/AMC parsers, FK, mannequin, automatic weights, OBJ): bone
 * transforms from the contract R = G_pose G_bind^T, t = head_pose - R
 * head_bind, 3x4 LBS and dual quaternion blending are its own, in double.
 * The kernels skin_run picks (SIMD where the board builds them) also
 * agree with the portable ones on every pose: float within 1e-5 of the
 * height, fixed point bit for bit. Last, `skintool skin` writes exactly
 * the kernel's output, in the input's vertex order, with the input's
 * faces. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bind.h"
#include "bind_balance.h"
#include "mannequin.h"
#include "obj.h"
#include "skin.h"
#include "skin_compact.h"
#include "skin_kernels.h"
#include "test_diff.h"
#include "scene.h"
#include "test_parse.h"
#include "test_paths.h"

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

static void d3(vec3 v, double o[3])
{
	o[0] = v.x; o[1] = v.y; o[2] = v.z;
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
	d3(bind->head[b], hb);
	d3(pose->head[b], hp);
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

static _Alignas(SKIN_ALIGN) unsigned char block[SKIN_SOA_BYTES(SKP_MAX_VERTS)];
static skin_soa soa;
static _Alignas(SKIN_ALIGN) unsigned char compact_block[SKIN_COMPACT_BYTES(SKP_MAX_VERTS)];
static skin_compact compact;
static int16_t nrm16[3 * SKP_MAX_VERTS];
static skin_bones bones;
static rbone rbones[SKP_MAX_BONES];
static float pos[SKIN_ALGO_COUNT][3 * SKP_MAX_VERTS], nrm[SKIN_ALGO_COUNT][3 * SKP_MAX_VERTS];
static int32_t fpos[3 * SKP_MAX_VERTS], fnrm[3 * SKP_MAX_VERTS];
/* the portable kernels' results, for the SIMD ones to match */
static float spos[3 * SKP_MAX_VERTS], snrm[3 * SKP_MAX_VERTS];
static int32_t sfpos[3 * SKP_MAX_VERTS], sfnrm[3 * SKP_MAX_VERTS];

typedef struct body {
	const skel *skel;
	const skel_pose *bind;
	const mesh *mesh;
	const skin_weights *w;
	double height;
	double pos_err[SKIN_ALGO_COUNT], nrm_err[SKIN_ALGO_COUNT]; /* largest so far */
	double simd_err[SKIN_ALGO_COUNT]; /* against the portable kernel: float units, fixed LSB */
	double compact_err[2], compact_nrm_err[2]; /* compact LBS, DQBS against the float streams' */
	int lbs_collapses;   /* poses where LBS squeezes the skin to a line: its normals are noise there */
	long poses;
} body;

static void load_body(body *b)
{
	skp_error err;
	assert_true(skin_soa_bytes(b->mesh->vert_count) <= sizeof block);
	skin_soa_attach(&soa, block, b->mesh->vert_count);
	assert_int_equal(skin_soa_load(&soa, b->mesh, b->w, b->skel->count, &err), SKP_OK);
	memset(b->pos_err, 0, sizeof b->pos_err);
	memset(b->nrm_err, 0, sizeof b->nrm_err);
	memset(b->simd_err, 0, sizeof b->simd_err);
	memset(b->compact_err, 0, sizeof b->compact_err);
	memset(b->compact_nrm_err, 0, sizeof b->compact_nrm_err);
	skin_compact_attach(&compact, compact_block, b->mesh->vert_count);
	skin_compact_load(&compact, &soa);
	b->poses = 0;
}

/* skin_run's kernels against the portable ones, into b->simd_err */
static void compare_portable(body *b, int n)
{
	skin_out out = { spos, snrm, sfpos, sfnrm, NULL };
	skin_lbs_scalar(&soa, &bones, 0, n, &out);
	b->simd_err[SKIN_LBS] = fmax(b->simd_err[SKIN_LBS], fmax(test_max_diff(pos[SKIN_LBS], spos, 3 * n),
								   test_max_diff(nrm[SKIN_LBS], snrm, 3 * n)));
	skin_dqbs_scalar(&soa, &bones, 0, n, &out);
	b->simd_err[SKIN_DQBS] = fmax(b->simd_err[SKIN_DQBS], fmax(test_max_diff(pos[SKIN_DQBS], spos, 3 * n),
								     test_max_diff(nrm[SKIN_DQBS], snrm, 3 * n)));
	skin_dqbs_fixed(&soa, &bones, 0, n, &out);
	b->simd_err[SKIN_DQBS_FIXED] = fmax(b->simd_err[SKIN_DQBS_FIXED],
					    fmax(test_max_diff_i32(fpos, sfpos, 3 * n), test_max_diff_i32(fnrm, sfnrm, 3 * n)));
}

static double err3(const float *k, const double r[3])
{
	double dx = k[0] - r[0], dy = k[1] - r[1], dz = k[2] - r[2];
	return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The compact streams' LBS and DQBS against the float streams' (pos, nrm
 * of skin_run), into b->compact_err */
static void compare_compact(body *b, int n)
{
	for (int a = SKIN_LBS; a <= SKIN_DQBS; a++) {
		skin_out out = { spos, NULL, NULL, NULL, nrm16 };
		skin_run_compact((skin_algo)a, &compact, &bones, 0, n, &out);
		for (int v = 0; v < n; v++) {
			double rp[3], rn[3];
			for (int i = 0; i < 3; i++) {
				rp[i] = pos[a][3 * v + i];
				rn[i] = nrm[a][3 * v + i];
			}
			const float n3[3] = { nrm16[3 * v] / SKIN_COMPACT_NORMAL_ONE, nrm16[3 * v + 1] / SKIN_COMPACT_NORMAL_ONE,
					      nrm16[3 * v + 2] / SKIN_COMPACT_NORMAL_ONE };
			b->compact_err[a] = fmax(b->compact_err[a], err3(&spos[3 * v], rp));
			b->compact_nrm_err[a] = fmax(b->compact_nrm_err[a], err3(n3, rn));
		}
	}
}

static void run_kernels(body *b, const skel_pose *pose, int n)
{
	skin_bones_compute(&bones, b->skel, b->bind, pose);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		skin_out out = { pos[a], nrm[a], fpos, fnrm, NULL };
		skin_run((skin_algo)a, &soa, &bones, 0, n, &out);
	}
	compare_portable(b, n);
	if (b->mesh)
		compare_compact(b, n);
	for (int i = 0; i < 3 * n; i++) {
		pos[SKIN_DQBS_FIXED][i] = (float)(fpos[i] / 65536.0);
		nrm[SKIN_DQBS_FIXED][i] = (float)(fnrm[i] / 65536.0);
	}
}


static void note(body *b, int a, const float *p, const float *n, const double rp[3], const double rn[3])
{
	b->pos_err[a] = fmax(b->pos_err[a], err3(p, rp));
	b->nrm_err[a] = fmax(b->nrm_err[a], err3(n, rn));
}

static void compare_pose(body *b, const skel_pose *pose)
{
	const mesh *m = b->mesh;
	run_kernels(b, pose, m->vert_count);
	for (int i = 0; i < b->skel->count; i++)
		ref_bone(b->bind, pose, i, &rbones[i]);
	for (int v = 0; v < m->vert_count; v++) {
		double p[3], n[3], lp[3], ln[3], dp[3], dn[3];
		d3(m->pos[v], p);
		d3(m->normal[v], n);
		ref_lbs(rbones, b->w, v, p, n, lp, ln);
		ref_dqbs(rbones, b->w, v, p, n, dp, dn);
		note(b, SKIN_LBS, &pos[SKIN_LBS][3 * v], &nrm[SKIN_LBS][3 * v], lp, ln);
		note(b, SKIN_DQBS, &pos[SKIN_DQBS][3 * v], &nrm[SKIN_DQBS][3 * v], dp, dn);
		note(b, SKIN_DQBS_FIXED, &pos[SKIN_DQBS_FIXED][3 * v], &nrm[SKIN_DQBS_FIXED][3 * v], dp, dn);
	}
	b->poses++;
}

/* Positions within 1e-5 (float) / 1e-4 (fixed) of the height; normals
 * (unit vectors) within 1e-4 / 1e-3. */
static void check(const body *b, const char *what)
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
		      (double)skin_compact_position_bound(&compact), b->compact_err[SKIN_LBS],
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

static skel s02;
static skel_pose rest02;
static mesh body02;
static skin_weights w02;
static int have02;

static int setup(void **state)
{
	(void)state;
	static manq_work work;
	static bind_rig rig;
	skp_error err;
	const char *asf = test_data_path("mocap/cmu/02.asf");
	if (!asf || test_parse_asf_file(asf, &s02, &err) != SKP_OK)
		return 0;
	fk_pose(&s02, NULL, &rest02);
	if (manq_build(&s02, 0, &work, &body02, &err) != SKP_OK)
		return -1;
	bind_prepare(&rig, &s02, &rest02, NULL);
	if (bind_weights(&rig, body02.pos, body02.vert_count, &w02, NULL, &err) != SKP_OK)
		return -1;
	have02 = 1;
	return 0;
}

static double height_of(const mesh *m)
{
	float lo = m->pos[0].y, hi = lo;
	for (int v = 1; v < m->vert_count; v++) {
		lo = fminf(lo, m->pos[v].y);
		hi = fmaxf(hi, m->pos[v].y);
	}
	return hi - lo;
}

static void on_frame(const amc_frame *f, void *ctx)
{
	static skel_pose pose;
	body *b = ctx;
	fk_pose(b->skel, f->value, &pose);
	compare_pose(b, &pose);
}

static void test_cmu_walk_every_frame(void **state)
{
	(void)state;
	const char *amc = test_data_path("mocap/cmu/02_01.amc");
	if (!have02 || !amc)
		skip();
	static body b;
	b = (body){ .skel = &s02, .bind = &rest02, .mesh = &body02, .w = &w02, .height = height_of(&body02) };
	load_body(&b);
	size_t len;
	char *text = test_read_file(amc, &len);
	assert_non_null(text);
	skp_error err;
	long frames = test_stream_amc(text, len, &s02, &err, on_frame, &b);
	free(text);
	assert_int_equal(frames, 343);
	print_message("02.asf mannequin: %d vertices, %d triangles\n", body02.vert_count, body02.tri_count);
	check(&b, "02_01.amc");
}

/* ---- the synthetic scene ---- */

static void test_scenes(void **state)
{
	(void)state;
	static scene_rig sc;
	static skel_pose pose;
	static body b;
	scene_build(&sc);
	b = (body){ .skel = &sc.skel, .bind = &sc.bind, .mesh = &sc.mesh, .w = &sc.weights, .height = 2.0,
		    .lbs_collapses = 1 /* the 180-degree twist */ };
	load_body(&b);
	for (int k = 0; k < SCENE_KIND_COUNT; k++)
		for (int deg = -180; deg <= 360; deg += 15) {
			scene_pose(&sc, (scene_kind)k, (float)(deg * PI / 180), &pose);
			compare_pose(&b, &pose);
		}
	check(&b, "twist and bend scenes, -180..360 degrees");
}

/* ---- skintool skin writes the kernel's output ---- */

static void parse_obj(const char *path, mesh *out)
{
	static obj_work work;
	static text_lines tl;
	skp_mem_source src;
	skp_error err;
	size_t len;
	char *text = test_read_file(path, &len);
	assert_non_null(text);
	text_lines_init(&tl, skp_mem_reader(&src, text, len));
	skp_status rc = obj_parse(out, &work, &tl, NULL, &err);
	free(text);
	if (rc != SKP_OK)
		fail_msg("%s:%ld: %s", path, err.line, err.msg);
}

static void frame_values(const amc_frame *f, void *ctx)
{
	amc_frame *want = ctx;
	if (f->number == want->number)
		*want = *f;
}

static void sh(const char *cmd)
{
	if (system(cmd) != 0)
		fail_msg("failed: %s", cmd);
}

static void check_written(const mesh *in, const mesh *out, skin_algo a, double height)
{
	assert_int_equal(out->vert_count, in->vert_count);
	assert_int_equal(out->tri_count, in->tri_count);
	assert_memory_equal(out->tri, in->tri, sizeof in->tri[0] * (size_t)in->tri_count);
	double perr = 0, nerr = 0;
	for (int v = 0; v < in->vert_count; v++) {
		double p[3], n[3];
		const float *kn = &nrm[a][3 * v];
		float unit[3];   /* the OBJ reader normalises vn; fixed point is unit to 2^-16 */
		float len = sqrtf(kn[0] * kn[0] + kn[1] * kn[1] + kn[2] * kn[2]);
		for (int k = 0; k < 3; k++)
			unit[k] = kn[k] / len;
		d3(out->pos[v], p);
		d3(out->normal[v], n);
		perr = fmax(perr, err3(&pos[a][3 * v], p));
		nerr = fmax(nerr, err3(unit, n));
	}
	print_message("skintool skin --algo %s: %d vertices, %d faces as given; max difference from the kernel: position %.3g, normal %.3g\n",
		      skin_algo_name(a), out->vert_count, out->tri_count, perr, nerr);
	assert_true(perr <= 1e-7 * height); /* %.9g round-trips a float */
	assert_true(nerr < 1e-5);           /* normals are written with %.6g */
}

static void test_skintool_skin_output(void **state)
{
	(void)state;
	const char *asf = test_data_path("mocap/cmu/02.asf"), *amc = test_data_path("mocap/cmu/02_01.amc");
	if (!have02 || !amc)
		skip();
	static mesh in, out;
	static skin_weights w;
	static bind_rig rig;
	static bind_balance_work balance;
	static amc_frame f;
	static skel_pose pose;
	char dir[] = "/tmp/skp_skin_XXXXXX", cmd[4096], body_obj[256], out_obj[256];
	skp_error err;
	assert_non_null(mkdtemp(dir));
	snprintf(body_obj, sizeof body_obj, "%s/body.obj", dir);
	snprintf(out_obj, sizeof out_obj, "%s/out.obj", dir);
	snprintf(cmd, sizeof cmd, "%s mannequin %s -o %s >/dev/null", test_tool_path("skintool"), asf, body_obj);
	sh(cmd);
	/* the tool's inputs, loaded and bound as it does */
	parse_obj(body_obj, &in);
	bind_prepare(&rig, &s02, &rest02, NULL);
	assert_int_equal(bind_weights(&rig, in.pos, in.vert_count, &w, NULL, &err), SKP_OK);
	assert_int_equal(bind_balance(&s02, &rest02, in.pos, in.vert_count, (const uint32_t (*)[3])in.tri,
				      in.tri_count, &w, &balance, NULL, &err), SKP_OK);
	skin_soa_attach(&soa, block, in.vert_count);
	assert_int_equal(skin_soa_load(&soa, &in, &w, s02.count, &err), SKP_OK);
	size_t len;
	char *text = test_read_file(amc, &len);
	f.number = 100;
	test_stream_amc(text, len, &s02, &err, frame_values, &f);
	free(text);
	fk_pose(&s02, f.value, &pose);
	body tool = { .skel = &s02, .bind = &rest02 };
	run_kernels(&tool, &pose, in.vert_count);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		snprintf(cmd, sizeof cmd, "%s skin %s %s %s --frame 100 --algo %s -o %s", test_tool_path("skintool"),
			 asf, amc, body_obj, skin_algo_name((skin_algo)a), out_obj);
		sh(cmd);
		parse_obj(out_obj, &out);
		check_written(&in, &out, (skin_algo)a, height_of(&in));
	}
	unlink(body_obj);
	unlink(out_obj);
	rmdir(dir);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cmu_walk_every_frame),
		cmocka_unit_test(test_scenes),
		cmocka_unit_test(test_skintool_skin_output),
	};
	return cmocka_run_group_tests_name("skin_reference", tests, setup, NULL);
}
