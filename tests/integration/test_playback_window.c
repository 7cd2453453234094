/* skinplay against the wall clock (needs a display: under qemu-user it is
 * skipped, board/rpi4/board.mk):
 * - in a desktop window (x11 under Xvfb) at 320x240 and 1600x900 the
 *   captured frame shown advances at the clip's rate per second of wall
 *   time (its log lines, timed here as they arrive), for a 120 Hz AMC and a
 *   30 Hz BVH, however fast the window draws;
 * - yaw = auto turns the camera to the clip's mean facing. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "test_paths.h"
#include "test_run.h"
#include "test_xvfb.h"

static double wall_s(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#define MAX_LINES 64

/* Runs skinplay (argv) with its stderr on a pipe until it has logged
 * `want` "frame N:" lines (once a second each) or `seconds` have passed
 * (a slow start under a sanitizer), every line timed as it arrives. Returns the captured frames a
 * second of wall time: the least-squares slope of frame number over
 * arrival time from the second line on (the first second includes
 * start-up), so that how long each frame took to draw before its line
 * came out averages away. */
static double frames_per_wall_second(char *const argv[], int want, double seconds, int *lines, double *fps)
{
	int fds[2];
	assert_int_equal(pipe(fds), 0);
	pid_t pid = fork();
	if (pid == 0) {
		dup2(fds[1], 2);
		close(fds[0]);
		execv(argv[0], argv);
		_exit(127);
	}
	close(fds[1]);
	char buf[8192];
	size_t have = 0;
	/* what it says besides the frame lines, for a failure */
	const char *log = test_scratch("window.log");
	FILE *said = fopen(log, "w");
	assert_non_null(said);
	double t0 = wall_s(), t[MAX_LINES], n[MAX_LINES];
	*lines = 0;
	*fps = 0;
	int stopped = 0;
	for (;;) {
		if (!stopped && (*lines >= want || wall_s() - t0 > seconds)) {
			kill(pid, SIGTERM); /* a kiosk's clean exit */
			stopped = 1;
		}
		struct pollfd p = { .fd = fds[0], .events = POLLIN };
		if (poll(&p, 1, 100) <= 0)
			continue;
		ssize_t got = read(fds[0], buf + have, sizeof buf - 1 - have);
		if (got <= 0)
			break;
		have += (size_t)got;
		buf[have] = 0;
		char *nl;
		while ((nl = strchr(buf, '\n')) != NULL) {
			*nl = 0;
			long frame;
			double f;
			if (sscanf(buf, "frame %ld: clip %*f s, %lf fps", &frame, &f) == 2 && !stopped && *lines < MAX_LINES) {
				t[*lines] = wall_s();
				n[*lines] = (double)frame;
				++*lines;
				*fps = f;
			} else if (strncmp(buf, "frame ", 6) != 0) {
				fprintf(said, "%s\n", buf);
			}
			memmove(buf, nl + 1, have - (size_t)(nl + 1 - buf) + 1);
			have -= (size_t)(nl + 1 - buf);
		}
	}
	close(fds[0]);
	fclose(said);
	int status;
	waitpid(pid, &status, 0);
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
		char *text = test_read_file(log, NULL);
		fail_msg("%s %s %d after %.1f s and %d frame lines; what else it said:\n%s", argv[0],
			 WIFEXITED(status) ? "exited with" : "was killed by signal",
			 WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status), wall_s() - t0, *lines,
			 text ? text : "");
	}
	double st = 0, sn = 0, stt = 0, stn = 0, k = *lines - 1;
	for (int i = 1; i < *lines; i++) {
		st += t[i];
		sn += n[i];
		stt += t[i] * t[i];
		stn += t[i] * n[i];
	}
	double var = k * stt - st * st;
	return k >= 3 && var > 0 ? (k * stn - st * sn) / var : 0;
}

static void test_window_plays_at_the_captured_rate(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	char name[16], asf[1024], amc[1024], bvh[1024];
	pid_t x = test_xvfb_start("1600x900x24", name, sizeof name);
	if (!x) {
		print_message("Xvfb not installed or did not start (apt-get install xvfb)\n");
		skip();
	}
	snprintf(asf, sizeof asf, "%s", test_data_path("mocap/cmu/135.asf"));
	snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/135_06.amc"));
	/* a 30 Hz BVH: the walk's frames at a quarter of the rate */
	snprintf(bvh, sizeof bvh, "%s", test_scratch("walk30.bvh"));
	assert_int_equal(test_run("%s convert '%s' '%s' --fps=30 -o '%s' -q", test_tool_path("skintool"),
				  test_data_path("mocap/cmu/02.asf"), test_data_path("mocap/cmu/02_01.amc"), bvh), 0);
	setenv("DISPLAY", name, 1);
	static const char *const sizes[] = { "320x240", "1600x900" };
	for (int k = 0; k < 4; k++) {
		/* under the sanitizers or an emulator each size and each rate
		 * once (the AMC small, the BVH large): CI runs this alone, at
		 * its end, 7 s of wall time a run */
		if (test_slow() && (k == 1 || k == 2))
			continue;
		char play[1024];
		snprintf(play, sizeof play, "%s", test_tool_path("skinplay"));
		char *argv_amc[] = { play, "--asf", asf, "--amc", amc, "--platform", "x11", "--size", (char *)sizes[k % 2],
				     "--input", "none", NULL };
		char *argv_bvh[] = { play, "--bvh", bvh, "--platform", "x11", "--size", (char *)sizes[k % 2], "--input",
				     "none", NULL };
		double want = k < 2 ? 120.0 : 30.0, fps;
		int lines;
		double got = frames_per_wall_second(k < 2 ? argv_amc : argv_bvh, 7, 90.0, &lines, &fps);
		print_message("x11 %s, %s at %.0f Hz: %.1f captured frames a second of wall time (%.3fx; the window "
			      "drew %.1f frames a second; %d log lines)\n", sizes[k % 2], k < 2 ? "135_06.amc" : "02_01 as a BVH",
			      want, got, got / want, fps, lines);
		if (fabs(got / want - 1.0) > 0.05)
			fail_msg("%.1f frames a second, not %.0f within 5%% (%d log lines)", got, want, lines);
	}
	unsetenv("DISPLAY");
	test_xvfb_stop(x);
}

/* The camera's turn skinplay logs for a clip ("camera yaw N degrees"). */
static int logged_yaw(const char *motion_args)
{
	const char *log = test_scratch("yaw.log");
	assert_int_equal(test_run("%s %s --platform surfaceless --size 64x36 --frames 1 2>'%s' >/dev/null",
				  test_tool_path("skinplay"), motion_args, log), 0);
	size_t n;
	char *text = test_read_file(log, &n), *at = text ? strstr(text, "camera yaw ") : NULL;
	int deg = 9999;
	assert_non_null(at);
	assert_int_equal(sscanf(at, "camera yaw %d degrees", &deg), 1);
	free(text);
	return deg;
}

/* yaw = auto: a clip captured facing away (assimp-testmodels' boxer) is
 * seen from the front, a walk towards +z from where it always was. */
static void test_camera_faces_the_clip(void **state)
{
	(void)state;
	char args[2048];
	const char *boxer = "/usr/share/assimp/models/BVH/Boxing_Toes.bvh";
	if (access(boxer, R_OK) == 0) {
		snprintf(args, sizeof args, "--bvh '%s'", boxer);
		int deg = logged_yaw(args);
		print_message("Boxing_Toes.bvh: camera yaw %d degrees\n", deg);
		assert_true(abs(deg) >= 150);
	} else
		print_message("assimp-testmodels not installed: the boxer is not tried\n");
	if (!test_data_path("mocap"))
		return;
	snprintf(args, sizeof args, "--asf '%s'", test_data_path("mocap/cmu/02.asf"));
	snprintf(args + strlen(args), sizeof args - strlen(args), " --amc '%s'", test_data_path("mocap/cmu/02_01.amc"));
	int walk = logged_yaw(args);
	print_message("02_01: camera yaw %d degrees\n", walk);
	assert_true(abs(walk) <= 30);
	strcat(args, " --yaw=-45");
	assert_int_equal(logged_yaw(args), -45);
}

/* Keys pressed in the window, as a user would (xdotool under Xvfb), each
 * doing what the legend says: 2 picks DQBS, d the difference view and
 * back, v the next view, space pauses, the right arrow steps a frame, ]
 * seeks a second, + doubles the speed, n the next clip; a drag turns the
 * camera, the wheel brings it nearer, a right drag moves its aim, f frames
 * the body again, r resets; l (a console's camera key) turns it, shift
 * and k moves it up; q quits (exit 0). */
static void test_window_keys(void **state)
{
	(void)state;
	char name[16];
	if (test_run("command -v xdotool >/dev/null") != 0) {
		print_message("xdotool not installed (apt-get install xdotool)\n");
		skip();
	}
	pid_t x = test_xvfb_start("640x480x24", name, sizeof name);
	if (!x)
		skip();
	const char *log = test_scratch("keys.log");
	/* each key once the one before it shows in the log (up to 30 s: a
	 * sanitizer build under a parallel test run starts slowly) */
	int rc = test_run("export DISPLAY=%s; log='%s'; "
			  "seen() { for i in $(seq 300); do grep -q \"$1\" \"$log\" && return 0; sleep 0.1; done; return 1; }; "
			  "%s --image %s --platform x11 --size 320x240 --input none --algo compare --loop clip "
			  "2>\"$log\" & pid=$!; seen '^display: x11' && sleep 0.5 && xdotool mousemove 160 120 && "
			  "xdotool key 2 && seen 'key 2 -> dqbs' && xdotool key d && seen 'key d -> difference' && "
			  "xdotool key d && seen 'key d -> body' && xdotool key v && seen 'VIEW -> ' && "
			  "xdotool key space && seen 'PLAY -> pause' && xdotool key Right && seen 'key right -> frame' && "
			  "xdotool key bracketright && seen 'key ] -> ' && xdotool key plus && seen 'speed 2' && "
			  "xdotool key n && seen 'NEXT -> ' && "
			  "xdotool mousemove 160 120 mousedown 1 mousemove_relative -- 60 20 sleep 0.2 mouseup 1 && "
			  "seen 'drag -> camera yaw -' && xdotool click 4 && seen 'wheel -> .*distance 0.85' && "
			  "xdotool mousedown 3 mousemove_relative -- 30 0 sleep 0.2 mouseup 3 && seen 'drag -> .*aim -0' && "
			  "xdotool key f && seen 'key f -> .*distance 1.00, aim 0.00 0.00 0.00' && xdotool key r && "
			  "seen 'key r -> camera yaw +0' && xdotool key l && seen 'camera key -> camera yaw -15' && "
			  "xdotool key shift+k && seen 'camera key -> .*aim 0.00 0.06' && xdotool key q || kill $pid; wait $pid",
			  name, log, test_tool_path("skinplay"), test_tool_path("assets/demo.skn"));
	test_xvfb_stop(x);
	if (rc != 0) {
		char *text = test_read_file(log, NULL);
		fail_msg("exit %d; log:\n%s", rc, text ? text : "");
	}
	static const char *const want[] = { "input: key 2 -> dqbs", "input: key d -> difference", "input: key d -> body",
					    "input: VIEW -> ", "input: PLAY -> pause", "input: key right -> frame",
					    "input: key ] -> ", "input: key + -> speed 2", "input: NEXT -> ", NULL };
	test_assert_contains_all(log, want);
}

/* The same keys on a terminal (--input keyboard: a console has no
 * window), typed into a pseudo-terminal as a user would (util-linux's
 * script): 2 DQBS, d the difference view, space pauses, the right arrow
 * (an escape sequence) steps a frame, the camera's keys turn, zoom and
 * move it (no pointer on a console), q quits a run of 3,000 frames before
 * its end (exit 0). The terminal stays open until skinplay has ended. */
static void test_console_keys(void **state)
{
	(void)state;
	if (test_run("command -v script >/dev/null") != 0) {
		print_message("script not installed (util-linux)\n");
		skip();
	}
	const char *log = test_scratch("console.log");
	int rc = test_run("log='%s'; "
			  "seen() { for i in $(seq 300); do grep -q \"$1\" \"$log\" 2>/dev/null && return 0; sleep 0.1; done; return 1; }; "
			  "( seen '^display: ' && printf 2 && seen 'key 2 -> dqbs' && printf d && seen 'key d -> difference' && "
			  "printf ' ' && seen 'PLAY -> pause' && printf '\\033[C' && seen 'key right -> frame' && "
			  "printf l && seen 'camera key -> camera yaw -15' && printf z && seen 'distance 0.85' && "
			  "printf K && seen 'aim 0.00 0.05' && printf q; seen '^played ' ) | timeout 300 "
			  "script -qfec \"ASAN_OPTIONS=detect_leaks=0 %s --image %s --platform surfaceless --size 160x120 "
			  "--input keyboard --frames 3000 2>$log\" /dev/null >/dev/null",
			  log, test_tool_path("skinplay"), test_tool_path("assets/demo.skn"));
	/* the log's text freed before any assertion, which jumps out */
	char *text = test_read_file(log, NULL);
	int ran_out = text && strstr(text, "played 3000 frames");
	if (rc != 0) {
		print_message("log:\n%s", text ? text : "");
		free(text);
		fail_msg("exit %d (the log above)", rc);
	}
	free(text);
	static const char *const want[] = { "input: key 2 -> dqbs", "input: key d -> difference", "input: PLAY -> pause",
					    "input: key right -> frame", "input: camera key -> camera yaw -15, pitch",
					    "distance 0.85, aim 0.00 0.00 0.00", "distance 0.85, aim 0.00 0.05 0.00", NULL };
	test_assert_contains_all(log, want);
	/* q ended it, before its 3,000 frames */
	assert_false(ran_out);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_camera_faces_the_clip),
		cmocka_unit_test(test_window_plays_at_the_captured_rate),
		cmocka_unit_test(test_window_keys),
		cmocka_unit_test(test_console_keys),
	};
	return cmocka_run_group_tests_name("playback_window", tests, test_scratch_setup, test_scratch_teardown);
}
