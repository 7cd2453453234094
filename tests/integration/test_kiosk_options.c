/* How the kiosk plays, through the real skinplay: an image's clips in
 * turn (loop = show) or the first alone (loop = clip); --report-timing's
 * table and summary agree; the board's [skin] threads and split_verts
 * give the pixels of one thread; --streams compact gives the float
 * streams' picture within 1% of the pixels. Buttons, the board config and
 * systemd: test_kiosk.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_kiosk_run.h"
#include "test_paths.h"

static kiosk_image a, b;

/* --report-timing: a row per stage, means that add up to the frame's; the
 * summary line's figures are the same record's (decode = decode and pose,
 * skin = bone transforms + skinning, upload, draw). */
static void test_report_timing(void **state)
{
	(void)state;
	assert_int_equal(kiosk_run("t", "--report-timing", 20), 0);
	char *log = kiosk_read_log();
	static const char *const stages[] = { "decode and pose", "bone transforms", "skinning (CPU)",
					      "upload", "draw", "swap / present" };
	const char *table = strstr(log, "timing over 20 frames");
	if (!table)
		fail_msg("no timing table in:\n%s", log);
	double sum = 0, frame = 0, mean[6], worst;
	for (size_t i = 0; i < sizeof stages / sizeof stages[0]; i++) {
		const char *row = strstr(table, stages[i]);
		assert_non_null(row);
		assert_int_equal(sscanf(row + strlen(stages[i]), "%lf %lf", &mean[i], &worst), 2);
		assert_true(mean[i] >= 0 && worst >= mean[i]);
		sum += mean[i];
	}
	const char *last = strstr(table, "\n  frame ");
	assert_non_null(last);
	assert_int_equal(sscanf(last + 9, "%lf", &frame), 1);
	assert_true(frame > 0 && fabs(sum - frame) <= 0.01 + 0.001 * frame);
	const char *played = strstr(log, "per frame decode ");
	double d, sk, up, dr;
	assert_non_null(played);
	assert_int_equal(sscanf(played, "per frame decode %lf ms, skin %lf ms, upload %lf ms, draw %lf ms", &d, &sk, &up, &dr),
			 4);
	if (fabs(d - mean[0]) > 0.006 || fabs(sk - mean[1] - mean[2]) > 0.011 || fabs(up - mean[3]) > 0.006 ||
	    fabs(dr - mean[4]) > 0.006)
		fail_msg("the summary line (%.2f %.2f %.2f %.2f ms) is not the table's record", d, sk, up, dr);
	free(log);
}

/* The board's [skin] threads share the mesh between threads (here from
 * one vertex on, as a big mesh would): every frame the same pixels as one
 * thread's, and the summary says how many skinned. A small mesh under the
 * default split_verts stays on one thread; split_verts = auto measures. */
static void test_skinning_threads(void **state)
{
	(void)state;
	const char *ini = "[skin]\nthreads = 2\nsplit_verts = 1\n";
	assert_int_equal(kiosk_run_board("two", ini, "--algo compare", 12), 0);
	kiosk_expect_log("CPU skinning on 2 threads)");
	assert_int_equal(kiosk_run_board("one", ini, "--algo compare --threads 1", 30), 0);
	kiosk_expect_log("CPU skinning)");
	for (int n = 1; n <= 12; n += 11) {
		kiosk_load("two", n, &a);
		kiosk_load("one", n, &b);
		assert_int_equal(kiosk_image_diff(&a, &b), 0);
	}
	assert_int_equal(kiosk_run("auto", "--threads auto", 1), 0);
	kiosk_expect_log("CPU skinning)");
	/* split_verts = auto: the first frames measure two threads against
	 * one, the log says what they chose, and the frames are the same */
	const char *tuned = "[skin]\nthreads = 2\nsplit_verts = auto\n";
	assert_int_equal(kiosk_run_board("tuned", tuned, "--algo compare", 30), 0);
	kiosk_expect_log("skinplay: a kernel run took ");
	kiosk_expect_log(" on 2 threads, ");
	static const int frames[] = { 1, 12, 30 };
	for (int i = 0; i < 3; i++) {
		kiosk_load("tuned", frames[i], &a);
		kiosk_load("one", frames[i], &b);
		assert_int_equal(kiosk_image_diff(&a, &b), 0);
	}
	assert_int_equal(kiosk_run("bad", "--threads 0", 1), 1);
	kiosk_expect_log("--threads expects auto or 1..16, got '0'");
}

/* --streams compact: LBS and DQBS read the 16-bit streams and upload
 * 16-bit normals; the picture is the float streams' within a few pixels'
 * shading (quantisation moves a vertex by about 1e-5 of the body; the
 * compare view's close-up magnifies a joint several times, and its
 * shading with it: 390 pixels of 76,800 here, 0.2% before it). */
static void test_compact_streams(void **state)
{
	(void)state;
	assert_int_equal(kiosk_run("compact", "--algo compare --hud off --streams compact --start 200", 2), 0);
	kiosk_expect_log("CPU skinning, compact streams)");
	assert_int_equal(kiosk_run("float", "--algo compare --hud off --streams float --start 200", 2), 0);
	for (int n = 1; n <= 2; n++) {
		kiosk_load("compact", n, &a);
		kiosk_load("float", n, &b);
		long d = kiosk_image_diff(&a, &b);
		print_message("frame %d: %ld of %d pixels differ between compact and float streams\n", n, d, KIOSK_W * KIOSK_H);
		assert_true(d * 100 < KIOSK_W * KIOSK_H); /* under 1% */
	}
	assert_int_equal(kiosk_run("bad", "--streams tiny", 1), 1);
	kiosk_expect_log("tiny");
}

/* Runs skinplay headless on an image at 30 frames a second; returns the
 * log (the caller frees it) after checking the exit status. */
static char *play_image(const char *show, const char *more)
{
	char cmd[2048];
	snprintf(cmd, sizeof cmd, "ASAN_OPTIONS=detect_leaks=0 %s --image %s --platform surfaceless --size 64x36 "
		 "--display-rate 30 %s 2>%s", test_tool_path("skinplay"), show, more, kiosk_log_path);
	assert_int_equal(system(cmd), 0);
	return kiosk_read_log();
}

/* The clips' names in the order their "clip:" lines came, and the frames
 * played, from a log. */
static void clips_played(const char *log, char *order, size_t size, long *frames)
{
	order[0] = '\0';
	for (const char *p = strstr(log, "clip: "); p; p = strstr(p + 1, "clip: ")) {
		long n = 0;
		sscanf(p, "clip: %ld frames", &n);
		snprintf(order + strlen(order), size - strlen(order), "%s", n == 1140 ? "a" : n == 120 ? "b" : "?");
	}
	const char *played = strstr(log, "played ");
	*frames = -1;
	assert_non_null(played);
	sscanf(played, "played %ld frames", frames);
}

/* loop = show (the default): an image's clips play in turn, headless the
 * show once; loop = clip: the first clip alone, as before. */
static void test_show_plays_its_clips_in_turn(void **state)
{
	(void)state;
	char clip_a[128], clip_b[128], show[128], cmd[2048], order[16];
	snprintf(clip_a, sizeof clip_a, "%s/a.amc", kiosk_dir);
	snprintf(clip_b, sizeof clip_b, "%s/b.amc", kiosk_dir);
	snprintf(show, sizeof show, "%s/two.skn", kiosk_dir);
	char amc[512]; /* test_tool_path's buffer is shared */
	snprintf(amc, sizeof amc, "%s", test_tool_path("assets/demo.amc"));
	/* the demo's first 9.5 s and its first 1 s: lengths of their own, not
	 * the demo's, which changes with the tour; under the sanitizers or an
	 * emulator packed raw (the encoder took 9.6 s of this case's 19
	 * there; the show plays raw clips alike) */
	snprintf(cmd, sizeof cmd, "awk '/^[0-9]+$/ { n = $1 } n <= 1140' %s > %s && "
		 "awk '/^[0-9]+$/ { n = $1 } n <= 120' %s > %s && "
		 "%s pack%s -q assets/demo.asf %s %s -o %s >/dev/null", amc, clip_a, clip_a, clip_b,
		 test_tool_path("skintool"), test_slow() ? " --raw" : "", clip_a, clip_b, show);
	assert_int_equal(system(cmd), 0);
	long frames;
	/* 9.5 s and 1 s at 30 frames a second: 285 + 30 frames */
	char *log = play_image(show, "");
	clips_played(log, order, sizeof order, &frames);
	if (strcmp(order, "ab") || frames != 315)
		fail_msg("clips %s, %ld frames; log:\n%s", order, frames, log);
	/* the summary names what was played, not the last clip alone */
	assert_non_null(strstr(log, "played 315 frames of 2 clips in turn (a first, b last)"));
	free(log);
	/* on past the end, the show starts over */
	log = play_image(show, "--frames 330");
	clips_played(log, order, sizeof order, &frames);
	if (strcmp(order, "aba"))
		fail_msg("clips %s; log:\n%s", order, log);
	assert_non_null(strstr(log, "of 3 clips in turn (a first, a last)"));
	free(log);
	log = play_image(show, "--loop clip");
	clips_played(log, order, sizeof order, &frames);
	if (strcmp(order, "a") || frames != 286)
		fail_msg("--loop clip: clips %s, %ld frames; log:\n%s", order, frames, log);
	assert_non_null(strstr(log, "played 286 frames of a in"));
	free(log);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_show_plays_its_clips_in_turn),
		cmocka_unit_test(test_report_timing),
		cmocka_unit_test(test_skinning_threads),
		cmocka_unit_test(test_compact_streams),
	};
	return cmocka_run_group_tests(tests, kiosk_setup, kiosk_teardown);
}
