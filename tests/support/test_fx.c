#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "test_fx.h"

#include <math.h>

#include "test_dref.h"
#include "test_rng.h"

#define Q30 1073741824.0

double test_fx_max_err[TEST_FX_SLOTS];

int test_fx_rng_reset(void **state)
{
	(void)state;
	test_rng_seed(0x1d872b41u);
	return 0;
}

double test_fx_q30d(int32_t v) { return v / Q30; }
int32_t test_fx_raw(double x, double one) { return (int32_t)llround(x * one); }

void test_fx_track(int slot, double got, double want, double tol, const char *what)
{
	test_error_track(&test_fx_max_err[slot], got, want, tol, what);
}
