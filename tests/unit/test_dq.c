/* Dual quaternions and the DQBS blend against double-precision references
 * (Rodrigues matrices and a double DLB written here), fixed-seed xorshift
 * inputs. Tolerances: 1e-6 for unit quantities (a few float ulps), and
 * 1e-6 * (1 + |p| + |t|) style absolute bounds for points, stated per check. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "dq.h"
#include "quat.h"
#include "rigid.h"
#include "test_dref.h"
#include "test_rng.h"
#include "vec3.h"

#define N_RANDOM 2000
#define PI 3.14159265358979323846

static int rng_reset(void **state)
{
	(void)state;
	test_rng_seed(0x6b43a9b5u);
	return 0;
}

/* ---- double references ---------------------------------------------------- */

static void rodrigues(dvec k, double angle, double m[3][3])
{
	double n = sqrt(k.x * k.x + k.y * k.y + k.z * k.z);
	double kv[3] = { k.x / n, k.y / n, k.z / n };
	double c = cos(angle), s = sin(angle), C = 1.0 - c;
	double cross[3][3] = { { 0, -kv[2], kv[1] }, { kv[2], 0, -kv[0] }, { -kv[1], kv[0], 0 } };

	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			m[i][j] = (i == j ? c : 0.0) + s * cross[i][j] + C * kv[i] * kv[j];
}

/* Rotation matrix of any nonzero quaternion, normalised in double:
 * the reference for a DLB result. */
static void dquat_to_mat(const double q[4], double m[3][3])
{
	double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
	double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;

	m[0][0] = w * w + x * x - y * y - z * z; m[0][1] = 2 * (x * y - w * z); m[0][2] = 2 * (x * z + w * y);
	m[1][0] = 2 * (x * y + w * z); m[1][1] = w * w - x * x + y * y - z * z; m[1][2] = 2 * (y * z - w * x);
	m[2][0] = 2 * (x * z - w * y); m[2][1] = 2 * (y * z + w * x); m[2][2] = w * w - x * x - y * y + z * z;
}

/* DLB in double straight from Kavan et al.: b = sum s_i w_i q_i, then
 * R from b0 / |b0| and t = 2 b_e b_0* / |b0|^2. */
static drigid ref_dlb(const dq *bones, const uint16_t *idx, const double *w, int n, quat pivot)
{
	double r[4] = { 0 }, d[4] = { 0 };
	drigid out;

	for (int i = 0; i < n; i++) {
		const dq *b = &bones[idx[i]];
		double dot = (double)b->real.w * pivot.w + (double)b->real.x * pivot.x +
			     (double)b->real.y * pivot.y + (double)b->real.z * pivot.z;
		double s = dot < 0 ? -w[i] : w[i];
		double br[4] = { b->real.w, b->real.x, b->real.y, b->real.z };
		double bd[4] = { b->dual.w, b->dual.x, b->dual.y, b->dual.z };
		for (int k = 0; k < 4; k++) {
			r[k] += s * br[k];
			d[k] += s * bd[k];
		}
	}
	double n2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3];
	dquat_to_mat(r, out.r);
	/* vector part of d * conj(r) */
	double tx = -d[0] * r[1] + r[0] * d[1] + (d[2] * -r[3] - d[3] * -r[2]);
	double ty = -d[0] * r[2] + r[0] * d[2] + (d[3] * -r[1] - d[1] * -r[3]);
	double tz = -d[0] * r[3] + r[0] * d[3] + (d[1] * -r[2] - d[2] * -r[1]);
	out.t = dv(2 * tx / n2, 2 * ty / n2, 2 * tz / n2);
	return out;
}

/* ---- random inputs and checks ----------------------------------------------- */

/* A random bone: float dq plus the exact double transform it stands for. */
static dq rand_bone(drigid *ref, double tmax)
{
	vec3 k = rand_axis(), t = rand_vec(tmax);
	float ang = (float)test_rng_range(-2 * PI, 2 * PI);

	rodrigues(dv_f(k), ang, ref->r);
	ref->t = dv_f(t);
	return dq_from_quat_trans(quat_from_axis_angle(k, ang), t);
}

static double qnorm(quat q) { return sqrt((double)quat_dot(q, q)); }

/* ---- tests -------------------------------------------------------------------- */

static void test_dq_rigid_round_trip(void **state)
{
	(void)state;
	dq id = dq_identity();
	vec3 p = vec3_make(1, 2, 3), q = dq_transform_point(&id, p);
	assert_true(q.x == 1.0f && q.y == 2.0f && q.z == 3.0f);

	/* |t| <= 100: translation back within 1e-4 (float ulp of 100 is 8e-6,
	 * times the product chain); rotation entries within 1e-6 */
	for (int i = 0; i < N_RANDOM; i++) {
		drigid ref;
		dq d = rand_bone(&ref, 100);
		rigid m = dq_to_rigid(&d);
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
				close_to(m.r[r][c], ref.r[r][c], 1e-6, 0, "dq_to_rigid rotation");
		vec_close(m.t, ref.t, 1e-4, 0, "dq_to_rigid translation");
		vec_close(dq_translation(&d), ref.t, 1e-4, 0, "dq_translation");

		dq back = dq_from_rigid(&m);
		rigid m2 = dq_to_rigid(&back);
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
				close_to(m2.r[r][c], ref.r[r][c], 2e-6, 0, "rigid->dq->rigid rotation");
		vec_close(m2.t, ref.t, 2e-4, 0, "rigid->dq->rigid translation");
		/* q and -q: the round trip may flip the sign, nothing else */
		double s = quat_dot(back.real, d.real) < 0 ? -1.0 : 1.0;
		close_to(s * back.real.w, d.real.w, 2e-6, 0, "dq_from_rigid real");
		close_to(s * back.dual.x, d.dual.x, 1e-4, 0, "dq_from_rigid dual");
	}
	print_message("dq <-> rigid: max error %.3g (|t| <= 100)\n", test_max_err[0]);
}

static void test_dq_mul_matches_rigid(void **state)
{
	(void)state;
	for (int i = 0; i < N_RANDOM; i++) {
		drigid ra, rb;
		dq a = rand_bone(&ra, 100), b = rand_bone(&rb, 100);
		dq ab = dq_mul(&a, &b);
		rigid ma = dq_to_rigid(&a), mb = dq_to_rigid(&b);
		rigid mab = rigid_mul(&ma, &mb), got = dq_to_rigid(&ab);
		vec3 p = rand_vec(100);

		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
				close_to(got.r[r][c], mab.r[r][c], 2e-6, 1, "dq_mul rotation vs rigid_mul");
		/* results up to |p| + 2 |t| = 520: 3e-4 */
		vec_close(dq_transform_point(&ab, p), drigid_apply(&ra, drigid_apply(&rb, dv_f(p))),
			  3e-4, 1, "dq_mul: b first, then a");
		close_to(qnorm(ab.real), 1.0, 1e-6, 1, "product stays unit");
	}
	print_message("dq_mul: max error %.3g\n", test_max_err[1]);
}

static void test_dq_normalize(void **state)
{
	(void)state;
	for (int i = 0; i < N_RANDOM; i++) {
		drigid ref;
		dq d = rand_bone(&ref, 100);
		float s = (float)test_rng_range(0.2, 5.0), drift = (float)test_rng_range(-3, 3);
		dq bad = d;
		/* scale both parts and push dual along real: both unit
		 * constraints broken, the transform unchanged in spirit */
		bad.real.w *= s; bad.real.x *= s; bad.real.y *= s; bad.real.z *= s;
		bad.dual.w = bad.dual.w * s + drift * bad.real.w;
		bad.dual.x = bad.dual.x * s + drift * bad.real.x;
		bad.dual.y = bad.dual.y * s + drift * bad.real.y;
		bad.dual.z = bad.dual.z * s + drift * bad.real.z;

		dq n = dq_normalize(bad);
		close_to(qnorm(n.real), 1.0, 1e-6, 2, "|real| = 1");
		close_to(quat_dot(n.real, n.dual), 0.0, 1e-4, 2, "real . dual = 0");
		vec3 p = rand_vec(100);
		vec_close(dq_transform_point(&n, p), drigid_apply(&ref, dv_f(p)), 3e-4, 2,
			  "normalised transform");
	}
	dq zero = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 } };
	dq id = dq_normalize(zero);
	assert_true(id.real.w == 1.0f && id.dual.x == 0.0f);
	print_message("dq_normalize: max error %.3g\n", test_max_err[2]);
}

static void test_dq_transform(void **state)
{
	(void)state;
	/* |p|, |t| <= 1000: results up to ~2700, float ulp 2.4e-4: 2e-3;
	 * normals 1e-6 */
	for (int i = 0; i < N_RANDOM; i++) {
		drigid ref;
		dq d = rand_bone(&ref, 1000);
		vec3 p = rand_vec(1000), n = vec3_normalize(rand_vec(1));

		vec_close(dq_transform_point(&d, p), drigid_apply(&ref, dv_f(p)), 2e-3, 3, "point");
		vec_close(dq_transform_normal(&d, n), dmat_apply(ref.r, dv_f(n)), 1e-6, 3, "normal");
	}
	print_message("dq_transform_point/normal: max error %.3g (|p|, |t| <= 1000)\n", test_max_err[3]);
}

static void test_blend_single(void **state)
{
	(void)state;
	for (int i = 0; i < 200; i++) {
		drigid ref[3];
		dq bones[3] = { rand_bone(&ref[0], 100), rand_bone(&ref[1], 100), rand_bone(&ref[2], 100) };
		uint16_t idx = (uint16_t)(i % 3);
		float w = 1.0f;
		quat pivot = dq_blend_pivot(bones, &idx, &w, 1);
		dq b = dq_blend(bones, &idx, &w, 1, pivot);

		/* 0 + 1 * x is exact */
		assert_memory_equal(&b, &bones[idx], sizeof b);
		/* normalising divides by |real| = 1 within an ulp */
		dq bn = dq_blend_normalized(bones, &idx, &w, 1, pivot);
		vec3 p = rand_vec(100);
		vec_close(dq_transform_point(&bn, p), drigid_apply(&ref[idx], dv_f(p)), 2e-4, 4,
			  "single influence");
	}
	print_message("single influence: max error %.3g\n", test_max_err[4]);
}

static void test_blend_antipodal(void **state)
{
	(void)state;
	for (int i = 0; i < 200; i++) {
		drigid ref;
		dq a = rand_bone(&ref, 100), b = a;
		/* -q with -dual: the very same transform */
		b.real.w = -b.real.w; b.real.x = -b.real.x; b.real.y = -b.real.y; b.real.z = -b.real.z;
		b.dual.w = -b.dual.w; b.dual.x = -b.dual.x; b.dual.y = -b.dual.y; b.dual.z = -b.dual.z;
		dq bones[2] = { a, b };
		uint16_t idx[2] = { 0, 1 };
		float w[2] = { 0.5f, 0.5f };

		/* without the sign fix the sum would be exactly zero */
		dq raw = dq_blend(bones, idx, w, 2, a.real);
		close_to(qnorm(raw.real), 1.0, 1e-6, 5, "no cancellation");
		dq bn = dq_blend_normalized(bones, idx, w, 2, dq_blend_pivot(bones, idx, w, 2));
		vec3 p = rand_vec(100);
		vec_close(dq_transform_point(&bn, p), drigid_apply(&ref, dv_f(p)), 2e-4, 5, "antipodal blend");
	}
	print_message("antipodal q / -q: max error %.3g\n", test_max_err[5]);
}

/* Angle of q about the unit axis k, in (-pi, pi]. */
static double angle_about(quat q, vec3 k)
{
	return 2.0 * atan2((double)q.x * k.x + (double)q.y * k.y + (double)q.z * k.z, q.w);
}

static double wrap(double a)
{
	while (a > PI)
		a -= 2 * PI;
	while (a <= -PI)
		a += 2 * PI;
	return a;
}

static void test_blend_twist_350(void **state)
{
	(void)state;
	vec3 z = vec3_make(0, 0, 1);
	/* 350 degrees is -10 degrees; its quaternion has w = cos 175 < 0, on
	 * the far hemisphere from the identity */
	dq bones[2] = { dq_identity(), dq_from_quat_trans(quat_from_axis_angle(z, (float)(350 * PI / 180)),
							    vec3_make(0, 0, 0)) };
	uint16_t idx[2] = { 0, 1 };
	const float ws[] = { 0.5f, 0.7f, 0.3f, 0.9f };

	assert_true(bones[1].real.w < 0);
	for (size_t i = 0; i < sizeof ws / sizeof ws[0]; i++) {
		float w[2] = { ws[i], 1.0f - ws[i] };
		quat pivot = dq_blend_pivot(bones, idx, w, 2);
		dq b = dq_blend_normalized(bones, idx, w, 2, pivot);
		double got = wrap(angle_about(b.real, z));
		/* -10 degrees weighted: a small twist, never the 175-degree
		 * candy wrapper the long way round would give; same-axis nlerp
		 * is within 0.002 degrees of linear at 10 degrees apart */
		double want = (1.0 - ws[i]) * (-10 * PI / 180);
		close_to(got, want, 1e-4, 6, "350-degree twist");
		vec3 p = dq_transform_point(&b, vec3_make(1, 0, 0));
		close_to(p.x, cos(want), 1e-4, 6, "twisted point x");
		close_to(p.y, sin(want), 1e-4, 6, "twisted point y");
	}
	print_message("350-degree twist: max error %.3g rad\n", test_max_err[6]);
}

static void test_blend_same_axis(void **state)
{
	(void)state;
	double worst_linear = 0;

	for (int i = 0; i < N_RANDOM; i++) {
		vec3 k = rand_axis();
		double a1 = test_rng_range(-PI, PI), delta = test_rng_range(-PI / 3, PI / 3);
		float w1 = (float)test_rng_range(0, 1), w[2] = { w1, 1.0f - w1 };
		dq bones[2] = { dq_from_quat_trans(quat_from_axis_angle(k, (float)a1), vec3_make(0, 0, 0)),
				dq_from_quat_trans(quat_from_axis_angle(k, (float)(a1 + delta)), vec3_make(0, 0, 0)) };
		uint16_t idx[2] = { 0, 1 };
		dq b = dq_blend_normalized(bones, idx, w, 2, dq_blend_pivot(bones, idx, w, 2));
		double got = angle_about(b.real, k);
		double h1 = 0.5 * (float)a1, h2 = 0.5 * (float)(a1 + delta);
		/* exact nlerp of the half angles on the unit circle */
		double nl = 2.0 * atan2(w[0] * sin(h1) + (double)w[1] * sin(h2),
					w[0] * cos(h1) + (double)w[1] * cos(h2));
		close_to(wrap(got - nl), 0.0, 2e-6, 7, "same axis vs exact nlerp");
		/* the weighted angle: nlerp departs from it by at most 0.27
		 * degrees when the rotations are <= 60 degrees apart */
		double lin = w[0] * (double)(float)a1 + w[1] * (double)(float)(a1 + delta);
		double e = fabs(wrap(got - lin));
		if (e > worst_linear)
			worst_linear = e;
		if (e > 5e-3)
			fail_msg("same axis: angle %.6f, weighted angle %.6f", got, lin);
	}
	print_message("same-axis blend: max error %.3g rad vs exact nlerp, %.3g rad vs weighted angle "
		      "(tolerance 5e-3)\n", test_max_err[7], worst_linear);
}

static void test_blend_random_unit(void **state)
{
	(void)state;
	double worst_norm = 0, worst_p = 0;

	for (int i = 0; i < N_RANDOM; i++) {
		drigid refs[6];
		dq bones[6];
		for (int j = 0; j < 6; j++)
			bones[j] = rand_bone(&refs[j], 100);
		int n = 1 + (int)(test_rng_u32() % 4);
		uint16_t idx[4];
		float w[4];
		double dw[4], sum = 0;
		for (int j = 0; j < n; j++) {
			idx[j] = (uint16_t)((i + j) % 6);
			dw[j] = test_rng_range(0.05, 1);
			sum += dw[j];
		}
		for (int j = 0; j < n; j++) {
			dw[j] /= sum;
			w[j] = (float)dw[j];
			dw[j] = w[j];
		}
		quat pivot = dq_blend_pivot(bones, idx, w, n);
		dq b = dq_blend_normalized(bones, idx, w, n, pivot);
		double e = fabs(qnorm(b.real) - 1.0);
		if (e > worst_norm)
			worst_norm = e;
		assert_true(e < 1e-6);

		/* transform against the double DLB of the same float dqs;
		 * |p| <= 100 and |t| up to 100/|b0|: 1e-3 */
		drigid ref = ref_dlb(bones, idx, dw, n, pivot);
		vec3 p = rand_vec(100), nn = vec3_normalize(rand_vec(1));
		dvec want = drigid_apply(&ref, dv_f(p));
		vec3 got = dq_transform_point(&b, p);
		double ep = fmax(fabs(got.x - want.x), fmax(fabs(got.y - want.y), fabs(got.z - want.z)));
		if (ep > worst_p)
			worst_p = ep;
		assert_true(ep < 1e-3);
		vec3 gn = dq_transform_normal(&b, nn);
		dvec wn = dmat_apply(ref.r, dv_f(nn));
		assert_true(fabs(gn.x - wn.x) < 2e-6 && fabs(gn.y - wn.y) < 2e-6 && fabs(gn.z - wn.z) < 2e-6);

		/* dq_normalize also removes the dual's component along real,
		 * which the transform ignores anyway */
		dq full = dq_normalize(dq_blend(bones, idx, w, n, pivot));
		assert_true(fabs(quat_dot(full.real, full.dual)) < 1e-4);
		vec3 p2 = dq_transform_point(&full, p);
		assert_true(fabs(p2.x - got.x) < 1e-3 && fabs(p2.y - got.y) < 1e-3 && fabs(p2.z - got.z) < 1e-3);
	}
	print_message("random 1-4 influence blends: | |real| - 1 | <= %.3g, point error <= %.3g\n",
		      worst_norm, worst_p);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_dq_rigid_round_trip, rng_reset),
		cmocka_unit_test_setup(test_dq_mul_matches_rigid, rng_reset),
		cmocka_unit_test_setup(test_dq_normalize, rng_reset),
		cmocka_unit_test_setup(test_dq_transform, rng_reset),
		cmocka_unit_test_setup(test_blend_single, rng_reset),
		cmocka_unit_test_setup(test_blend_antipodal, rng_reset),
		cmocka_unit_test_setup(test_blend_twist_350, rng_reset),
		cmocka_unit_test_setup(test_blend_same_axis, rng_reset),
		cmocka_unit_test_setup(test_blend_random_unit, rng_reset),
	};
	return cmocka_run_group_tests_name("dq", tests, NULL, NULL);
}
