/* The rate limiter on a fake clock: the first occurrence said, then one
 * line an interval with the count held back in between; a month of an
 * event every second is 720 lines, not 2.6 million. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "skp_ratelimit.h"

#define SECOND 1000000000ull

static void test_first_then_hourly_with_counts(void **state)
{
	(void)state;
	skp_ratelimit r;
	unsigned long held = 99;
	skp_ratelimit_init(&r, SKP_RATELIMIT_HOUR);
	assert_int_equal(skp_ratelimit_take(&r, 5 * SECOND, &held), 1);
	assert_int_equal(held, 0);
	for (uint64_t t = 6; t < 3605; t++)
		assert_int_equal(skp_ratelimit_take(&r, t * SECOND, &held), 0);
	assert_int_equal(skp_ratelimit_take(&r, 3605 * SECOND, &held), 1);
	assert_int_equal(held, 3599);
	/* quiet for a day: the next one is said at once, nothing held */
	assert_int_equal(skp_ratelimit_take(&r, 90000 * SECOND, &held), 1);
	assert_int_equal(held, 0);
}

static void test_a_month_of_seconds(void **state)
{
	(void)state;
	skp_ratelimit r;
	unsigned long held, said = 0, counted = 0;
	skp_ratelimit_init(&r, SKP_RATELIMIT_HOUR);
	for (uint64_t t = 0; t < 30ull * 86400; t++)
		if (skp_ratelimit_take(&r, t * SECOND, &held)) {
			said++;
			counted += held + 1;
		}
	assert_int_equal(said, 30 * 24);
	/* every occurrence but those still held is accounted for */
	assert_true(counted + r.held == 30ull * 86400);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_first_then_hourly_with_counts),
		cmocka_unit_test(test_a_month_of_seconds),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
