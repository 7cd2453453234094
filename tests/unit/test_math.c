/* vec3, quat and rigid against double-precision references written here
 * independently (Rodrigues matrices, scalar/vector quaternion product), on
 * inputs from a fixed-seed xorshift PRNG. Tolerances are absolute and sized
 * for single precision: a few float ulps (1.2e-7) times the operation count
 * and the magnitude of the operands. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "quat.h"
#include "rigid.h"
#include "test_dref.h"
#include "test_rng.h"
#include "vec3.h"

#define N_RANDOM 2000
#define PI 3.14159265358979323846

/* ---- PRNG ---------------------------------------------------------------- */

static int rng_reset(void **state)
{
	(void)state;
	test_rng_seed(0x2545f491u);
	return 0;
}

/* ---- double references ---------------------------------------------------- */

typedef struct dquat { double w; dvec v; } dquat;

static double dv_dot(dvec a, dvec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dvec dv_cross(dvec a, dvec b)
{
	return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static dvec dv_axpy(double s, dvec a, dvec b) { return dv(s * a.x + b.x, s * a.y + b.y, s * a.z + b.z); }

/* (s1, v1)(s2, v2) = (s1 s2 - v1.v2, s1 v2 + s2 v1 + v1 x v2) */
static dquat dq_ref_mul(dquat a, dquat b)
{
	dquat r;

	r.w = a.w * b.w - dv_dot(a.v, b.v);
	r.v = dv_axpy(a.w, b.v, dv_axpy(b.w, a.v, dv_cross(a.v, b.v)));
	return r;
}

static dquat dquat_f(quat q) { dquat r = { q.w, dv(q.x, q.y, q.z) }; return r; }

/* Rodrigues: R = cos I + sin [k]x + (1 - cos) k k^T, for a unit axis k. */
static void rodrigues(dvec k, double angle, double m[3][3])
{
	double c = cos(angle), s = sin(angle), C = 1.0 - c;
	double kv[3] = { k.x, k.y, k.z };
	double cross[3][3] = { { 0, -k.z, k.y }, { k.z, 0, -k.x }, { -k.y, k.x, 0 } };

	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			m[i][j] = (i == j ? c : 0.0) + s * cross[i][j] + C * kv[i] * kv[j];
}

static void dmat_mul(const double a[3][3], const double b[3][3], double r[3][3])
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
}

/* ---- random inputs -------------------------------------------------------- */

/* Unit axis rounded to float, so the reference sees exactly what the code
 * under test sees. */

/* Reference matrix for a float axis that is unit only to float precision. */
static void rodrigues_f(vec3 axis, float angle, double m[3][3])
{
	dvec k = dv_f(axis);
	double n = sqrt(dv_dot(k, k));

	rodrigues(dv(k.x / n, k.y / n, k.z / n), angle, m);
}

/* ---- checks ----------------------------------------------------------------- */

static void quat_close(quat got, dquat want, double tol, int slot, const char *what)
{
	close_to(got.w, want.w, tol, slot, what);
	vec_close(vec3_make(got.x, got.y, got.z), want.v, tol, slot, what);
}

/* Same rotation: q or -q. */
static void rot_close(quat got, dquat want, double tol, int slot, const char *what)
{
	if (got.w * want.w + dv_dot(dv(got.x, got.y, got.z), want.v) < 0) {
		want.w = -want.w;
		want.v = dv(-want.v.x, -want.v.y, -want.v.z);
	}
	quat_close(got, want, tol, slot, what);
}

/* ---- vec3 ------------------------------------------------------------------- */

static void test_vec3_ops(void **state)
{
	(void)state;
	/* |components| <= 100: products up to 3e4, float ulp there ~2e-3 */
	for (int i = 0; i < N_RANDOM; i++) {
		vec3 a = rand_vec(100), b = rand_vec(100);
		float s = (float)test_rng_range(-10, 10);
		dvec da = dv_f(a), db = dv_f(b);

		vec_close(vec3_add(a, b), dv(da.x + db.x, da.y + db.y, da.z + db.z), 2e-5, 0, "add");
		vec_close(vec3_sub(a, b), dv(da.x - db.x, da.y - db.y, da.z - db.z), 2e-5, 0, "sub");
		vec_close(vec3_scale(a, s), dv(da.x * s, da.y * s, da.z * s), 1e-4, 0, "scale");
		vec_close(vec3_madd(a, b, s), dv_axpy(s, db, da), 2e-4, 0, "madd");
		close_to(vec3_dot(a, b), dv_dot(da, db), 1e-2, 0, "dot");
		vec_close(vec3_cross(a, b), dv_cross(da, db), 5e-3, 0, "cross");
		close_to(vec3_length(a), sqrt(dv_dot(da, da)), 2e-5, 0, "length");
		vec3 n = vec3_normalize(a);
		double l = sqrt(dv_dot(da, da));
		vec_close(n, dv(da.x / l, da.y / l, da.z / l), 3e-7, 0, "normalize");
	}
	vec3 z = vec3_normalize(vec3_make(0, 0, 0));
	assert_true(z.x == 0.0f && z.y == 0.0f && z.z == 0.0f);
	print_message("vec3: max error %.3g (absolute, operands up to 100)\n", test_max_err[0]);
}

/* ---- quat ------------------------------------------------------------------- */

static void test_quat_mul(void **state)
{
	(void)state;
	/* components in [-1, 1]: sums of 4 products, tolerance 8 ulps of 1 */
	for (int i = 0; i < N_RANDOM; i++) {
		quat a = { (float)test_rng_range(-1, 1), (float)test_rng_range(-1, 1),
			   (float)test_rng_range(-1, 1), (float)test_rng_range(-1, 1) };
		quat b = { (float)test_rng_range(-1, 1), (float)test_rng_range(-1, 1),
			   (float)test_rng_range(-1, 1), (float)test_rng_range(-1, 1) };
		quat_close(quat_mul(a, b), dq_ref_mul(dquat_f(a), dquat_f(b)), 1e-6, 1, "quat_mul");
		quat c = quat_conj(a);
		assert_true(c.w == a.w && c.x == -a.x && c.y == -a.y && c.z == -a.z);
		close_to(quat_dot(a, b), a.w * (double)b.w + a.x * (double)b.x +
			 a.y * (double)b.y + a.z * (double)b.z, 1e-6, 1, "quat_dot");
		quat n = quat_normalize(a);
		double l = sqrt(quat_dot(a, a) + 0.0);
		dquat dn = { a.w / l, dv(a.x / l, a.y / l, a.z / l) };
		quat_close(n, dn, 5e-7, 1, "quat_normalize");
	}
	quat zero = { 0, 0, 0, 0 };
	quat id = quat_normalize(zero);
	assert_true(id.w == 1.0f && id.x == 0.0f && id.y == 0.0f && id.z == 0.0f);
	print_message("quat_mul/dot/normalize: max error %.3g\n", test_max_err[1]);
}

static void test_quat_rotate_and_matrix(void **state)
{
	(void)state;
	/* angles up to +-4 pi: rotated unit-ish vectors within 1e-6, |v| <= 10
	 * within 1e-5 */
	for (int i = 0; i < N_RANDOM; i++) {
		vec3 k = rand_axis();
		float ang = (float)test_rng_range(-4 * PI, 4 * PI);
		double m[3][3];
		float fm[3][3];
		vec3 v = rand_vec(10);
		quat q = quat_from_axis_angle(k, ang);

		rodrigues_f(k, ang, m);
		vec_close(quat_rotate(q, v), dmat_apply(m, dv_f(v)), 1e-5, 2, "quat_rotate");
		quat_to_mat3(q, fm);
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
				close_to(fm[r][c], m[r][c], 1e-6, 2, "quat_to_mat3");
		close_to(quat_dot(q, q), 1.0, 5e-7, 2, "axis-angle is unit");
	}
	for (int axis = 0; axis < 3; axis++) {
		double m[3][3];
		vec3 v = vec3_make(0.3f, -0.7f, 1.1f);
		rodrigues(dv(axis == 0, axis == 1, axis == 2), 0.8, m);
		vec_close(quat_rotate(quat_from_basis_angle(axis, 0.8f), v),
			  dmat_apply(m, dv_f(v)), 1e-6, 2, "quat_from_basis_angle");
	}
	print_message("quat_rotate/quat_to_mat3: max error %.3g\n", test_max_err[2]);
}

static void test_quat_composition(void **state)
{
	(void)state;
	for (int i = 0; i < N_RANDOM; i++) {
		vec3 k = rand_axis();
		float a = (float)test_rng_range(-PI, PI), b = (float)test_rng_range(-PI, PI);
		/* half angles add: q(a) q(b) = q(a + b) exactly, sign included */
		quat ab = quat_mul(quat_from_axis_angle(k, a), quat_from_axis_angle(k, b));
		double h = 0.5 * ((double)a + (double)b);
		dvec dk = dv_f(k);
		dquat want = { cos(h), dv(dk.x * sin(h), dk.y * sin(h), dk.z * sin(h)) };
		quat_close(ab, want, 1e-6, 3, "same-axis composition");

		/* different axes: rotate(a b) = Ra Rb */
		vec3 k2 = rand_axis();
		double ma[3][3], mb[3][3], mab[3][3];
		vec3 v = rand_vec(1);
		rodrigues_f(k, a, ma);
		rodrigues_f(k2, b, mb);
		dmat_mul(ma, mb, mab);
		quat qab = quat_mul(quat_from_axis_angle(k, a), quat_from_axis_angle(k2, b));
		vec_close(quat_rotate(qab, v), dmat_apply(mab, dv_f(v)), 2e-6, 3, "composition order");
	}
	print_message("composition: max error %.3g\n", test_max_err[3]);
}

static void check_from_mat3(vec3 k, double ang, double tol)
{
	double m[3][3];
	float fm[3][3];

	rodrigues_f(k, (float)ang, m);
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++)
			fm[r][c] = (float)m[r][c];
	quat q = quat_from_mat3(fm);
	double h = 0.5 * (double)(float)ang, n = sqrt(dv_dot(dv_f(k), dv_f(k)));
	dquat want = { cos(h), dv(k.x / n * sin(h), k.y / n * sin(h), k.z / n * sin(h)) };
	rot_close(q, want, tol, 4, "quat_from_mat3");
	close_to(quat_dot(q, q), 1.0, 5e-7, 4, "quat_from_mat3 unit");
}

static void test_quat_from_mat3(void **state)
{
	(void)state;
	/* A matrix rounded to float carries ~6e-8 noise per entry; Shepperd's
	 * method divides by at least ~1, so the quaternion stays within 1e-6
	 * even at 180 degrees, where the trace branch would lose it. */
	for (int i = 0; i < N_RANDOM; i++)
		check_from_mat3(rand_axis(), test_rng_range(-PI, PI), 1e-6);
	const double near[] = { 0.0, 1e-7, 1e-5, 1e-3, 1e-2 };
	for (int i = 0; i < 500; i++) {
		vec3 k = rand_axis();
		for (size_t j = 0; j < sizeof near / sizeof near[0]; j++) {
			check_from_mat3(k, PI - near[j], 1e-6);
			check_from_mat3(k, -PI + near[j], 1e-6);
		}
	}
	/* exactly 180 degrees about each basis axis and a diagonal: trace -1,
	 * every branch of the method */
	for (int axis = 0; axis < 3; axis++)
		check_from_mat3(vec3_make(axis == 0, axis == 1, axis == 2), PI, 1e-6);
	check_from_mat3(vec3_normalize(vec3_make(1, 1, 0)), PI, 1e-6);
	check_from_mat3(vec3_normalize(vec3_make(1, -1, 1)), PI, 1e-6);
	print_message("quat_from_mat3 (incl. near 180 deg): max error %.3g\n", test_max_err[4]);
}

/* ---- rigid ------------------------------------------------------------------ */

static rigid rand_rigid(drigid *ref, double tmax)
{
	vec3 k = rand_axis(), t = rand_vec(tmax);
	float ang = (float)test_rng_range(-PI, PI);

	rodrigues_f(k, ang, ref->r);
	ref->t = dv_f(t);
	return rigid_from_quat_trans(quat_from_axis_angle(k, ang), t);
}

static void test_rigid(void **state)
{
	(void)state;
	rigid id = rigid_identity();
	vec3 p0 = vec3_make(1.5f, -2.0f, 3.25f);
	vec3 q0 = rigid_apply_point(&id, p0);
	assert_true(q0.x == p0.x && q0.y == p0.y && q0.z == p0.z);

	/* |t| <= 100, |p| <= 100: results up to ~270, float ulp there 3e-5;
	 * tolerance 2e-4 after a product of two transforms */
	for (int i = 0; i < N_RANDOM; i++) {
		drigid ra, rb;
		rigid a = rand_rigid(&ra, 100), b = rand_rigid(&rb, 100);
		vec3 p = rand_vec(100), n = vec3_normalize(rand_vec(1));

		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
				close_to(a.r[r][c], ra.r[r][c], 1e-6, 5, "rigid_from_quat_trans");
		vec_close(rigid_apply_point(&a, p), drigid_apply(&ra, dv_f(p)), 1e-4, 5, "rigid_apply_point");
		vec_close(rigid_apply_normal(&a, n), dmat_apply(ra.r, dv_f(n)), 1e-6, 5, "rigid_apply_normal");

		rigid ab = rigid_mul(&a, &b);
		vec_close(rigid_apply_point(&ab, p), drigid_apply(&ra, drigid_apply(&rb, dv_f(p))),
			  2e-4, 5, "rigid_mul (b first, then a)");

		/* inverse: R^T and -R^T t in double */
		rigid ia = rigid_inverse(&a);
		drigid ri;
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 3; c++)
				ri.r[r][c] = ra.r[c][r];
		dvec mt = dmat_apply(ri.r, ra.t);
		ri.t = dv(-mt.x, -mt.y, -mt.z);
		vec_close(rigid_apply_point(&ia, p), drigid_apply(&ri, dv_f(p)), 1e-4, 5, "rigid_inverse");
		rigid round = rigid_mul(&ia, &a);
		vec_close(rigid_apply_point(&round, p), dv_f(p), 2e-4, 5, "inverse * a = identity");
	}
	print_message("rigid: max error %.3g (points up to |p| + |t| = 270)\n", test_max_err[5]);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup(test_vec3_ops, rng_reset),
		cmocka_unit_test_setup(test_quat_mul, rng_reset),
		cmocka_unit_test_setup(test_quat_rotate_and_matrix, rng_reset),
		cmocka_unit_test_setup(test_quat_composition, rng_reset),
		cmocka_unit_test_setup(test_quat_from_mat3, rng_reset),
		cmocka_unit_test_setup(test_rigid, rng_reset),
	};
	return cmocka_run_group_tests_name("math", tests, NULL, NULL);
}
