/* What the fixed-point tests (test_fixed, test_fixed_scalar) share: the
 * random inputs' seed, Q30 values read as doubles and doubles rounded to a
 * fixed format, and the largest error seen per slot. */
#ifndef TEST_FX_H
#define TEST_FX_H

#include <stdint.h>

/* cmocka setup: every test draws the same inputs (test_rng.h). */
int test_fx_rng_reset(void **state);

/* A Q30 value as a double. */
double test_fx_q30d(int32_t v);
/* x in the fixed format whose one is `one`, rounded to nearest. */
int32_t test_fx_raw(double x, double one);

/* Largest error seen per slot (each test file gives its slots meanings). */
#define TEST_FX_SLOTS 16
extern double test_fx_max_err[TEST_FX_SLOTS];

/* Records |got - want| in slot's largest error; fails the test naming what
 * when it exceeds tol. */
void test_fx_track(int slot, double got, double want, double tol, const char *what);

#endif
