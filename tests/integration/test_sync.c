/* Many screens, one performance (skinplay --sync=clock): instances started
 * at different wall times (faketime sets each one's clock) render the same
 * picture at the same wall time, pixel for pixel; one paused for two
 * seconds joins the clock again within a second, crossfading; a bad
 * --epoch is refused. Headless on the default show, HUD off. Skipped
 * without faketime (apt-get install faketime). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_paths.h"
#include "test_run.h"

#define RATE 60
#define FRAMES 420
#define EVERY 10

static int have_faketime(void)
{
	if (test_run("command -v faketime >/dev/null") == 0)
		return 1;
	print_message("faketime not installed (apt-get install faketime)\n");
	return 0;
}

/* One instance started at 12:00:SS (the clock frozen there while it
 * starts; its own monotonic clock runs), frames in DIR; extra options.
 * Returns its first frame's display frame counted from the epoch. */
static long instance(const char *dir, double ss, const char *extra)
{
	const char *log = test_scratch("sync.log");
	int st = test_run("FAKETIME_DONT_FAKE_MONOTONIC=1 faketime -f '2026-01-01 12:00:%06.3f' %s --image %s "
			  "--platform surfaceless --sync=clock --epoch=2026-01-01T00:00:00Z --size 160x90 --hud=off "
			  "--algo=dqbs --display-rate=%d --frames %d --every %d --out '%s' %s 2>'%s'",
			  ss, test_tool_path("skinplay"), test_tool_path("assets/demo.skn"), RATE, FRAMES, EVERY, dir, extra, log);
	char *text = test_read_file(log, NULL);
	assert_non_null(text);
	const char *at = strstr(text, "display frame ");
	long first = at ? strtol(at + 14, NULL, 10) : -1;
	if (st != 0 || first < 0)
		fail_msg("skinplay exited %d:\n%s", st, text);
	free(text);
	return first;
}

/* Whether frame a of dir_a and frame b of dir_b are the same PNG. */
static int same_frame(const char *dir_a, long a, const char *dir_b, long b)
{
	return test_run("cmp -s '%s/frame_%06ld.png' '%s/frame_%06ld.png'", dir_a, a, dir_b, b) == 0;
}

/* Of dir_b's frames written, those whose wall time dir_a also wrote:
 * how many, and how many of them differ. first_*: their display frames
 * since the epoch. */
static void compare_runs(const char *dir_a, long first_a, const char *dir_b, long first_b, int *common, int *differ)
{
	*common = *differ = 0;
	for (long b = 0; b < FRAMES; b += EVERY) {
		long a = first_b + b - first_a;
		if (a < 0 || a >= FRAMES || a % EVERY)
			continue;
		(*common)++;
		*differ += !same_frame(dir_a, a + 1, dir_b, b + 1);
	}
}

static void test_instances_in_lock_step(void **state)
{
	(void)state;
	if (!have_faketime())
		skip();
	const char *a = test_scratch("a"), *b = test_scratch("b"), *c = test_scratch("c");
	long fa = instance(a, 0.0, ""), fb = instance(b, 2.5, ""), fc = instance(c, 4.0, "");
	assert_int_equal(fb - fa, 150); /* 2.5 s at 60 Hz, on the epoch's grid */
	assert_int_equal(fc - fa, 240);
	int common, differ;
	compare_runs(a, fa, b, fb, &common, &differ);
	print_message("started 2.5 s apart: %d frames at the same wall times, %d differ\n", common, differ);
	assert_true(common >= 20);
	assert_int_equal(differ, 0);
	compare_runs(a, fa, c, fc, &common, &differ);
	print_message("started 4 s apart: %d frames at the same wall times, %d differ\n", common, differ);
	assert_true(common >= 15);
	assert_int_equal(differ, 0);
	/* and the pictures are a show, not one pose: the first and last differ */
	assert_false(same_frame(a, 1, a, FRAMES - EVERY + 1));
}

/* Paused from 1 s to 3 s (a local PLAY): the frames paused differ from an
 * instance that played on, and within a second of the resume (the 300 ms
 * crossfade) they are the same again. */
static void test_paused_instance_rejoins(void **state)
{
	(void)state;
	if (!have_faketime())
		skip();
	const char *a = test_scratch("a"), *p = test_scratch("p"), *script = test_scratch("pause.txt");
	char extra[512];
	test_write_text(script, "1000 PLAY press\n1010 PLAY release\n3000 PLAY press\n3010 PLAY release\n");
	snprintf(extra, sizeof extra, "--input script:%s", script);
	long fa = instance(a, 0.0, ""), fp = instance(p, 0.0, extra);
	assert_int_equal(fa, fp);
	int paused = 0, paused_differ = 0, joined_at = -1;
	for (long k = 0; k < FRAMES; k += EVERY) {
		int same = same_frame(a, k + 1, p, k + 1);
		if (k >= 70 && k < 180) { /* from a frame after the pause to the resume */
			paused++;
			paused_differ += !same;
		}
		if (k >= 180 && same && joined_at < 0)
			joined_at = (int)k;
		if (joined_at >= 0 && !same)
			fail_msg("frame %ld differs after the join at frame %d", k + 1, joined_at + 1);
	}
	print_message("paused 2 s: %d of %d frames paused differ; joined %d ms after the resume\n", paused_differ,
		      paused, (joined_at - 180) * 1000 / RATE);
	assert_int_equal(paused_differ, paused);
	assert_true(joined_at >= 180 && joined_at <= 180 + RATE);
	char *log = test_read_file(test_scratch("sync.log"), NULL);
	assert_non_null(log);
	assert_non_null(strstr(log, "behind the show's clock (after a pause, a stop or a stall): joined it"));
	free(log);
}

static void test_bad_epoch_refused(void **state)
{
	(void)state;
	const char *log = test_scratch("epoch.log");
	assert_int_equal(test_run("%s --image %s --platform none --sync=clock --epoch=2026-13-01T00:00:00Z 2>'%s'",
				  test_tool_path("skinplay"), test_tool_path("assets/demo.skn"), log),
			 1);
	static const char *const said[] = { "--epoch expects an ISO 8601 UTC time such as 2026-01-01T00:00:00Z",
					    "'2026-13-01T00:00:00Z'", NULL };
	test_assert_contains_all(log, said);
	assert_int_equal(test_run("%s --image %s --platform none --sync=sometimes 2>'%s'", test_tool_path("skinplay"),
				  test_tool_path("assets/demo.skn"), log),
			 1);
	static const char *const sync[] = { "--sync expects off or clock", NULL };
	test_assert_contains_all(log, sync);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_instances_in_lock_step),
		cmocka_unit_test(test_paused_instance_rejoins),
		cmocka_unit_test(test_bad_epoch_refused),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
