/* app/play/play_sync: the show's position from the wall clock, to the
 * nanosecond, whenever a device started; joins; the epoch's ISO 8601. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "play_sync.h"
#include "utc_time.h"

#define S 1000000000LL

/* A show of 3 s, a clip that does not play, then 2 s. */
static const uint64_t lengths[] = { 3 * S, 0, 2 * S };

static void assert_at(int64_t wall, int clip, uint64_t into, uint64_t pass)
{
	play_sync_at at;
	assert_int_equal(play_sync_locate(wall, 0, lengths, 3, &at), 0);
	assert_int_equal(at.clip, clip);
	assert_int_equal(at.into_ns, into);
	assert_int_equal(at.pass, pass);
}

static void test_locate(void **state)
{
	(void)state;
	assert_at(0, 0, 0, 0);
	assert_at(2 * S + 999999999, 0, 2 * S + 999999999, 0);
	assert_at(3 * S, 2, 0, 0);           /* the clip of length 0 is never chosen */
	assert_at(4 * S + S / 2, 2, 1 * S + S / 2, 0);
	assert_at(5 * S, 0, 0, 1);
	assert_at(-1, 2, 2 * S - 1, 1);      /* before the epoch: round the show backwards */
	assert_at(-5 * S, 0, 0, 1);
	assert_at(-6 * S, 2, 1 * S, 2);
	play_sync_at at;
	static const uint64_t none[] = { 0, 0 };
	assert_int_equal(play_sync_locate(12345, 0, none, 2, &at), -1);
	assert_int_equal(play_sync_locate(12345, 0, none, 0, &at), -1);
}

/* Two devices that started at any two times compute the same clip and
 * time for the same instant: the position depends on the wall clock and
 * the epoch alone, exact to the ns at today's clock (1.8e18 ns). */
static void test_same_instant_same_pose(void **state)
{
	(void)state;
	int64_t epoch = 1767225600LL * S; /* 2026-01-01T00:00:00Z */
	uint64_t show = 5 * S;
	for (int64_t k = 0; k < 10000; k += 97) { /* up to 57 years of 5 s shows */
		int64_t x = (k * 7919 * 1000003LL) % (int64_t)show, wall = epoch + (int64_t)(k * 36000) * (int64_t)show + x;
		play_sync_at at;
		assert_int_equal(play_sync_locate(wall, epoch, lengths, 3, &at), 0);
		uint64_t start = at.clip == 0 ? 0 : 3 * S;
		assert_int_equal(start + at.into_ns, (uint64_t)x);
		assert_int_equal(at.pass, (uint64_t)(k * 36000));
	}
}

static void test_off_the_clock(void **state)
{
	(void)state;
	assert_false(play_sync_off(10.0, 10.02, 0.05));
	assert_false(play_sync_off(10.02, 10.0, 0.05));
	assert_true(play_sync_off(10.0, 11.0, 0.05));
	assert_true(play_sync_off(12.0, 11.0, 0.05));
	assert_true(play_sync_off(0.0 / 0.0, 1.0, 0.05)); /* a NaN is never on the clock */
}

static void assert_epoch(const char *text, int64_t want)
{
	int64_t ns = -7;
	if (utc_time_parse(text, &ns) != 0)
		fail_msg("'%s' not parsed", text);
	assert_int_equal(ns, want);
}

static void test_epoch(void **state)
{
	(void)state;
	assert_epoch("1970-01-01T00:00:00Z", 0);
	assert_epoch("2026-01-01T00:00:00Z", 1767225600LL * S);
	assert_epoch("2000-02-29T12:34:56.25Z", 951827696LL * S + S / 4);
	assert_epoch("2026-06-30T23:59:59+00:00", 1782863999LL * S);
	assert_epoch("1969-12-31T23:59:59Z", -S);
	static const char *const bad[] = { "", "2026-01-01", "2026-01-01T00:00:00", "2026-01-01T00:00:00+01:00",
					   "2025-02-29T00:00:00Z", "2026-13-01T00:00:00Z", "2026-01-32T00:00:00Z",
					   "2026-01-01T24:00:00Z", "2026-01-01T00:60:00Z", "2026-01-01T00:00:00Zx",
					   "20260101T000000Z", "9999-01-01T00:00:00Z", "2026-01-01T00:00:0aZ" };
	int64_t ns;
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
		if (utc_time_parse(bad[i], &ns) == 0)
			fail_msg("'%s' parsed", bad[i]);
	assert_int_equal(utc_time_parse(NULL, &ns), -1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_locate),
		cmocka_unit_test(test_same_instant_same_pose),
		cmocka_unit_test(test_off_the_clock),
		cmocka_unit_test(test_epoch),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
