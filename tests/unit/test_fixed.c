/* Fixed-point quaternion and DQ skinning (fixed.h) against double-precision
 * references written here: quaternion products and rotations (any int32
 * vector, saturating), DQ products, the blend and its normalisation. The
 * fixed inputs are converted to double exactly, so the measured errors are
 * those of the integer arithmetic alone; one test also goes end to end
 * from float dqs through fixed_convert.h. Targets: below 1e-6 for unit
 * components, below 1e-3 model units for positions with |p| < 1000 and
 * |t| < 1000. The measured maxima are printed. The scalar operations and
 * conversions: test_fixed_scalar.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>

#include "dq.h"
#include "fixed.h"
#include "fixed_convert.h"
#include "test_fx.h"
#include "test_rng.h"

#define N_RANDOM 5000
#define PI 3.14159265358979323846
#define Q30 1073741824.0
#define POS ((double)FX_POS_ONE)

/* ---- double references ---------------------------------------------------- */

static double posd(int32_t v) { return v / POS; }

typedef struct dquat { double c[4]; } dquat;   /* w x y z */

static dquat dquat_q30(fx_quat q)
{
	dquat r = { { test_fx_q30d(q.w), test_fx_q30d(q.x), test_fx_q30d(q.y), test_fx_q30d(q.z) } };
	return r;
}

static dquat dquat_pos(fx_quat q) { dquat r = { { posd(q.w), posd(q.x), posd(q.y), posd(q.z) } }; return r; }

static dquat dquat_mul(dquat a, dquat b)
{
	const double *p = a.c, *q = b.c;
	dquat r = { {
		p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
		p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
		p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
		p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0],
	} };
	return r;
}

static double dquat_norm(dquat q)
{
	return sqrt(q.c[0] * q.c[0] + q.c[1] * q.c[1] + q.c[2] * q.c[2] + q.c[3] * q.c[3]);
}

/* Rotation matrix of q / |q|. */
static void dquat_mat(dquat q, double m[3][3])
{
	double n = dquat_norm(q);
	double w = q.c[0] / n, x = q.c[1] / n, y = q.c[2] / n, z = q.c[3] / n;

	m[0][0] = 1 - 2 * (y * y + z * z); m[0][1] = 2 * (x * y - w * z); m[0][2] = 2 * (x * z + w * y);
	m[1][0] = 2 * (x * y + w * z); m[1][1] = 1 - 2 * (x * x + z * z); m[1][2] = 2 * (y * z - w * x);
	m[2][0] = 2 * (x * z - w * y); m[2][1] = 2 * (y * z + w * x); m[2][2] = 1 - 2 * (x * x + y * y);
}

static void dmat_apply(const double m[3][3], const double v[3], double r[3])
{
	for (int i = 0; i < 3; i++)
		r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

/* DLB reference: R from b0 / |b0|, t = 2 vec(be conj(b0)) / |b0|^2. */
typedef struct dxf { double r[3][3], t[3]; } dxf;

static dxf dlb_ref(const dquat *real, const dquat *dual, const double *w, int n, dquat pivot)
{
	dquat b0 = { { 0 } }, be = { { 0 } };
	dxf x;

	for (int i = 0; i < n; i++) {
		double dot = 0;
		for (int k = 0; k < 4; k++)
			dot += real[i].c[k] * pivot.c[k];
		double s = dot < 0 ? -w[i] : w[i];
		for (int k = 0; k < 4; k++) {
			b0.c[k] += s * real[i].c[k];
			be.c[k] += s * dual[i].c[k];
		}
	}
	dquat conj = { { b0.c[0], -b0.c[1], -b0.c[2], -b0.c[3] } };
	dquat t = dquat_mul(be, conj);
	double n2 = dquat_norm(b0) * dquat_norm(b0);
	dquat_mat(b0, x.r);
	for (int k = 0; k < 3; k++)
		x.t[k] = 2 * t.c[k + 1] / n2;
	return x;
}

/* ---- random inputs ------------------------------------------------------------ */

static dquat rand_unit(void)
{
	for (;;) {
		dquat q = { { test_rng_range(-1, 1), test_rng_range(-1, 1), test_rng_range(-1, 1), test_rng_range(-1, 1) } };
		double n = dquat_norm(q);
		if (n > 0.1 && n <= 1.0) {
			for (int k = 0; k < 4; k++)
				q.c[k] /= n;
			return q;
		}
	}
}

static fx_quat fx_unit(dquat q)
{
	fx_quat r = { test_fx_raw(q.c[0], Q30), test_fx_raw(q.c[1], Q30), test_fx_raw(q.c[2], Q30), test_fx_raw(q.c[3], Q30) };
	return r;
}

static fx_vec3 rand_pos(double r)
{
	fx_vec3 v = { test_fx_raw(test_rng_range(-r, r), POS), test_fx_raw(test_rng_range(-r, r), POS),
		      test_fx_raw(test_rng_range(-r, r), POS) };
	return v;
}

static fx_vec3 rand_normal(void)
{
	dquat q = rand_unit();
	double n = sqrt(q.c[1] * q.c[1] + q.c[2] * q.c[2] + q.c[3] * q.c[3]);
	fx_vec3 v = { test_fx_raw(q.c[1] / n, Q30), test_fx_raw(q.c[2] / n, Q30), test_fx_raw(q.c[3] / n, Q30) };
	return v;
}

/* Random 1..4 weights summing to exactly 32768. */
static int rand_weights(fx_w15 *w)
{
	int n = 1 + (int)(test_rng_u32() % 4);
	float f[4];

	for (int i = 0; i < n; i++)
		f[i] = (float)test_rng_range(0.01, 1);
	assert_int_equal(fx_weights_from_float(f, w, n), SKP_OK);
	return n;
}

/* ---- error tracking (test_fx.h) ------------------------------------------------- */

enum { E_QMUL, E_ROT_N, E_ROT_P, E_DQMUL_R, E_DQMUL_P, E_BLEND_R, E_BLEND_P, E_BLEND_N, E_E2E_P, E_COUNT };
_Static_assert(E_COUNT <= TEST_FX_SLOTS, "more slots than test_fx keeps");

/* ---- tests ---------------------------------------------------------------------- */

static void test_quat_mul(void **state)
{
	(void)state;
	for (int i = 0; i < N_RANDOM; i++) {
		fx_quat a = fx_unit(rand_unit()), b = fx_unit(rand_unit());
		fx_quat r = fx_quat_mul(a, b);
		dquat want = dquat_mul(dquat_q30(a), dquat_q30(b)), got = dquat_q30(r);
		for (int k = 0; k < 4; k++)
			test_fx_track(E_QMUL, got.c[k], want.c[k], 1e-9, "fx_quat_mul");
		/* unit times a Q16.16 quaternion: result in Q16.16 */
		fx_quat d = { test_fx_raw(test_rng_range(-500, 500), POS), test_fx_raw(test_rng_range(-500, 500), POS),
			      test_fx_raw(test_rng_range(-500, 500), POS), test_fx_raw(test_rng_range(-500, 500), POS) };
		dquat wd = dquat_mul(dquat_q30(a), dquat_pos(d)), gd = dquat_pos(fx_quat_mul(a, d));
		for (int k = 0; k < 4; k++)
			test_fx_track(E_QMUL, gd.c[k] * 1e-6, wd.c[k] * 1e-6, 1e-9, "fx_quat_mul mixed (scaled)");
		/* exact dot product */
		dquat da = dquat_q30(a), db = dquat_q30(b);
		double dot = 0;
		for (int k = 0; k < 4; k++)
			dot += da.c[k] * db.c[k];
		test_fx_track(E_QMUL, (double)fx_quat_dot(a, b) / (Q30 * Q30), dot, 1e-15, "fx_quat_dot");
	}
	print_message("fx_quat_mul: max error %.3g (unit components)\n", test_fx_max_err[E_QMUL]);
}

static void test_rotate(void **state)
{
	(void)state;
	for (int i = 0; i < N_RANDOM; i++) {
		fx_quat q = fx_unit(rand_unit());
		double m[3][3], want[3];
		dquat_mat(dquat_q30(q), m);

		fx_vec3 n = rand_normal(), rn = fx_quat_rotate(q, n);
		double dn[3] = { test_fx_q30d(n.x), test_fx_q30d(n.y), test_fx_q30d(n.z) };
		dmat_apply(m, dn, want);
		test_fx_track(E_ROT_N, test_fx_q30d(rn.x), want[0], 1e-8, "rotate normal x");
		test_fx_track(E_ROT_N, test_fx_q30d(rn.y), want[1], 1e-8, "rotate normal y");
		test_fx_track(E_ROT_N, test_fx_q30d(rn.z), want[2], 1e-8, "rotate normal z");

		fx_vec3 p = rand_pos(1000), rp = fx_quat_rotate(q, p);
		double dp[3] = { posd(p.x), posd(p.y), posd(p.z) };
		dmat_apply(m, dp, want);
		test_fx_track(E_ROT_P, posd(rp.x), want[0], 1e-4, "rotate point x");
		test_fx_track(E_ROT_P, posd(rp.y), want[1], 1e-4, "rotate point y");
		test_fx_track(E_ROT_P, posd(rp.z), want[2], 1e-4, "rotate point z");
	}
	print_message("fx_quat_rotate: max error %.3g (normals), %.3g units (points |p| < 1000)\n",
		      test_fx_max_err[E_ROT_N], test_fx_max_err[E_ROT_P]);
}

/* Any int32 vector, even |v| > 2^31: no overflow inside (UBSan would trap
 * under SANITIZE=1), results saturate at the int32 range. */
static void test_rotate_extremes(void **state)
{
	(void)state;
	for (int i = 0; i < N_RANDOM; i++) {
		fx_quat q = fx_unit(rand_unit());
		fx_vec3 v = { (int32_t)test_rng_u32(), (int32_t)test_rng_u32(), (int32_t)test_rng_u32() };
		if (i % 7 == 0)
			v.x = v.y = v.z = (i & 8) ? INT32_MAX : INT32_MIN;
		double m[3][3], dv[3] = { v.x, v.y, v.z }, want[3];
		dquat_mat(dquat_q30(q), m);
		dmat_apply(m, dv, want);
		fx_vec3 r = fx_quat_rotate(q, v);
		int32_t got[3] = { r.x, r.y, r.z };
		for (int k = 0; k < 3; k++) {
			double w = fmin(fmax(want[k], INT32_MIN), INT32_MAX);
			/* a few LSB plus the Q30 rounding of q times |v| */
			if (fabs(got[k] - w) > 8)
				fail_msg("extreme rotate: got %d want %.1f", got[k], w);
		}
		/* unit real, arbitrary dual: translation sums cannot overflow */
		fx_dq d = { q, { (int32_t)test_rng_u32(), (int32_t)test_rng_u32(), (int32_t)test_rng_u32(), (int32_t)test_rng_u32() } };
		(void)fx_dq_translation(&d);
		(void)fx_quat_mul(q, d.dual);
	}
}

/* Bone with a rotation and |t| < tmax, built in fixed from exact Q30/Q16. */
static fx_dq rand_fx_bone(double tmax)
{
	return fx_dq_from_quat_trans(fx_unit(rand_unit()), rand_pos(tmax));
}

static void test_dq_mul(void **state)
{
	(void)state;
	for (int i = 0; i < N_RANDOM; i++) {
		fx_quat qa = fx_unit(rand_unit()), qb = fx_unit(rand_unit());
		fx_vec3 ta = rand_pos(1000), tb = rand_pos(1000);
		fx_dq a = fx_dq_from_quat_trans(qa, ta), b = fx_dq_from_quat_trans(qb, tb);

		/* from_quat_trans + translation round trip */
		fx_vec3 t2 = fx_dq_translation(&a);
		test_fx_track(E_DQMUL_P, posd(t2.x), posd(ta.x), 1e-3, "fx_dq_translation x");
		test_fx_track(E_DQMUL_P, posd(t2.y), posd(ta.y), 1e-3, "fx_dq_translation y");
		test_fx_track(E_DQMUL_P, posd(t2.z), posd(ta.z), 1e-3, "fx_dq_translation z");

		/* reference: p -> Ra (Rb p + tb) + ta in double */
		fx_dq ab = fx_dq_mul(&a, &b);
		dquat want = dquat_mul(dquat_q30(qa), dquat_q30(qb)), got = dquat_q30(ab.real);
		for (int k = 0; k < 4; k++)
			test_fx_track(E_DQMUL_R, got.c[k], want.c[k], 1e-6, "fx_dq_mul real");
		double ma[3][3], mb[3][3], dtb[3] = { posd(tb.x), posd(tb.y), posd(tb.z) };
		dquat_mat(dquat_q30(qa), ma);
		dquat_mat(dquat_q30(qb), mb);
		fx_vec3 p = rand_pos(1000);
		double dp[3] = { posd(p.x), posd(p.y), posd(p.z) }, x[3], y[3];
		dmat_apply(mb, dp, x);
		for (int k = 0; k < 3; k++)
			x[k] += dtb[k];
		dmat_apply(ma, x, y);
		y[0] += posd(ta.x); y[1] += posd(ta.y); y[2] += posd(ta.z);
		fx_vec3 r = fx_dq_transform_point(&ab, p);
		test_fx_track(E_DQMUL_P, posd(r.x), y[0], 1e-3, "fx_dq_mul point x");
		test_fx_track(E_DQMUL_P, posd(r.y), y[1], 1e-3, "fx_dq_mul point y");
		test_fx_track(E_DQMUL_P, posd(r.z), y[2], 1e-3, "fx_dq_mul point z");
	}
	print_message("fx_dq_mul: max error %.3g (real), %.3g units (points, |p|, |t| < 1000)\n",
		      test_fx_max_err[E_DQMUL_R], test_fx_max_err[E_DQMUL_P]);
}

/* Bones with translations up to tmax per axis, points |p| < 1000. */
static void blend_run(double tmax)
{
	fx_dq bones[8];
	dquat real[4], dual[4];

	for (int i = 0; i < N_RANDOM; i++) {
		if (i % 16 == 0)
			for (int j = 0; j < 8; j++)
				bones[j] = rand_fx_bone(tmax);
		fx_w15 w[4];
		int n = rand_weights(w);
		uint16_t idx[4];
		double dw[4];
		unsigned sum = 0;
		for (int j = 0; j < n; j++) {
			idx[j] = (uint16_t)((i + 3 * j) % 8);
			real[j] = dquat_q30(bones[idx[j]].real);
			dual[j] = dquat_pos(bones[idx[j]].dual);
			dw[j] = w[j] / 32768.0;
			sum += w[j];
		}
		assert_int_equal(sum, 32768);
		fx_quat pivot = fx_dq_blend_pivot(bones, idx, w, n);
		fx_dq blend = fx_dq_blend(bones, idx, w, n, pivot), b = fx_dq_normalize(blend);
		dxf ref = dlb_ref(real, dual, dw, n, dquat_q30(pivot));

		/* normalised real part against b0 / |b0| in double */
		dquat b0 = { { 0 } };
		for (int j = 0; j < n; j++) {
			double dot = 0;
			for (int k = 0; k < 4; k++)
				dot += real[j].c[k] * dquat_q30(pivot).c[k];
			for (int k = 0; k < 4; k++)
				b0.c[k] += (dot < 0 ? -dw[j] : dw[j]) * real[j].c[k];
		}
		double nb = dquat_norm(b0);
		dquat got = dquat_q30(b.real);
		for (int k = 0; k < 4; k++)
			test_fx_track(E_BLEND_R, got.c[k], b0.c[k] / nb, 1e-6, "blend real / |real|");

		/* the kernels' path: the transform with the division folded in */
		fx_vec3 p = rand_pos(1000), nn = rand_normal(), np, rn;
		fx_dq_transform_blend(&blend, p, nn, &np, &rn);
		double dp[3] = { posd(p.x), posd(p.y), posd(p.z) }, want[3];
		dmat_apply(ref.r, dp, want);
		test_fx_track(E_BLEND_P, posd(np.x), want[0] + ref.t[0], 1e-3, "DQBS point x");
		test_fx_track(E_BLEND_P, posd(np.y), want[1] + ref.t[1], 1e-3, "DQBS point y");
		test_fx_track(E_BLEND_P, posd(np.z), want[2] + ref.t[2], 1e-3, "DQBS point z");

		double dn[3] = { test_fx_q30d(nn.x), test_fx_q30d(nn.y), test_fx_q30d(nn.z) };
		dmat_apply(ref.r, dn, want);
		test_fx_track(E_BLEND_N, test_fx_q30d(rn.x), want[0], 1e-6, "DQBS normal x");
		test_fx_track(E_BLEND_N, test_fx_q30d(rn.y), want[1], 1e-6, "DQBS normal y");
		test_fx_track(E_BLEND_N, test_fx_q30d(rn.z), want[2], 1e-6, "DQBS normal z");
	}
	print_message("fixed DQBS (1-4 influences, |t_i| < %.0f per axis, |p| < 1000): max error %.3g "
		      "(real components), %.3g units (points), %.3g (normals)\n", tmax,
		      test_fx_max_err[E_BLEND_R], test_fx_max_err[E_BLEND_P], test_fx_max_err[E_BLEND_N]);
}

static void test_blend(void **state)
{
	(void)state;
	blend_run(1000);
}

/* With the largest weight as pivot |b0| >= 1/4, so the blended translation
 * is at most 4 max|t_i| = 4 * 4000 * sqrt(3) < 27713: still in range. */
static void test_blend_far(void **state)
{
	(void)state;
	test_fx_max_err[E_BLEND_R] = test_fx_max_err[E_BLEND_P] = test_fx_max_err[E_BLEND_N] = 0;
	blend_run(4000);
}

static void test_blend_special(void **state)
{
	(void)state;
	fx_dq bones[2] = { rand_fx_bone(1000), rand_fx_bone(1000) };
	uint16_t idx[2] = { 1, 0 };
	fx_w15 full = FX_W15_ONE;

	/* a single full weight reproduces the bone bit for bit */
	fx_dq b = fx_dq_blend(bones, idx, &full, 1, bones[1].real);
	assert_memory_equal(&b, &bones[1], sizeof b);

	/* q and -q (same transform): the sign fix keeps them from cancelling */
	fx_dq neg = bones[0];
	neg.real.w = -neg.real.w; neg.real.x = -neg.real.x; neg.real.y = -neg.real.y; neg.real.z = -neg.real.z;
	neg.dual.w = -neg.dual.w; neg.dual.x = -neg.dual.x; neg.dual.y = -neg.dual.y; neg.dual.z = -neg.dual.z;
	fx_dq pair[2] = { bones[0], neg };
	uint16_t pidx[2] = { 0, 1 };
	fx_w15 half[2] = { 16384, 16384 };
	fx_dq h = fx_dq_blend(pair, pidx, half, 2, fx_dq_blend_pivot(pair, pidx, half, 2));
	fx_vec3 p = { 100 * FX_POS_ONE, -20 * FX_POS_ONE, 3 * FX_POS_ONE }, c, cn;
	fx_vec3 a = fx_dq_transform_point(&bones[0], p);
	fx_dq_transform_blend(&h, p, p, &c, &cn);
	assert_true(llabs((long long)a.x - c.x) <= 4 && llabs((long long)a.y - c.y) <= 4 &&
		    llabs((long long)a.z - c.z) <= 4);

	/* zero real part: identity, not a division by zero */
	fx_dq zero = { { 0, 0, 0, 0 }, { 5, 5, 5, 5 } };
	fx_dq z = fx_dq_normalize(zero);
	assert_int_equal(z.real.w, FX_Q30_ONE);
	assert_int_equal(z.dual.x, 0);
	/* a real part 2^32 long (weights summing to 4): its squared norm does
	 * not fit 64 bits, and it too gives the identity (UBSan checks that
	 * nothing overflows on the way) */
	fx_dq huge = { { INT32_MAX, INT32_MIN, INT32_MAX, INT32_MIN }, { 5, 5, 5, 5 } };
	z = fx_dq_normalize(huge);
	assert_int_equal(z.real.w, FX_Q30_ONE);
	assert_int_equal(z.real.x, 0);
	assert_int_equal(z.dual.y, 0);
}

static void test_end_to_end_from_float(void **state)
{
	(void)state;
	dq fb[8];
	fx_dq bones[8];
	dquat real[4], dual[4];

	for (int i = 0; i < N_RANDOM; i++) {
		if (i % 16 == 0)
			for (int j = 0; j < 8; j++) {
				dquat q = rand_unit();
				quat fq = { (float)q.c[0], (float)q.c[1], (float)q.c[2], (float)q.c[3] };
				vec3 t = vec3_make((float)test_rng_range(-1000, 1000), (float)test_rng_range(-1000, 1000),
						   (float)test_rng_range(-1000, 1000));
				fb[j] = dq_from_quat_trans(quat_normalize(fq), t);
				bones[j] = fx_dq_from_dq(&fb[j]);
			}
		fx_w15 w[4];
		int n = rand_weights(w);
		uint16_t idx[4];
		double dw[4];
		for (int j = 0; j < n; j++) {
			idx[j] = (uint16_t)((i + 5 * j) % 8);
			const dq *d = &fb[idx[j]];
			dquat r = { { d->real.w, d->real.x, d->real.y, d->real.z } };
			dquat e = { { d->dual.w, d->dual.x, d->dual.y, d->dual.z } };
			real[j] = r;
			dual[j] = e;
			dw[j] = w[j] / 32768.0;
		}
		fx_quat pivot = fx_dq_blend_pivot(bones, idx, w, n);
		fx_dq b = fx_dq_blend(bones, idx, w, n, pivot);
		dxf ref = dlb_ref(real, dual, dw, n, dquat_q30(pivot));
		vec3 fp = vec3_make((float)test_rng_range(-1000, 1000), (float)test_rng_range(-1000, 1000),
				    (float)test_rng_range(-1000, 1000));
		fx_vec3 moved, moved_n, n0 = { FX_Q30_ONE, 0, 0 };
		fx_dq_transform_blend(&b, fx_vec3_from_vec3(fp), n0, &moved, &moved_n);
		vec3 got = fx_vec3_to_vec3(moved);
		double dp[3] = { fp.x, fp.y, fp.z }, want[3];
		dmat_apply(ref.r, dp, want);
		/* float dq input, Q16 point input and float output each add
		 * rounding; the target is the same 1e-3 */
		test_fx_track(E_E2E_P, got.x, want[0] + ref.t[0], 1e-3, "end to end x");
		test_fx_track(E_E2E_P, got.y, want[1] + ref.t[1], 1e-3, "end to end y");
		test_fx_track(E_E2E_P, got.z, want[2] + ref.t[2], 1e-3, "end to end z");
	}
	print_message("end to end from float dqs: max error %.3g units\n", test_fx_max_err[E_E2E_P]);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_quat_mul, test_fx_rng_reset),
		cmocka_unit_test_setup(test_rotate, test_fx_rng_reset),
		cmocka_unit_test_setup(test_rotate_extremes, test_fx_rng_reset),
		cmocka_unit_test_setup(test_dq_mul, test_fx_rng_reset),
		cmocka_unit_test_setup(test_blend, test_fx_rng_reset),
		cmocka_unit_test_setup(test_blend_far, test_fx_rng_reset),
		cmocka_unit_test_setup(test_blend_special, test_fx_rng_reset),
		cmocka_unit_test_setup(test_end_to_end_from_float, test_fx_rng_reset),
	};
	return cmocka_run_group_tests_name("fixed", tests, NULL, NULL);
}
