#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "test_dref.h"
#include "test_rng.h"

double test_max_err[TEST_ERR_SLOTS];

dvec dv(double x, double y, double z) { dvec r = { x, y, z }; return r; }
dvec dv_f(vec3 a) { return dv(a.x, a.y, a.z); }
dvec dmat_apply(const double m[3][3], dvec v)
{
	return dv(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
		  m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
		  m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
}
dmat3 dmat3_mul(dmat3 a, dmat3 b)
{
	dmat3 r;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
	return r;
}

dmat3 dmat3_transpose(dmat3 a)
{
	dmat3 r;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			r.m[i][j] = a.m[j][i];
	return r;
}

dmat3 dmat3_rot(int axis, double rad)
{
	dmat3 r = { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
	double c = cos(rad), s = sin(rad);
	int i = (axis + 1) % 3, j = (axis + 2) % 3;
	r.m[i][i] = c; r.m[i][j] = -s;
	r.m[j][i] = s; r.m[j][j] = c;
	return r;
}

dvec drigid_apply(const drigid *a, dvec p)
{
	dvec r = dmat_apply(a->r, p);
	return dv(r.x + a->t.x, r.y + a->t.y, r.z + a->t.z);
}
vec3 rand_axis(void)
{
	for (;;) {
		double x = test_rng_range(-1, 1), y = test_rng_range(-1, 1), z = test_rng_range(-1, 1);
		double n = sqrt(x * x + y * y + z * z);
		if (n > 0.1 && n <= 1.0)
			return vec3_make((float)(x / n), (float)(y / n), (float)(z / n));
	}
}
vec3 rand_vec(double r)
{
	return vec3_make((float)test_rng_range(-r, r), (float)test_rng_range(-r, r), (float)test_rng_range(-r, r));
}
void test_error_track(double *worst, double got, double want, double tol, const char *what)
{
	double e = fabs(got - want);

	if (e > *worst)
		*worst = e;
	if (!(e <= tol))
		fail_msg("%s: got %.12g want %.12g (error %.3g > %.3g)", what, got, want, e, tol);
}

void close_to(double got, double want, double tol, int slot, const char *what)
{
	test_error_track(&test_max_err[slot], got, want, tol, what);
}
void vec_close(vec3 got, dvec want, double tol, int slot, const char *what)
{
	close_to(got.x, want.x, tol, slot, what);
	close_to(got.y, want.y, tol, slot, what);
	close_to(got.z, want.z, tol, slot, what);
}
