/* The kiosk through the real skinplay: scripted buttons switch the
 * algorithm at exactly the frames the script says (log lines and images),
 * pause and resume, cycle the view and show the visitor's PAUSED badge;
 * the board config sets the starting algorithm and view; systemd hears
 * READY=1 and WATCHDOG=1 on a socket the test opens, SIGHUP restarts the
 * show and SIGTERM ends it cleanly; and a bad board config names its file,
 * line and key, keeps the defaults and plays on. How it plays (the show's
 * clips in turn, timing, threads, compact streams): test_kiosk_options.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include "render_font.h"
#include "test_kiosk_run.h"
#include "test_paths.h"
#include "test_run.h"

static kiosk_image a, b;

/* Pixels that differ in HUD line i (0: the algorithm; 1: clip and frame
 * number), in the left half at the top (text scale 1 at this size). */
static long hud_line_diff(const kiosk_image *x, const kiosk_image *y, int i)
{
	long n = 0;
	int top = 4 + i * (FONT_CELL_H + 2);
	for (int r = top - 1; r < top + FONT_CELL_H + 1; r++)
		for (int c = 0; c < KIOSK_W / 2; c++)
			n += memcmp(&x->px[(r * KIOSK_W + c) * 4], &y->px[(r * KIOSK_W + c) * 4], 3) != 0;
	return n;
}

static int count_lines(const char *text, const char *prefix)
{
	int n = 0;
	for (const char *p = text; p && *p; p = strchr(p, '\n'), p = p ? p + 1 : NULL)
		n += strncmp(p, prefix, strlen(prefix)) == 0;
	return n;
}

/* At 120 fps frame n (0-based) is at n * 1000 / 120 ms: the press at
 * 100 ms shows first in frame 12 (file 13), the one at 250 ms in frame 30
 * (file 31). Each scripted frame must equal the frame of a run started
 * with that algorithm, and the HUD's first line must change there. */
static void test_script_switches_algorithm_at_its_frames(void **state)
{
	(void)state;
	char extra[256];
	test_write_text(kiosk_script_path, "# two ALGO presses\n"
				"100 ALGO press\n"
				"130 ALGO release\n"
				"250 ALGO press\n"
				"260 ALGO release\n");
	snprintf(extra, sizeof extra, "--algo lbs --input script:%s", kiosk_script_path);
	assert_int_equal(kiosk_run("s", extra, 32), 0);
	char *log = kiosk_read_log();
	const char *l1 = strstr(log, "input: ALGO -> dqbs\n");
	const char *l2 = strstr(log, "input: ALGO -> dqbs-fixed\n");
	if (!l1 || !l2 || l2 < l1 || count_lines(log, "input: ") != 3) /* "input: script ..." too */
		fail_msg("log:\n%s", log);
	free(log);
	assert_int_equal(kiosk_run("lbs", "--algo lbs", 13), 0);
	assert_int_equal(kiosk_run("dqbs", "--algo dqbs", 31), 0);
	assert_int_equal(kiosk_run("fixed", "--algo dqbs-fixed", 32), 0);
	static const struct { int file; const char *ref; } want[] = {
		{ 11, "lbs" }, { 12, "lbs" }, { 13, "dqbs" }, { 30, "dqbs" }, { 31, "fixed" }, { 32, "fixed" },
	};
	for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
		kiosk_load("s", want[i].file, &a);
		kiosk_load(want[i].ref, want[i].file, &b);
		long d = kiosk_image_diff(&a, &b);
		if (d != 0)
			fail_msg("frame file %d: %ld pixels differ from the %s run", want[i].file, d, want[i].ref);
	}
	/* the HUD's first line names the algorithm: it changes at the press */
	kiosk_load("s", 12, &a);
	kiosk_load("s", 13, &b);
	assert_true(hud_line_diff(&a, &b, 0) > 20);
	kiosk_load("s", 30, &a);
	kiosk_load("s", 31, &b);
	assert_true(hud_line_diff(&a, &b, 0) > 20);
	kiosk_load("s", 13, &a);
	kiosk_load("s", 14, &b);
	assert_int_equal(hud_line_diff(&a, &b, 0), 0);
}

/* PLAY pauses (the picture stops), PLAY again resumes; VIEW cycles. */
static void test_play_pause_and_view(void **state)
{
	(void)state;
	char extra[256];
	test_write_text(kiosk_script_path, "50 PLAY press\n60 PLAY release\n"
				"100 PLAY press\n110 PLAY release\n"
				"120 VIEW press\n130 VIEW release\n");
	snprintf(extra, sizeof extra, "--input script:%s", kiosk_script_path);
	assert_int_equal(kiosk_run("p", extra, 20), 0);
	char *log = kiosk_read_log();
	/* in this order; a progress line may come between them on a slow run */
	const char *at = strstr(log, "input: PLAY -> pause\n");
	at = at ? strstr(at, "input: PLAY -> play\n") : NULL;
	at = at ? strstr(at, "input: VIEW -> skeleton\n") : NULL;
	int in_order = at != NULL;
	if (!in_order)
		print_message("log:\n%s", log);
	free(log);
	assert_true(in_order);
	/* paused at the release at 60 ms (frame 8, file 9: it shows the motion
	 * frame of file 8 again), playing at the release at 110 ms (frame 14,
	 * file 15): the HUD's frame number stands still in between (the camera
	 * may still settle) */
	kiosk_load("p", 7, &a);
	kiosk_load("p", 8, &b);
	assert_true(hud_line_diff(&a, &b, 1) > 0);
	kiosk_load("p", 8, &a);
	for (int f = 9; f <= 14; f++) {
		kiosk_load("p", f, &b);
		if (hud_line_diff(&a, &b, 1) != 0)
			fail_msg("file %d: the frame number moved while paused", f);
	}
	kiosk_load("p", 15, &b);
	assert_true(hud_line_diff(&a, &b, 1) > 0);
}

/* Skin-toned or text pixels differ between two frames in a box. */
static long box_diff(const kiosk_image *x, const kiosk_image *y, int x0, int y0, int x1, int y1)
{
	long n = 0;
	for (int r = y0; r < y1; r++)
		for (int c = x0; c < x1; c++)
			n += memcmp(&x->px[(r * KIOSK_W + c) * 4], &y->px[(r * KIOSK_W + c) * 4], 3) != 0;
	return n;
}

/* Pixels of the PAUSED badge's colour (render_draw.c: 1, 0.8, 0.2). */
static long badge_pixels(const kiosk_image *x)
{
	long n = 0;
	for (int i = 0; i < KIOSK_W * KIOSK_H; i++) {
		const uint8_t *p = &x->px[i * 4];
		n += p[0] >= 253 && abs(p[1] - 204) <= 2 && abs(p[2] - 51) <= 2;
	}
	return n;
}

/* The visitor's screen: the methods' names large at the foot with their
 * sentence, no figures at the top; PAUSED across the top only while paused. */
static void test_visitor_hud(void **state)
{
	(void)state;
	char extra[256];
	test_write_text(kiosk_script_path, "50 PLAY press\n60 PLAY release\n");
	snprintf(extra, sizeof extra, "--algo compare --hud=visitor --input script:%s", kiosk_script_path);
	assert_int_equal(kiosk_run("v", extra, 12), 0);
	assert_int_equal(kiosk_run("e", "--algo compare --hud engineer", 12), 0);
	kiosk_load("v", 5, &a);
	kiosk_load("e", 5, &b);
	/* engineer's figures at the top left, none for the visitor */
	assert_true(hud_line_diff(&a, &b, 0) > 0);
	/* the visitor's labels are larger: more of the foot differs */
	assert_true(box_diff(&a, &b, 0, KIOSK_H - 60, KIOSK_W, KIOSK_H) > 500);
	/* paused at 60 ms (file 9 on): the badge across the top, in its own
	 * colour; none before */
	kiosk_load("v", 12, &b);
	long badge = badge_pixels(&b);
	if (badge < 100)
		fail_msg("no PAUSED badge: %ld pixels of its colour", badge);
	kiosk_load("v", 4, &b);
	assert_int_equal(badge_pixels(&b), 0);
	assert_int_equal(badge_pixels(&a), 0);
}

/* Frames in an AMC: its lines that are a bare frame number. */
static long amc_frames(const char *path)
{
	char *text = test_read_file(path, NULL);
	assert_non_null(text);
	long n = 0;
	for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
		size_t d = strspn(line, "0123456789");
		n += d > 0 && (line[d] == '\0' || line[d] == '\r');
	}
	free(text);
	return n;
}

/* Headless, a pause the script never lifts still ends the run: the held
 * frames count, one PNG per frame shown, as many as the clip takes at the
 * default 60 Hz display: those at times 0, 1/60 ... up to its length (the
 * demo's frames at 120 Hz: half of them, and one). The demo's first two
 * seconds: every frame is a PNG, and the whole demo's 1,156 took a minute. */
static void test_headless_pause_ends(void **state)
{
	(void)state;
	char cmd[2048], amc[512], out[128];
	char *demo = test_read_file(test_tool_path("assets/demo.amc"), NULL);
	assert_non_null(demo);
	char *cut = strstr(demo, "\n241\n");
	assert_non_null(cut);
	cut[1] = '\0';
	snprintf(amc, sizeof amc, "%s/first_240.amc", kiosk_dir);
	test_write_text(amc, demo);
	free(demo);
	snprintf(out, sizeof out, "%s/held", kiosk_dir);
	test_write_text(kiosk_script_path, "50 PLAY press\n60 PLAY release\n");
	snprintf(cmd, sizeof cmd,
		 "timeout 300 %s --asf assets/demo.asf --amc %s --platform surfaceless --size %dx%d --hud-fps off "
		 "--input=script:%s --output=%s 2>%s", test_tool_path("skinplay"), amc, KIOSK_W, KIOSK_H, kiosk_script_path, out, kiosk_log_path);
	assert_int_equal(system(cmd), 0);
	long frames = amc_frames(amc), pngs = 0;
	DIR *d = opendir(out);
	assert_non_null(d);
	for (struct dirent *e; (e = readdir(d)) != NULL;)
		pngs += strncmp(e->d_name, "frame_", 6) == 0;
	closedir(d);
	assert_int_equal(frames, 240);
	assert_int_equal(pngs, frames / 2 + 1);
	char *log = kiosk_read_log();
	if (!strstr(log, "input: PLAY -> pause\n"))
		fail_msg("log:\n%s", log);
	free(log);
}

static int listen_at(const char *name)
{
	struct sockaddr_un sa;
	memset(&sa, 0, sizeof sa);
	sa.sun_family = AF_UNIX;
	size_t n = strlen(name);
	memcpy(sa.sun_path, name, n);
	sa.sun_path[0] = '\0'; /* abstract, as '@' */
	int fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	assert_true(fd >= 0);
	if (bind(fd, (struct sockaddr *)&sa, (socklen_t)(offsetof(struct sockaddr_un, sun_path) + n)) != 0)
		fail_msg("bind: %s", strerror(errno));
	return fd;
}

/* Waits up to ms for a datagram equal to want; counts the others. */
static int wait_for(int fd, const char *want, int ms, int *watchdogs)
{
	char buf[128];
	for (int waited = 0; waited < ms; waited += 50) {
		struct pollfd p = { fd, POLLIN, 0 };
		if (poll(&p, 1, 50) != 1)
			continue;
		ssize_t n = recv(fd, buf, sizeof buf - 1, 0);
		buf[n > 0 ? n : 0] = '\0';
		if (!strcmp(buf, "WATCHDOG=1") && watchdogs)
			(*watchdogs)++;
		if (!strcmp(buf, want))
			return 1;
	}
	return 0;
}

/* skinplay as a kiosk that runs until told (the demo motion, headless,
 * no buttons), its stderr in the kiosk log (emptied first); under
 * "systemd" (notify: the socket's name, a 100 ms watchdog) or not. */
static pid_t start_kiosk(const char *notify)
{
	test_write_text(kiosk_log_path, "");
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		char image[512];
		snprintf(image, sizeof image, "%s", test_tool_path("assets/demo.skn"));
		if (notify) {
			setenv("NOTIFY_SOCKET", notify, 1);
			setenv("WATCHDOG_USEC", "100000", 1);
		}
		setenv("ASAN_OPTIONS", "detect_leaks=0", 1);
		if (!freopen(kiosk_log_path, "a", stderr))
			_exit(126);
		execl(test_tool_path("skinplay"), "skinplay", "--image", image, "--platform", "surfaceless", "--size",
		      "64x64", "--frames", "100000000", "--input", "none", (char *)NULL);
		_exit(127);
	}
	return pid;
}

/* Under "systemd": READY=1, WATCHDOG=1 every half period, SIGHUP: a fresh
 * start (READY=1 again), SIGTERM: a clean exit with status 0. */
static void test_notify_signals_and_watchdog(void **state)
{
	(void)state;
	char name[64];
	snprintf(name, sizeof name, "@skp_kiosk_%d", (int)getpid());
	int srv = listen_at(name);
	pid_t pid = start_kiosk(name);
	int dogs = 0;
	assert_true(wait_for(srv, "READY=1", 20000, &dogs));
	assert_true(wait_for(srv, "WATCHDOG=1", 5000, &dogs));
	kill(pid, SIGHUP);
	assert_true(wait_for(srv, "RELOADING=1", 5000, &dogs));
	assert_true(wait_for(srv, "READY=1", 20000, &dogs));
	assert_true(wait_for(srv, "WATCHDOG=1", 5000, &dogs));
	kill(pid, SIGTERM);
	assert_true(wait_for(srv, "STOPPING=1", 5000, &dogs));
	int status;
	assert_int_equal(waitpid(pid, &status, 0), pid);
	close(srv);
	char *log = kiosk_read_log();
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !strstr(log, "signal: SIGHUP -> reopen the show") ||
	    !strstr(log, "signal: quit -> clean exit") || count_lines(log, "display: surfaceless") != 2)
		fail_msg("status %d, log:\n%s", status, log);
	free(log);
	assert_true(dogs >= 2);
}

/* The log's count of lines starting with prefix, waiting up to ms for it
 * to reach want. */
static int wait_lines(const char *prefix, int want, int ms)
{
	int n = 0;
	for (int t = 0; t < ms; t += 20) {
		char *log = kiosk_read_log();
		n = count_lines(log, prefix);
		free(log);
		if (n >= want)
			break;
		usleep(20000);
	}
	return n;
}

/* `systemctl reload` twice in a row: two SIGHUPs 0-20 ms apart, ten times;
 * skinplay re-executes for each reload it sees and never dies of one (a
 * SIGHUP between taking down the handlers and the new process's start met
 * the default action). SIGTERM at the end: exit 0. */
static void test_sighup_twice(void **state)
{
	(void)state;
	/* under the sanitizers or an emulator 4 rounds (0-6 ms apart): each
	 * start takes 0.5 s there; natively 10 */
	const int rounds = test_slow() ? 4 : 10;
	pid_t pid = start_kiosk(NULL);
	int starts = wait_lines("display: surfaceless", 1, 20000), status;
	for (int round = 0; round < rounds && starts >= 1; round++) {
		kill(pid, SIGHUP);
		usleep((useconds_t)(round * 2000));
		kill(pid, SIGHUP);
		int now = wait_lines("display: surfaceless", starts + 1, 20000);
		if (waitpid(pid, &status, WNOHANG) != 0 || now <= starts) {
			kill(pid, SIGKILL);
			waitpid(pid, &status, 0);
			fail_msg("round %d: skinplay %s after two SIGHUPs %d ms apart", round,
				 now <= starts ? "did not start again" : "died", round * 2);
		}
		starts = now;
	}
	if (starts < 1) {
		kill(pid, SIGKILL);
		waitpid(pid, &status, 0);
		fail_msg("skinplay did not start");
	}
	usleep(200000);
	kill(pid, SIGTERM);
	assert_int_equal(waitpid(pid, &status, 0), pid);
	print_message("two SIGHUPs 0-%d ms apart, %d times: %d starts, then SIGTERM: %s %d\n", (rounds - 1) * 2,
		      rounds, starts, WIFEXITED(status) ? "exit" : "signal",
		      WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status));
	assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

static void test_bad_board_config_is_said_and_played_through(void **state)
{
	(void)state;
	char board[128], extra[256];
	snprintf(board, sizeof board, "%s/board.ini", kiosk_dir);
	/* a kiosk never stops over its config: each mistake said once, the
	 * key's default kept, the first mistake on the engineer HUD */
	assert_int_equal(kiosk_run_board("bad", "\xef\xbb\xbf[display]\r\nhud = engineer\r\n\n[button.play]\nline = 27\n"
				   "bias = sideways\nwobble = 1\n", "", 1), 0);
	char *log = kiosk_read_log(), want[512];
	snprintf(want, sizeof want, "%s:6: key 'bias' in [button.play]: expected as-is, disable, pull-up or pull-down, "
		 "found 'sideways'; ignored, the default stays\n%s:7: unknown key 'wobble'", board, board);
	if (strncmp(log, want, strlen(want)) != 0)
		fail_msg("log: %s\nwant: %s", log, want);
	free(log);
	assert_int_equal(kiosk_run_board("good", "[display]\nhud = engineer\n", "", 1), 0);
	kiosk_load("bad", 1, &a);
	kiosk_load("good", 1, &b);
	assert_true(hud_line_diff(&a, &b, 3) > 0);
	assert_int_equal(hud_line_diff(&a, &b, 0), 0);
	snprintf(extra, sizeof extra, "--board %s/none.ini", kiosk_dir);
	assert_int_equal(kiosk_run("gone", extra, 1), 0);
	kiosk_expect_log("none.ini: cannot open: No such file or directory; running with the defaults");
	/* a good one applies its display size unless --size says otherwise */
	test_write_text(board, "[display]\nsize = 64x48\n[input]\nbackend = none\n");
	char cmd[1024], amc[512];
	snprintf(amc, sizeof amc, "%s", test_tool_path("assets/demo.amc"));
	snprintf(cmd, sizeof cmd, "ASAN_OPTIONS=detect_leaks=0 %s --asf assets/demo.asf --amc %s --platform surfaceless "
		 "--board %s --frames 1 2>%s", test_tool_path("skinplay"), amc, board,
		 kiosk_log_path);
	assert_int_equal(system(cmd), 0);
	log = kiosk_read_log();
	assert_non_null(strstr(log, "display: surfaceless 64x48"));
	free(log);
	snprintf(extra, sizeof extra, "--input script:%s/missing.txt", kiosk_dir);
	assert_int_equal(kiosk_run("bad", extra, 1), 1);
	log = kiosk_read_log();
	assert_non_null(strstr(log, "missing.txt: cannot open"));
	free(log);
}

/* The board's [display] algo and view are what the kiosk starts with (the
 * first frame is that of a run with --algo compare; ALGO and VIEW step on
 * from there); --algo and --view on the command line win over them. */
static void test_board_sets_starting_algo_and_view(void **state)
{
	(void)state;
	static const char ini[] = "[display]\nalgo = compare\nview = weights\n";
	char more[256];
	test_write_text(kiosk_script_path, "100 ALGO press\n110 ALGO release\n120 VIEW press\n130 VIEW release\n");
	snprintf(more, sizeof more, "--input script:%s", kiosk_script_path);
	assert_int_equal(kiosk_run_board("board", ini, more, 18), 0);
	char *log = kiosk_read_log();
	if (!strstr(log, "input: ALGO -> lbs\n") || !strstr(log, "input: VIEW -> difference\n"))
		fail_msg("from compare and weights, want lbs and difference; log:\n%s", log);
	free(log);
	snprintf(more, sizeof more, "--algo=lbs --view body --input script:%s", kiosk_script_path);
	assert_int_equal(kiosk_run_board("cli", ini, more, 18), 0);
	log = kiosk_read_log();
	if (!strstr(log, "input: ALGO -> dqbs\n") || !strstr(log, "input: VIEW -> skeleton\n"))
		fail_msg("from --algo lbs and --view body, want dqbs and skeleton; log:\n%s", log);
	free(log);
	assert_int_equal(kiosk_run("compare", "--algo compare --view weights", 1), 0);
	assert_int_equal(kiosk_run("lbs", "--algo lbs", 1), 0);
	kiosk_load("board", 1, &a);
	kiosk_load("compare", 1, &b);
	assert_int_equal(kiosk_image_diff(&a, &b), 0);
	kiosk_load("cli", 1, &a);
	assert_true(kiosk_image_diff(&a, &b) > 0);
	kiosk_load("lbs", 1, &b);
	assert_int_equal(kiosk_image_diff(&a, &b), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_script_switches_algorithm_at_its_frames),
		cmocka_unit_test(test_play_pause_and_view),
		cmocka_unit_test(test_headless_pause_ends),
		cmocka_unit_test(test_visitor_hud),
		cmocka_unit_test(test_notify_signals_and_watchdog),
		cmocka_unit_test(test_sighup_twice),
		cmocka_unit_test(test_bad_board_config_is_said_and_played_through),
		cmocka_unit_test(test_board_sets_starting_algo_and_view),
	};
	return cmocka_run_group_tests(tests, kiosk_setup, kiosk_teardown);
}
