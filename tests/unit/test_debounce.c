/* Debounce with synthetic bounce trains: chatter, long presses, two
 * buttons at once, timestamps going backwards. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "debounce.h"

static const debounce_config cfg = { 30, 800 };

/* One sample of a train: time, level (or DEBOUNCE_TICK). */
typedef struct sample {
	uint64_t t;
	int level;
} sample;

typedef struct seen {
	unsigned bits[64];
	uint64_t at[64];
	int n;
	int press, release, lng;
} seen;

static void run(const debounce_config *c, debounce_data *d, const sample *s, int n, seen *out)
{
	memset(out, 0, sizeof *out);
	for (int i = 0; i < n; i++) {
		unsigned b = debounce_update(c, d, s[i].t, s[i].level);
		if (!b)
			continue;
		out->bits[out->n] = b;
		out->at[out->n++] = s[i].t;
		out->press += !!(b & DEBOUNCE_PRESS);
		out->release += !!(b & DEBOUNCE_RELEASE);
		out->lng += !!(b & DEBOUNCE_LONG);
	}
}

static void test_clean_press_after_debounce_time(void **state)
{
	(void)state;
	debounce_data d;
	debounce_init(&d, 0, 0);
	assert_int_equal(debounce_update(&cfg, &d, 100, 1), 0);
	assert_int_equal(debounce_update(&cfg, &d, 129, DEBOUNCE_TICK), 0);
	assert_int_equal(debounce_update(&cfg, &d, 130, DEBOUNCE_TICK), DEBOUNCE_PRESS);
	assert_int_equal(debounce_update(&cfg, &d, 131, DEBOUNCE_TICK), 0);
	assert_int_equal(debounce_update(&cfg, &d, 300, 0), 0);
	assert_int_equal(debounce_update(&cfg, &d, 330, DEBOUNCE_TICK), DEBOUNCE_RELEASE);
}

/* Contact chatter: edges every 1-9 ms for 25 ms, on press and on release:
 * exactly one press and one release, and the press counts from the last
 * bounce, not the first. */
static void test_chatter_gives_one_press_one_release(void **state)
{
	(void)state;
	static const int gaps[] = { 1, 3, 2, 9, 4, 1, 5 };
	sample s[256];
	int n = 0, level = 1;
	uint64_t t = 1000;
	for (int i = 0; i < 7; i++, level = !level) {
		s[n++] = (sample){ t, level };
		t += (uint64_t)gaps[i];
	}
	uint64_t settled = s[n - 1].t;      /* last edge: level 1 (7 edges) */
	for (uint64_t k = t; k < t + 400; k += 5)
		s[n++] = (sample){ k, DEBOUNCE_TICK };
	level = 0;
	t += 400;
	for (int i = 0; i < 7; i++, level = !level) {
		s[n++] = (sample){ t, level };
		t += (uint64_t)gaps[i];
	}
	for (uint64_t k = t; k < t + 100; k += 5)
		s[n++] = (sample){ k, DEBOUNCE_TICK };
	debounce_data d;
	debounce_init(&d, 0, 0);
	seen out;
	run(&cfg, &d, s, n, &out);
	assert_int_equal(out.press, 1);
	assert_int_equal(out.release, 1);
	assert_int_equal(out.lng, 0);
	assert_true(out.at[0] >= settled + cfg.debounce_ms);
	assert_true(out.at[0] < settled + cfg.debounce_ms + 5);
	assert_int_equal(d.stable, 0);
}

/* Glitches shorter than the debounce time never count. */
static void test_short_glitches_ignored(void **state)
{
	(void)state;
	sample s[40];
	int n = 0;
	for (uint64_t t = 0; t < 1000; t += 50) {
		s[n++] = (sample){ t, 1 };
		s[n++] = (sample){ t + 29, 0 };
	}
	debounce_data d;
	debounce_init(&d, 0, 0);
	seen out;
	run(&cfg, &d, s, n, &out);
	assert_int_equal(out.n, 0);
}

static void test_long_press_once_then_release(void **state)
{
	(void)state;
	debounce_data d;
	debounce_init(&d, 0, 0);
	seen out;
	sample s[] = { { 100, 1 }, { 130, DEBOUNCE_TICK }, { 899, DEBOUNCE_TICK }, { 900, DEBOUNCE_TICK },
		       { 2000, DEBOUNCE_TICK }, { 3000, 0 }, { 3030, DEBOUNCE_TICK } };
	run(&cfg, &d, s, 7, &out);
	assert_int_equal(out.n, 3);
	assert_int_equal(out.bits[0], DEBOUNCE_PRESS);
	assert_int_equal(out.bits[1], DEBOUNCE_LONG);
	assert_int_equal(out.at[1], 900);   /* 800 ms after the edge */
	assert_int_equal(out.bits[2], DEBOUNCE_RELEASE);
	/* a bounce during the hold does not restart the long-press timer */
	debounce_init(&d, 0, 0);
	sample b[] = { { 0, 1 }, { 40, DEBOUNCE_TICK }, { 500, 0 }, { 505, 1 }, { 800, DEBOUNCE_TICK } };
	run(&cfg, &d, b, 5, &out);
	assert_int_equal(out.lng, 1);
	assert_int_equal(out.at[out.n - 1], 800);
}

/* A release just before the long-press deadline, confirmed after it: no
 * long press. Released just after the deadline: long press, then release. */
static void test_release_near_long_deadline(void **state)
{
	(void)state;
	debounce_data d;
	seen out;
	debounce_init(&d, 0, 0);
	sample a[] = { { 0, 1 }, { 30, DEBOUNCE_TICK }, { 790, 0 }, { 805, DEBOUNCE_TICK }, { 820, DEBOUNCE_TICK } };
	run(&cfg, &d, a, 5, &out);
	assert_int_equal(out.press, 1);
	assert_int_equal(out.lng, 0);
	assert_int_equal(out.release, 1);
	debounce_init(&d, 0, 0);
	sample b[] = { { 0, 1 }, { 30, DEBOUNCE_TICK }, { 801, 0 }, { 900, DEBOUNCE_TICK } };
	run(&cfg, &d, b, 4, &out);
	assert_int_equal(out.lng, 1);
	assert_int_equal(out.release, 1);
	assert_int_equal(out.bits[out.n - 2], DEBOUNCE_LONG);   /* at the release edge */
	assert_int_equal(out.at[out.n - 2], 801);
	assert_int_equal(out.bits[out.n - 1], DEBOUNCE_RELEASE);
	/* without debounce time both happen at the edge, long press first */
	debounce_config nodeb = { 0, 800 };
	debounce_init(&d, 0, 0);
	debounce_update(&nodeb, &d, 0, 1);
	assert_int_equal(debounce_update(&nodeb, &d, 850, 0), DEBOUNCE_LONG | DEBOUNCE_RELEASE);
	/* one late tick after a long silence reports press and long together */
	debounce_init(&d, 0, 0);
	debounce_update(&cfg, &d, 0, 1);
	assert_int_equal(debounce_update(&cfg, &d, 5000, DEBOUNCE_TICK), DEBOUNCE_PRESS | DEBOUNCE_LONG);
}

/* Two buttons pressed at once with interleaved bounces: each has its own
 * state, each gives its own press and release. */
static void test_two_buttons_at_once(void **state)
{
	(void)state;
	debounce_data a, b;
	debounce_init(&a, 0, 0);
	debounce_init(&b, 0, 0);
	int pa = 0, pb = 0, ra = 0, rb = 0;
	for (uint64_t t = 0; t < 600; t++) {
		/* a bounces at 100..110, b at 104..120; a released at 300, b at 400 */
		int la = t >= 100 && t < 300 ? (t < 110 ? (int)(t & 1) : 1) : 0;
		int lb = t >= 104 && t < 400 ? (t < 120 ? (int)((t >> 1) & 1) : 1) : 0;
		unsigned ea = debounce_update(&cfg, &a, t, la);
		unsigned eb = debounce_update(&cfg, &b, t, lb);
		pa += !!(ea & DEBOUNCE_PRESS), ra += !!(ea & DEBOUNCE_RELEASE);
		pb += !!(eb & DEBOUNCE_PRESS), rb += !!(eb & DEBOUNCE_RELEASE);
		if (ea & DEBOUNCE_PRESS)
			assert_int_equal(t, 109 + 30);
		if (eb & DEBOUNCE_RELEASE)
			assert_int_equal(t, 430);
	}
	assert_int_equal(pa + pb + ra + rb, 4);
	assert_int_equal(pa, 1);
	assert_int_equal(pb, 1);
}

/* Timestamps going backwards (events read out of order, clocks stepped):
 * no spurious event, and no debounce or long press completes early. */
static void test_time_going_backwards(void **state)
{
	(void)state;
	debounce_data d;
	debounce_init(&d, 0, 1000);
	assert_int_equal(debounce_update(&cfg, &d, 1000, 1), 0);
	/* an edge stamped before the last one: counted as "now", not earlier */
	assert_int_equal(debounce_update(&cfg, &d, 500, 0), 0);
	assert_int_equal(debounce_update(&cfg, &d, 400, 1), 0);
	assert_int_equal(debounce_update(&cfg, &d, 0, DEBOUNCE_TICK), 0);
	assert_int_equal(debounce_update(&cfg, &d, 1029, DEBOUNCE_TICK), 0);
	assert_int_equal(debounce_update(&cfg, &d, 1030, DEBOUNCE_TICK), DEBOUNCE_PRESS);
	/* a burst of stale ticks changes nothing */
	for (uint64_t t = 0; t < 1030; t += 7)
		assert_int_equal(debounce_update(&cfg, &d, t, DEBOUNCE_TICK), 0);
	assert_int_equal(debounce_update(&cfg, &d, 1799, DEBOUNCE_TICK), 0);
	assert_int_equal(debounce_update(&cfg, &d, 1800, DEBOUNCE_TICK), DEBOUNCE_LONG);
	/* a stale release followed by a stale press: a 0 ms glitch */
	assert_int_equal(debounce_update(&cfg, &d, 10, 0), 0);
	assert_int_equal(debounce_update(&cfg, &d, 5, 1), 0);
	assert_int_equal(debounce_update(&cfg, &d, 5000, DEBOUNCE_TICK), 0);
	assert_int_equal(d.stable, 1);
}

static void test_held_at_boot_and_deadlines(void **state)
{
	(void)state;
	debounce_data d;
	uint64_t at;
	debounce_init(&d, 1, 0);
	assert_int_equal(debounce_next_deadline(&cfg, &d, &at), 0);
	assert_int_equal(debounce_update(&cfg, &d, 5000, DEBOUNCE_TICK), 0); /* no long press */
	assert_int_equal(debounce_update(&cfg, &d, 5000, 0), 0);
	assert_int_equal(debounce_next_deadline(&cfg, &d, &at), 1);
	assert_int_equal(at, 5030);
	assert_int_equal(debounce_update(&cfg, &d, 5030, DEBOUNCE_TICK), DEBOUNCE_RELEASE);
	debounce_update(&cfg, &d, 6000, 1);
	debounce_update(&cfg, &d, 6030, DEBOUNCE_TICK);
	assert_int_equal(debounce_next_deadline(&cfg, &d, &at), 1);
	assert_int_equal(at, 6800);
	/* no debounce time: levels count at once */
	debounce_config zero = { 0, 0 };
	debounce_init(&d, 0, 0);
	assert_int_equal(debounce_update(&zero, &d, 7, 1), DEBOUNCE_PRESS);
	assert_int_equal(debounce_update(&zero, &d, 9000, DEBOUNCE_TICK), 0); /* long press off */
	assert_int_equal(debounce_update(&zero, &d, 9000, 0), DEBOUNCE_RELEASE);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_clean_press_after_debounce_time),
		cmocka_unit_test(test_chatter_gives_one_press_one_release),
		cmocka_unit_test(test_short_glitches_ignored),
		cmocka_unit_test(test_long_press_once_then_release),
		cmocka_unit_test(test_release_near_long_deadline),
		cmocka_unit_test(test_two_buttons_at_once),
		cmocka_unit_test(test_time_going_backwards),
		cmocka_unit_test(test_held_at_boot_and_deadlines),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
