/* A kiosk whose image slots hold nothing that can play keeps running: the
 * screen says so (the notice renderer, checked in pixels), the process
 * stays up feeding its watchdog, and a good show copied into a slot starts
 * playing by itself. Headless runs still fail (a batch run has no screen to
 * wait on). Needs a display: skipped under qemu-user (board/rpi4/board.mk). */
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
#include <unistd.h>

#include "display.h"
#include "gl_api.h"
#include "render.h"
#include "test_paths.h"
#include "test_run.h"
#include "test_xvfb.h"

#define W 480
#define H 270

static uint8_t rgba[W * H * 4];

/* The title is drawn in amber, the rest near white, on the dark clear
 * colour: count each kind of pixel in rows [y0, y1) (from the top). */
static void count_text(int y0, int y1, long *amber, long *white)
{
	*amber = *white = 0;
	for (int y = y0; y < y1; y++)
		for (int x = 0; x < W; x++) {
			const uint8_t *p = rgba + 4 * ((size_t)(H - 1 - y) * W + (size_t)x);
			*amber += p[0] > 200 && p[1] > 150 && p[1] < 230 && p[2] < 100;
			*white += p[0] > 200 && p[1] > 200 && p[2] > 170;
		}
}

static void test_notice_says_it_on_the_screen(void **state)
{
	(void)state;
	const display_backend *b = display_find("surfaceless");
	display_config cfg = { W, H, NULL, 0 };
	display_info info;
	skp_error err;
	static gl_api gl;
	static renderer r;
	if (!b || b->init(&cfg, &info, &err) != SKP_OK)
		skip();
	assert_int_equal(gl_api_load(&gl, b->get_proc, &err), SKP_OK);
	assert_int_equal(render_init_notice(&r, &gl, W, H, 0, &err), SKP_OK);
	static const char *const lines[] = { "NO SHOW TO PLAY", "NO IMAGE SLOT HOLDS A SHOW THAT CAN PLAY" };
	render_draw_notice(&r, lines, 2);
	render_read_rgba(&r, rgba);
	long amber, white, amber_low, white_low;
	count_text(0, H / 3 + 40, &amber, &white);
	count_text(H / 3 + 40, H, &amber_low, &white_low);
	print_message("notice at %dx%d: title %ld amber pixels, %ld white below it\n", W, H, amber, white_low);
	assert_true(amber > 200);          /* the title, in the upper third */
	assert_true(white_low > 200);      /* the explanation below */
	assert_true(amber_low < amber / 10);
	render_shutdown(&r);
	b->shutdown();
}

static char *slurp(const char *path)
{
	size_t n;
	return test_read_file(path, &n);
}

static void test_kiosk_waits_for_a_show(void **state)
{
	(void)state;
	char name[16];
	if (!test_data_path("mocap"))
		skip();
	pid_t x = test_xvfb_start("640x480x24", name, sizeof name);
	if (!x)
		skip();
	const char *slot = test_scratch("slot.skn"), *good = test_scratch("good.skn"), *log = test_scratch("wait.log");
	test_write_text(slot, "not an image\n");
	assert_int_equal(test_run("%s pack '%s' '%s' -q -o '%s'", test_tool_path("skintool"),
				  test_data_path("mocap/cmu/09.asf"), test_data_path("mocap/cmu/09_06.amc"), good), 0);
	/* headless: an error, as before */
	assert_int_equal(test_run("%s --image '%s' --platform surfaceless --size 64x36 2>/dev/null",
				  test_tool_path("skinplay"), slot), 1);
	pid_t pid = fork();
	if (pid == 0) {
		if (!freopen(log, "w", stderr))
			_exit(126);
		setenv("DISPLAY", name, 1);
		execl(test_tool_path("skinplay"), "skinplay", "--image", slot, "--platform", "x11", "--size", "320x240",
		      "--input", "none", (char *)NULL);
		_exit(127);
	}
	int waiting = test_wait_for_text(log, "waiting for one", 30);
	sleep(2);
	int alive = waitpid(pid, NULL, WNOHANG) == 0;
	/* a good show copied in (a temporary name, then renamed, as an update does) */
	assert_int_equal(test_run("cp '%s' '%s.tmp' && mv '%s.tmp' '%s'", good, slot, slot, slot), 0);
	int started = test_wait_for_text(log, "image: playing", 30) && test_wait_for_text(log, "frame ", 30);
	kill(pid, SIGTERM);
	int status;
	waitpid(pid, &status, 0);
	test_xvfb_stop(x);
	char *text = slurp(log);
	if (!waiting || !alive || !started || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
		fail_msg("waiting %d, alive %d, started %d, status %d; log:\n%s", waiting, alive, started, status,
			 text ? text : "");
	free(text);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_notice_says_it_on_the_screen),
		cmocka_unit_test(test_kiosk_waits_for_a_show),
	};
	return cmocka_run_group_tests_name("kiosk_wait", tests, test_scratch_setup, test_scratch_teardown);
}
