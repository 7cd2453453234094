/* Double-precision references and error checks shared by the math tests:
 * the code under test runs in float, the references in double. */
#ifndef TEST_DREF_H
#define TEST_DREF_H

#include "vec3.h"

typedef struct dvec { double x, y, z; } dvec;
/* Double rigid transform p' = R p + t. */
typedef struct drigid { double r[3][3]; dvec t; } drigid;

/* A 3x3 matrix by value (column vectors: m * v), for reference FK. */
typedef struct dmat3 { double m[3][3]; } dmat3;

dmat3 dmat3_mul(dmat3 a, dmat3 b);
dmat3 dmat3_transpose(dmat3 a);
/* Right-handed rotation by rad about axis 0 x, 1 y, 2 z. */
dmat3 dmat3_rot(int axis, double rad);

/* Largest error seen per slot (each test file gives its slots meanings). */
#define TEST_ERR_SLOTS 8
extern double test_max_err[TEST_ERR_SLOTS];

dvec dv(double x, double y, double z);
dvec dv_f(vec3 a);
dvec dmat_apply(const double m[3][3], dvec v);
dvec drigid_apply(const drigid *a, dvec p);
vec3 rand_axis(void);
vec3 rand_vec(double r);
void close_to(double got, double want, double tol, int slot, const char *what);
/* The same against any tracker: *worst the largest error seen; fails the
 * test past tol. */
void test_error_track(double *worst, double got, double want, double tol, const char *what);
void vec_close(vec3 got, dvec want, double tol, int slot, const char *what);

#endif
