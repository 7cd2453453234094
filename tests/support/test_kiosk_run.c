/* Running the real skinplay as a kiosk (test_kiosk_run.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "png_writer.h"
#include "test_kiosk_run.h"
#include "test_paths.h"
#include "test_run.h"

char kiosk_dir[64], kiosk_log_path[96], kiosk_script_path[96];

int kiosk_setup(void **state)
{
	(void)state;
	snprintf(kiosk_dir, sizeof kiosk_dir, "/tmp/skp_kiosk_XXXXXX");
	assert_non_null(mkdtemp(kiosk_dir));
	snprintf(kiosk_log_path, sizeof kiosk_log_path, "%s/log.txt", kiosk_dir);
	snprintf(kiosk_script_path, sizeof kiosk_script_path, "%s/script.txt", kiosk_dir);
	return 0;
}

int kiosk_teardown(void **state)
{
	(void)state;
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf %s", kiosk_dir);
	return system(cmd) == 0 ? 0 : -1;
}

/* The demo as kiosk_run gives it: natively its ASF and AMC (the body made
 * and bound at start-up); under the sanitizers or an emulator the same
 * packed raw once, as an image (making and binding the body took 1.5 s
 * of a 32-frame run's 3 there; the kiosk's code after it is the same). */
static const char *kiosk_demo(void)
{
	static char args[1200];
	char amc[512], image[160];
	if (args[0])
		return args;
	snprintf(amc, sizeof amc, "%s", test_tool_path("assets/demo.amc")); /* one static buffer */
	snprintf(args, sizeof args, "--asf assets/demo.asf --amc %s", amc);
	if (!test_slow())
		return args;
	snprintf(image, sizeof image, "%s/demo_raw.skn", kiosk_dir);
	assert_int_equal(test_run("%s pack --raw -q assets/demo.asf %s -o %s >/dev/null", test_tool_path("skintool"),
				  amc, image), 0);
	snprintf(args, sizeof args, "--image %s", image);
	return args;
}

int kiosk_run(const char *out, const char *extra, long frames)
{
	char cmd[2048];
	snprintf(cmd, sizeof cmd,
		 "rm -rf %s/%s && ASAN_OPTIONS=detect_leaks=0 %s %s "
		 "--platform surfaceless --size %dx%d --hud-fps off --display-rate 120 --frames %ld --out %s/%s %s 2>%s",
		 kiosk_dir, out, test_tool_path("skinplay"), kiosk_demo(), KIOSK_W, KIOSK_H, frames, kiosk_dir, out,
		 extra, kiosk_log_path);
	int status = system(cmd);
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void kiosk_load(const char *out, int n, kiosk_image *img)
{
	char path[160];
	skp_error err;
	snprintf(path, sizeof path, "%s/%s/frame_%06d.png", kiosk_dir, out, n);
	if (png_read_rgba(path, img->px, sizeof img->px, &img->w, &img->h, &err) != 0)
		fail_msg("%s: %s", path, err.msg);
}

long kiosk_image_diff(const kiosk_image *x, const kiosk_image *y)
{
	long n = 0;
	for (int i = 0; i < KIOSK_W * KIOSK_H; i++)
		n += memcmp(&x->px[i * 4], &y->px[i * 4], 3) != 0;
	return n;
}

char *kiosk_read_log(void)
{
	char *text = test_read_file(kiosk_log_path, NULL);
	assert_non_null(text);
	return text;
}

int kiosk_run_board(const char *out, const char *ini, const char *more, long frames)
{
	char board[128], extra[512];
	snprintf(board, sizeof board, "%s/board.ini", kiosk_dir);
	test_write_text(board, ini);
	snprintf(extra, sizeof extra, "--board %s %s", board, more);
	return kiosk_run(out, extra, frames);
}

void kiosk_expect_log(const char *needle)
{
	char *log = kiosk_read_log();
	if (!strstr(log, needle))
		fail_msg("'%s' not in:\n%s", needle, log);
	free(log);
}
