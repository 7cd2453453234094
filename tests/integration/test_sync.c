/* Many screens, one performance (skinplay --sync=clock): instances started
 * at different wall times (faketime sets each one's clock) render the same
 * picture at the same wall time, pixel for pixel; one paused for two
 * seconds joins the clock again within a second, crossfading; three
 * screens of a wall (--wall) stitched equal one render at the wall's size,
 * with bezels too; a bad --epoch, --sync or --wall is refused. Headless on the default show, HUD off. Skipped
 * without faketime (apt-get install faketime). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "png_writer.h"
#include "test_paths.h"
#include "test_run.h"
#include "test_xvfb.h"

#define RATE 60
#define FRAMES 420
#define EVERY 10

static int have_faketime(void)
{
	/* libfaketime is preloaded: under ASan (SANITIZE=1) its runtime is then
	 * not the first library, which it refuses unless told */
	setenv("ASAN_OPTIONS", "verify_asan_link_order=0:detect_leaks=0", 1);
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
	assert_non_null(strstr(log, "behind the show's clock (after a pause): joined it"));
	free(log);
}

#define TILE_W 160
#define TILE_H 90
#define BEZEL 12

/* One picture at 12:00:20 on the clock, travelling (the figure's own way):
 * the whole wall's width, or tile --wall=3x1+X+0, into name/. */
static void wall_frame(const char *name, int tile, int bezel)
{
	char wall[64] = "", size[32];
	int whole_w = 3 * TILE_W + 2 * bezel;
	snprintf(size, sizeof size, "%dx%d", tile < 0 ? whole_w : TILE_W, TILE_H);
	/* the whole: a wall of one screen its size (the same camera: on the
	 * clip's start, the picture running on across without bands) */
	if (tile >= 0)
		snprintf(wall, sizeof wall, "--wall=3x1+%d+0 --bezel=%d", tile, bezel);
	else
		snprintf(wall, sizeof wall, "--wall=1x1+0+0");
	assert_int_equal(test_run("FAKETIME_DONT_FAKE_MONOTONIC=1 faketime -f '2026-01-01 12:00:20' %s --image %s "
				  "--platform surfaceless --sync=clock --root=travel --size %s --hud=off --algo=dqbs "
				  "--frames 1 --out '%s' %s 2>/dev/null",
				  test_tool_path("skinplay"), test_tool_path("assets/demo.skn"), size, test_scratch(name), wall),
			 0);
}

static uint8_t whole_px[4 * (3 * TILE_W + 2 * BEZEL) * TILE_H], tile_px[4 * TILE_W * TILE_H];

static int read_frame(const char *name, uint8_t *px, int cap, int *w, int *h)
{
	char path[600];
	skp_error err;
	snprintf(path, sizeof path, "%s/frame_000001.png", test_scratch(name));
	return png_read_rgba(path, px, cap, w, h, &err);
}

/* Tiles stitched (a bezel's columns skipped between them) against the
 * whole: pixels that differ by more than 24 in a channel. */
static int stitched_differ(int bezel, int *body)
{
	int ww, wh, tw, th, differ = 0;
	*body = 0;
	assert_int_equal(read_frame("whole", whole_px, (int)sizeof whole_px, &ww, &wh), 0);
	assert_int_equal(ww, 3 * TILE_W + 2 * bezel);
	for (int t = 0; t < 3; t++) {
		char name[16];
		snprintf(name, sizeof name, "tile%d", t);
		assert_int_equal(read_frame(name, tile_px, (int)sizeof tile_px, &tw, &th), 0);
		assert_true(tw == TILE_W && th == TILE_H && wh == TILE_H);
		for (int y = 0; y < TILE_H; y++)
			for (int x = 0; x < TILE_W; x++) {
				const uint8_t *a = tile_px + 4 * (y * TILE_W + x);
				const uint8_t *b = whole_px + 4 * (y * ww + t * (TILE_W + bezel) + x);
				int m = 0;
				for (int c = 0; c < 3; c++)
					m = abs(a[c] - b[c]) > m ? abs(a[c] - b[c]) : m;
				differ += m > 24;
				*body += a[0] > 120 && a[0] > a[2] + 20; /* the skin's warm pixels */
			}
	}
	return differ;
}

static void test_wall_tiles_equal_whole(void **state)
{
	(void)state;
	if (!have_faketime())
		skip();
	for (int bezel = 0; bezel <= BEZEL; bezel += BEZEL) {
		wall_frame("whole", -1, bezel);
		for (int t = 0; t < 3; t++) {
			char name[16];
			snprintf(name, sizeof name, "tile%d", t);
			wall_frame(name, t, bezel);
		}
		int body, differ = stitched_differ(bezel, &body);
		print_message("3x1 wall, bezel %d px: %d of %d pixels of the stitched tiles differ from the whole by more "
			      "than 24 (%d pixels of skin)\n", bezel, differ, 3 * TILE_W * TILE_H, body);
		assert_true(body > 100);
		assert_true(differ <= 3 * TILE_W * TILE_H / 1000);
	}
}

static double seconds_now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The stall a log said at offset at ("sync: 2.01 s without a frame"). */
static double stall_said(const char *text, long at)
{
	double behind = 0;
	const char *line = at >= 0 ? strstr(text + at, "sync: ") : NULL;
	if (line)
		sscanf(line, "sync: %lf", &behind);
	return behind;
}

/* A window on the wall clock (x11 under Xvfb) stopped for two seconds
 * (SIGSTOP, SIGCONT: a stall) joins the show's clock again, crossfading,
 * and says how far behind it was: at least the stop, at most the time
 * since its frames were seen running. Only what it said after the stop
 * counts: a loaded machine may stall it before (its first frames). */
static void test_stopped_window_rejoins(void **state)
{
	(void)state;
	char name[32], display[64], shown[64];
	pid_t x = test_xvfb_start("320x240x24", name, sizeof name);
	if (!x) {
		print_message("Xvfb not installed or did not start (apt-get install xvfb)\n");
		skip();
	}
	const char *log = test_scratch("window.log");
	snprintf(display, sizeof display, "DISPLAY=%s", name);
	snprintf(shown, sizeof shown, "%s", log);
	pid_t pid = fork();
	if (pid == 0) {
		FILE *err = freopen(shown, "w", stderr);
		(void)err;
		putenv(display);
		execl(test_tool_path("skinplay"), "skinplay", "--image", test_tool_path("assets/demo.skn"), "--platform",
		      "x11", "--size", "160x90", "--sync=clock", "--algo=dqbs", "--input", "none", (char *)NULL);
		_exit(127);
	}
	long started = test_wait_for_text_after(log, 0, "sync: the show follows the wall clock", 60.0);
	/* a second's frame line: the loop is drawing */
	long running = test_wait_for_text_after(log, started < 0 ? 0 : started, "\nframe ", 60.0);
	double seen = seconds_now();
	sleep(1);
	long before = test_file_size(log);
	kill(pid, SIGSTOP);
	sleep(2);
	kill(pid, SIGCONT);
	long joined = test_wait_for_text_after(log, before, "without a frame (a stop or a stall): joined the show's clock",
					       20.0);
	double waited = seconds_now() - seen;
	kill(pid, SIGTERM);
	int status;
	waitpid(pid, &status, 0);
	test_xvfb_stop(x);
	char *text = test_read_file(log, NULL);
	assert_non_null(text);
	long line = joined;
	while (line > 0 && text[line - 1] != '\n')
		line--;
	double behind = stall_said(text, joined < 0 ? -1 : line);
	print_message("stopped 2 s: %s; %.2f s without a frame (%.2f s since its frames ran)\n",
		      joined >= 0 ? "joined the clock" : "NOT joined", behind, waited);
	int clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
	if (started < 0 || running < 0 || joined < 0 || !(behind >= 1.9 && behind <= waited + 0.2) || !clean) {
		print_message("its log:\n%s", text);
		fail_msg("skinplay %s %d after SIGTERM; started %d, drawing %d, joined %d, %.2f s behind (between 1.9 and "
			 "%.2f expected)",
			 WIFSIGNALED(status) ? "killed by signal" : "exited",
			 WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status), started >= 0, running >= 0,
			 joined >= 0, behind, waited + 0.2);
	}
	free(text);
}

/* Skin pixels of one picture with the board's [camera] (text, or none). */
static int skin_with_camera(const char *name, const char *camera)
{
	char extra[600] = "";
	int w, h, skin = 0;
	if (camera) {
		const char *board = test_scratch("camera.ini");
		test_write_text(board, camera);
		snprintf(extra, sizeof extra, "--board '%s'", board);
	}
	assert_int_equal(test_run("%s --image %s --platform surfaceless --size %dx%d --hud=off --algo=dqbs --frames 1 "
				  "--out '%s' %s 2>/dev/null", test_tool_path("skinplay"), test_tool_path("assets/demo.skn"),
				  TILE_W, TILE_H, test_scratch(name), extra),
			 0);
	assert_int_equal(read_frame(name, tile_px, (int)sizeof tile_px, &w, &h), 0);
	for (int i = 0; i < w * h; i++)
		skin += tile_px[4 * i] > 120 && tile_px[4 * i] > tile_px[4 * i + 2] + 20;
	return skin;
}

/* Each screen its view: the board's [camera] moves this one's camera
 * (twice as far: about a quarter of the skin; from above: another picture). */
static void test_camera_of_the_board(void **state)
{
	(void)state;
	int usual = skin_with_camera("usual", NULL), far = skin_with_camera("far", "[camera]\ndistance = 2\n");
	int above = skin_with_camera("above", "[camera]\npitch = 60\ntarget = 0, -0.2, 0\n");
	print_message("skin pixels: usual %d, [camera] distance 2: %d, pitch 60: %d\n", usual, far, above);
	assert_true(usual > 400);
	assert_true(far > usual / 8 && far < usual / 2);
	assert_true(above > 100);
	assert_false(test_run("cmp -s '%s/frame_000001.png' '%s/frame_000001.png'", test_scratch("usual"),
			      test_scratch("above")) == 0);
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
	assert_int_equal(test_run("%s --image %s --platform none --wall=3x1+3+0 2>'%s'", test_tool_path("skinplay"),
				  test_tool_path("assets/demo.skn"), log),
			 1);
	static const char *const wall[] = { "--wall expects COLUMNSxROWS+COLUMN+ROW", "'3x1+3+0'", NULL };
	test_assert_contains_all(log, wall);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_instances_in_lock_step),
		cmocka_unit_test(test_paused_instance_rejoins),
		cmocka_unit_test(test_wall_tiles_equal_whole),
		cmocka_unit_test(test_stopped_window_rejoins),
		cmocka_unit_test(test_camera_of_the_board),
		cmocka_unit_test(test_bad_epoch_refused),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
