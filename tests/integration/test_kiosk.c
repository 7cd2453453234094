/* The kiosk through the real skinplay: scripted buttons switch the
 * algorithm at exactly the frames the script says (log lines and images),
 * systemd hears READY=1 and WATCHDOG=1 on a socket the test opens, SIGHUP
 * restarts the show and SIGTERM ends it cleanly, and a bad board config
 * names its file, line and key, keeps the defaults and plays on. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include "png_writer.h"
#include "render_font.h"
#include "test_paths.h"
#include "test_run.h"

#define W 320
#define H 240

typedef struct image {
	int w, h;
	uint8_t px[W * H * 4];
} image;

static image a, b;
static char dir[64], log_path[96], script_path[96];

static int setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof dir, "/tmp/skp_kiosk_XXXXXX");
	assert_non_null(mkdtemp(dir));
	snprintf(log_path, sizeof log_path, "%s/log.txt", dir);
	snprintf(script_path, sizeof script_path, "%s/script.txt", dir);
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
	return system(cmd) == 0 ? 0 : -1;
}

/* Runs skinplay headless on the demo into dir/out (frames 1..n), at a
 * display rate of the clip's 120 Hz: display frame n shows captured frame
 * n, and script time n * 1000 / 120 ms is frame n. */
static int run(const char *out, const char *extra, long frames)
{
	char cmd[2048], amc[512];
	snprintf(amc, sizeof amc, "%s", test_tool_path("assets/demo.amc")); /* one static buffer */
	snprintf(cmd, sizeof cmd,
		 "rm -rf %s/%s && ASAN_OPTIONS=detect_leaks=0 %s --asf assets/demo.asf --amc %s "
		 "--platform surfaceless --size %dx%d --hud-fps off --display-rate 120 --frames %ld --out %s/%s %s 2>%s",
		 dir, out, test_tool_path("skinplay"), amc, W, H, frames, dir, out,
		 extra, log_path);
	int status = system(cmd);
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static void load(const char *out, int n, image *img)
{
	char path[160];
	skp_error err;
	snprintf(path, sizeof path, "%s/%s/frame_%06d.png", dir, out, n);
	if (png_read_rgba(path, img->px, sizeof img->px, &img->w, &img->h, &err) != 0)
		fail_msg("%s: %s", path, err.msg);
}

/* Pixels that differ in HUD line i (0: the algorithm; 1: clip and frame
 * number), in the left half at the top (text scale 1 at this size). */
static long hud_line_diff(const image *x, const image *y, int i)
{
	long n = 0;
	int top = 4 + i * (FONT_CELL_H + 2);
	for (int r = top - 1; r < top + FONT_CELL_H + 1; r++)
		for (int c = 0; c < W / 2; c++)
			n += memcmp(&x->px[(r * W + c) * 4], &y->px[(r * W + c) * 4], 3) != 0;
	return n;
}

static long image_diff(const image *x, const image *y)
{
	long n = 0;
	for (int i = 0; i < W * H; i++)
		n += memcmp(&x->px[i * 4], &y->px[i * 4], 3) != 0;
	return n;
}

static char *read_log(void)
{
	char *text = test_read_file(log_path, NULL);
	assert_non_null(text);
	return text;
}

/* run() with a board config of the given text (dir/board.ini) and more
 * options. */
static int run_board(const char *out, const char *ini, const char *more, long frames)
{
	char board[128], extra[512];
	snprintf(board, sizeof board, "%s/board.ini", dir);
	test_write_text(board, ini);
	snprintf(extra, sizeof extra, "--board %s %s", board, more);
	return run(out, extra, frames);
}

/* The last run's stderr says needle. */
static void expect_log(const char *needle)
{
	char *log = read_log();
	if (!strstr(log, needle))
		fail_msg("'%s' not in:\n%s", needle, log);
	free(log);
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
	test_write_text(script_path, "# two ALGO presses\n"
				"100 ALGO press\n"
				"130 ALGO release\n"
				"250 ALGO press\n"
				"260 ALGO release\n");
	snprintf(extra, sizeof extra, "--algo lbs --input script:%s", script_path);
	assert_int_equal(run("s", extra, 32), 0);
	char *log = read_log();
	const char *l1 = strstr(log, "input: ALGO -> dqbs\n");
	const char *l2 = strstr(log, "input: ALGO -> dqbs-fixed\n");
	if (!l1 || !l2 || l2 < l1 || count_lines(log, "input: ") != 3) /* "input: script ..." too */
		fail_msg("log:\n%s", log);
	free(log);
	assert_int_equal(run("lbs", "--algo lbs", 13), 0);
	assert_int_equal(run("dqbs", "--algo dqbs", 31), 0);
	assert_int_equal(run("fixed", "--algo dqbs-fixed", 32), 0);
	static const struct { int file; const char *ref; } want[] = {
		{ 11, "lbs" }, { 12, "lbs" }, { 13, "dqbs" }, { 30, "dqbs" }, { 31, "fixed" }, { 32, "fixed" },
	};
	for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
		load("s", want[i].file, &a);
		load(want[i].ref, want[i].file, &b);
		long d = image_diff(&a, &b);
		if (d != 0)
			fail_msg("frame file %d: %ld pixels differ from the %s run", want[i].file, d, want[i].ref);
	}
	/* the HUD's first line names the algorithm: it changes at the press */
	load("s", 12, &a);
	load("s", 13, &b);
	assert_true(hud_line_diff(&a, &b, 0) > 20);
	load("s", 30, &a);
	load("s", 31, &b);
	assert_true(hud_line_diff(&a, &b, 0) > 20);
	load("s", 13, &a);
	load("s", 14, &b);
	assert_int_equal(hud_line_diff(&a, &b, 0), 0);
}

/* PLAY pauses (the picture stops), PLAY again resumes; VIEW cycles. */
static void test_play_pause_and_view(void **state)
{
	(void)state;
	char extra[256];
	test_write_text(script_path, "50 PLAY press\n60 PLAY release\n"
				"100 PLAY press\n110 PLAY release\n"
				"120 VIEW press\n130 VIEW release\n");
	snprintf(extra, sizeof extra, "--input script:%s", script_path);
	assert_int_equal(run("p", extra, 20), 0);
	char *log = read_log();
	if (!strstr(log, "input: PLAY -> pause\ninput: PLAY -> play\ninput: VIEW -> skeleton\n"))
		fail_msg("log:\n%s", log);
	free(log);
	/* paused at the release at 60 ms (frame 8, file 9: it shows the motion
	 * frame of file 8 again), playing at the release at 110 ms (frame 14,
	 * file 15): the HUD's frame number stands still in between (the camera
	 * may still settle) */
	load("p", 7, &a);
	load("p", 8, &b);
	assert_true(hud_line_diff(&a, &b, 1) > 0);
	load("p", 8, &a);
	for (int f = 9; f <= 14; f++) {
		load("p", f, &b);
		if (hud_line_diff(&a, &b, 1) != 0)
			fail_msg("file %d: the frame number moved while paused", f);
	}
	load("p", 15, &b);
	assert_true(hud_line_diff(&a, &b, 1) > 0);
}

/* Skin-toned or text pixels differ between two frames in a box. */
static long box_diff(const image *x, const image *y, int x0, int y0, int x1, int y1)
{
	long n = 0;
	for (int r = y0; r < y1; r++)
		for (int c = x0; c < x1; c++)
			n += memcmp(&x->px[(r * W + c) * 4], &y->px[(r * W + c) * 4], 3) != 0;
	return n;
}

/* Pixels of the PAUSED badge's colour (render_draw.c: 1, 0.8, 0.2). */
static long badge_pixels(const image *x)
{
	long n = 0;
	for (int i = 0; i < W * H; i++) {
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
	test_write_text(script_path, "50 PLAY press\n60 PLAY release\n");
	snprintf(extra, sizeof extra, "--algo compare --hud=visitor --input script:%s", script_path);
	assert_int_equal(run("v", extra, 12), 0);
	assert_int_equal(run("e", "--algo compare --hud engineer", 12), 0);
	load("v", 5, &a);
	load("e", 5, &b);
	/* engineer's figures at the top left, none for the visitor */
	assert_true(hud_line_diff(&a, &b, 0) > 0);
	/* the visitor's labels are larger: more of the foot differs */
	assert_true(box_diff(&a, &b, 0, H - 60, W, H) > 500);
	/* paused at 60 ms (file 9 on): the badge across the top, in its own
	 * colour; none before */
	load("v", 12, &b);
	long badge = badge_pixels(&b);
	if (badge < 100)
		fail_msg("no PAUSED badge: %ld pixels of its colour", badge);
	load("v", 4, &b);
	assert_int_equal(badge_pixels(&b), 0);
	assert_int_equal(badge_pixels(&a), 0);
}

/* --report-timing: a row per stage, means that add up to the frame's; the
 * summary line's figures are the same record's (decode = decode and pose,
 * skin = bone transforms + skinning, upload, draw). */
static void test_report_timing(void **state)
{
	(void)state;
	assert_int_equal(run("t", "--report-timing", 20), 0);
	char *log = read_log();
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
	assert_int_equal(run_board("two", ini, "--algo compare", 12), 0);
	expect_log("CPU skinning on 2 threads)");
	assert_int_equal(run_board("one", ini, "--algo compare --threads 1", 30), 0);
	expect_log("CPU skinning)");
	for (int n = 1; n <= 12; n += 11) {
		load("two", n, &a);
		load("one", n, &b);
		assert_int_equal(image_diff(&a, &b), 0);
	}
	assert_int_equal(run("auto", "--threads auto", 1), 0);
	expect_log("CPU skinning)");
	/* split_verts = auto: the first frames measure two threads against
	 * one, the log says what they chose, and the frames are the same */
	const char *tuned = "[skin]\nthreads = 2\nsplit_verts = auto\n";
	assert_int_equal(run_board("tuned", tuned, "--algo compare", 30), 0);
	expect_log("skinplay: a kernel run took ");
	expect_log(" on 2 threads, ");
	static const int frames[] = { 1, 12, 30 };
	for (int i = 0; i < 3; i++) {
		load("tuned", frames[i], &a);
		load("one", frames[i], &b);
		assert_int_equal(image_diff(&a, &b), 0);
	}
	assert_int_equal(run("bad", "--threads 0", 1), 1);
	expect_log("--threads expects auto or 1..16, got '0'");
}

/* --streams compact: LBS and DQBS read the 16-bit streams and upload
 * 16-bit normals; the picture is the float streams' within a few pixels'
 * shading (quantisation moves a vertex by about 1e-5 of the body; the
 * compare view's close-up magnifies a joint several times, and its
 * shading with it: 390 pixels of 76,800 here, 0.2% before it). */
static void test_compact_streams(void **state)
{
	(void)state;
	assert_int_equal(run("compact", "--algo compare --hud off --streams compact --start 200", 2), 0);
	expect_log("CPU skinning, compact streams)");
	assert_int_equal(run("float", "--algo compare --hud off --streams float --start 200", 2), 0);
	for (int n = 1; n <= 2; n++) {
		load("compact", n, &a);
		load("float", n, &b);
		long d = image_diff(&a, &b);
		print_message("frame %d: %ld of %d pixels differ between compact and float streams\n", n, d, W * H);
		assert_true(d * 100 < W * H); /* under 1% */
	}
	assert_int_equal(run("bad", "--streams tiny", 1), 1);
	expect_log("tiny");
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
 * demo's frames at 120 Hz: half of them, and one). */
static void test_headless_pause_ends(void **state)
{
	(void)state;
	char cmd[2048], amc[512], out[128];
	snprintf(amc, sizeof amc, "%s", test_tool_path("assets/demo.amc"));
	snprintf(out, sizeof out, "%s/held", dir);
	test_write_text(script_path, "50 PLAY press\n60 PLAY release\n");
	snprintf(cmd, sizeof cmd,
		 "timeout 300 %s --asf assets/demo.asf --amc %s --platform surfaceless --size %dx%d --hud-fps off "
		 "--input=script:%s --output=%s 2>%s", test_tool_path("skinplay"), amc, W, H, script_path, out, log_path);
	assert_int_equal(system(cmd), 0);
	long frames = amc_frames(amc), pngs = 0;
	DIR *d = opendir(out);
	assert_non_null(d);
	for (struct dirent *e; (e = readdir(d)) != NULL;)
		pngs += strncmp(e->d_name, "frame_", 6) == 0;
	closedir(d);
	assert_true(frames > 100);
	assert_int_equal(pngs, frames / 2 + 1);
	char *log = read_log();
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

/* Under "systemd": READY=1, WATCHDOG=1 every half period, SIGHUP: a fresh
 * start (READY=1 again), SIGTERM: a clean exit with status 0. */
static void test_notify_signals_and_watchdog(void **state)
{
	(void)state;
	char name[64];
	snprintf(name, sizeof name, "@skp_kiosk_%d", (int)getpid());
	int srv = listen_at(name);
	pid_t pid = fork();
	assert_true(pid >= 0);
	if (pid == 0) {
		char amc[512];
		snprintf(amc, sizeof amc, "%s", test_tool_path("assets/demo.amc"));
		setenv("NOTIFY_SOCKET", name, 1);
		setenv("WATCHDOG_USEC", "100000", 1);
		setenv("ASAN_OPTIONS", "detect_leaks=0", 1);
		if (!freopen(log_path, "w", stderr))
			_exit(126);
		execl(test_tool_path("skinplay"), "skinplay", "--asf", "assets/demo.asf", "--amc", amc, "--platform",
		      "surfaceless", "--size", "64x64", "--frames", "100000000", "--input", "none", (char *)NULL);
		_exit(127);
	}
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
	char *log = read_log();
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !strstr(log, "signal: SIGHUP -> reopen the show") ||
	    !strstr(log, "signal: quit -> clean exit") || count_lines(log, "display: surfaceless") != 2)
		fail_msg("status %d, log:\n%s", status, log);
	free(log);
	assert_true(dogs >= 2);
}

static void test_bad_board_config_is_said_and_played_through(void **state)
{
	(void)state;
	char board[128], extra[256];
	snprintf(board, sizeof board, "%s/board.ini", dir);
	/* a kiosk never stops over its config: each mistake said once, the
	 * key's default kept, the first mistake on the engineer HUD */
	assert_int_equal(run_board("bad", "\xef\xbb\xbf[display]\r\nhud = engineer\r\n\n[button.play]\nline = 27\n"
				   "bias = sideways\nwobble = 1\n", "", 1), 0);
	char *log = read_log(), want[512];
	snprintf(want, sizeof want, "%s:6: key 'bias' in [button.play]: expected as-is, disable, pull-up or pull-down, "
		 "found 'sideways'; ignored, the default stays\n%s:7: unknown key 'wobble'", board, board);
	if (strncmp(log, want, strlen(want)) != 0)
		fail_msg("log: %s\nwant: %s", log, want);
	free(log);
	assert_int_equal(run_board("good", "[display]\nhud = engineer\n", "", 1), 0);
	load("bad", 1, &a);
	load("good", 1, &b);
	assert_true(hud_line_diff(&a, &b, 3) > 0);
	assert_int_equal(hud_line_diff(&a, &b, 0), 0);
	snprintf(extra, sizeof extra, "--board %s/none.ini", dir);
	assert_int_equal(run("gone", extra, 1), 0);
	expect_log("none.ini: cannot open: No such file or directory; running with the defaults");
	/* a good one applies its display size unless --size says otherwise */
	test_write_text(board, "[display]\nsize = 64x48\n[input]\nbackend = none\n");
	char cmd[1024], amc[512];
	snprintf(amc, sizeof amc, "%s", test_tool_path("assets/demo.amc"));
	snprintf(cmd, sizeof cmd, "ASAN_OPTIONS=detect_leaks=0 %s --asf assets/demo.asf --amc %s --platform surfaceless "
		 "--board %s --frames 1 2>%s", test_tool_path("skinplay"), amc, board,
		 log_path);
	assert_int_equal(system(cmd), 0);
	log = read_log();
	assert_non_null(strstr(log, "display: surfaceless 64x48"));
	free(log);
	snprintf(extra, sizeof extra, "--input script:%s/missing.txt", dir);
	assert_int_equal(run("bad", extra, 1), 1);
	log = read_log();
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
	test_write_text(script_path, "100 ALGO press\n110 ALGO release\n120 VIEW press\n130 VIEW release\n");
	snprintf(more, sizeof more, "--input script:%s", script_path);
	assert_int_equal(run_board("board", ini, more, 18), 0);
	char *log = read_log();
	if (!strstr(log, "input: ALGO -> lbs\n") || !strstr(log, "input: VIEW -> difference\n"))
		fail_msg("from compare and weights, want lbs and difference; log:\n%s", log);
	free(log);
	snprintf(more, sizeof more, "--algo=lbs --view body --input script:%s", script_path);
	assert_int_equal(run_board("cli", ini, more, 18), 0);
	log = read_log();
	if (!strstr(log, "input: ALGO -> dqbs\n") || !strstr(log, "input: VIEW -> skeleton\n"))
		fail_msg("from --algo lbs and --view body, want dqbs and skeleton; log:\n%s", log);
	free(log);
	assert_int_equal(run("compare", "--algo compare --view weights", 1), 0);
	assert_int_equal(run("lbs", "--algo lbs", 1), 0);
	load("board", 1, &a);
	load("compare", 1, &b);
	assert_int_equal(image_diff(&a, &b), 0);
	load("cli", 1, &a);
	assert_true(image_diff(&a, &b) > 0);
	load("lbs", 1, &b);
	assert_int_equal(image_diff(&a, &b), 0);
}

/* Runs skinplay headless on an image at 30 frames a second; returns the
 * log (the caller frees it) after checking the exit status. */
static char *play_image(const char *show, const char *more)
{
	char cmd[2048];
	snprintf(cmd, sizeof cmd, "ASAN_OPTIONS=detect_leaks=0 %s --image %s --platform surfaceless --size 64x36 "
		 "--display-rate 30 %s 2>%s", test_tool_path("skinplay"), show, more, log_path);
	assert_int_equal(system(cmd), 0);
	return read_log();
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
	snprintf(clip_a, sizeof clip_a, "%s/a.amc", dir);
	snprintf(clip_b, sizeof clip_b, "%s/b.amc", dir);
	snprintf(show, sizeof show, "%s/two.skn", dir);
	char amc[512]; /* test_tool_path's buffer is shared */
	snprintf(amc, sizeof amc, "%s", test_tool_path("assets/demo.amc"));
	/* the demo's first 9.5 s and its first 1 s: lengths of their own, not
	 * the demo's, which changes with the tour */
	snprintf(cmd, sizeof cmd, "awk '/^[0-9]+$/ { n = $1 } n <= 1140' %s > %s && "
		 "awk '/^[0-9]+$/ { n = $1 } n <= 120' %s > %s && "
		 "%s pack -q assets/demo.asf %s %s -o %s >/dev/null", amc, clip_a, clip_a, clip_b,
		 test_tool_path("skintool"), clip_a, clip_b, show);
	assert_int_equal(system(cmd), 0);
	long frames;
	/* 9.5 s and 1 s at 30 frames a second: 285 + 30 frames */
	char *log = play_image(show, "");
	clips_played(log, order, sizeof order, &frames);
	if (strcmp(order, "ab") || frames != 315)
		fail_msg("clips %s, %ld frames; log:\n%s", order, frames, log);
	free(log);
	/* on past the end, the show starts over */
	log = play_image(show, "--frames 330");
	clips_played(log, order, sizeof order, &frames);
	if (strcmp(order, "aba"))
		fail_msg("clips %s; log:\n%s", order, log);
	free(log);
	log = play_image(show, "--loop clip");
	clips_played(log, order, sizeof order, &frames);
	if (strcmp(order, "a") || frames != 286)
		fail_msg("--loop clip: clips %s, %ld frames; log:\n%s", order, frames, log);
	free(log);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_show_plays_its_clips_in_turn),
		cmocka_unit_test(test_script_switches_algorithm_at_its_frames),
		cmocka_unit_test(test_play_pause_and_view),
		cmocka_unit_test(test_headless_pause_ends),
		cmocka_unit_test(test_visitor_hud),
		cmocka_unit_test(test_report_timing),
		cmocka_unit_test(test_skinning_threads),
		cmocka_unit_test(test_compact_streams),
		cmocka_unit_test(test_notify_signals_and_watchdog),
		cmocka_unit_test(test_bad_board_config_is_said_and_played_through),
		cmocka_unit_test(test_board_sets_starting_algo_and_view),
	};
	return cmocka_run_group_tests(tests, setup, teardown);
}
