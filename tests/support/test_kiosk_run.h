/* Running the real skinplay as a kiosk for test_kiosk and
 * test_kiosk_options: headless on the demo in a scratch directory that the
 * group setup creates and the teardown removes, its frames read back as
 * images and its stderr as the log. */
#ifndef TEST_KIOSK_RUN_H
#define TEST_KIOSK_RUN_H

#include <stdint.h>

#define KIOSK_W 320
#define KIOSK_H 240

typedef struct kiosk_image {
	int w, h;
	uint8_t px[KIOSK_W * KIOSK_H * 4];
} kiosk_image;

/* the scratch directory, the log (skinplay's stderr) and a script in it */
extern char kiosk_dir[64], kiosk_log_path[96], kiosk_script_path[96];

/* cmocka group setup/teardown: a fresh /tmp/skp_kiosk_XXXXXX */
int kiosk_setup(void **state);
int kiosk_teardown(void **state);

/* Runs skinplay headless on the demo into dir/out (frames 1..n), at a
 * display rate of the clip's 120 Hz: display frame n shows captured frame
 * n, and script time n * 1000 / 120 ms is frame n. Returns its status. */
int kiosk_run(const char *out, const char *extra, long frames);

/* kiosk_run() with a board config of the given text (dir/board.ini) and
 * more options. */
int kiosk_run_board(const char *out, const char *ini, const char *more, long frames);

/* Frame file n of run out into img (the test fails when it cannot). */
void kiosk_load(const char *out, int n, kiosk_image *img);

/* Pixels that differ between two frames. */
long kiosk_image_diff(const kiosk_image *x, const kiosk_image *y);

/* The last run's stderr, for the caller to free. */
char *kiosk_read_log(void);

/* Fails the test unless the last run's stderr says needle. */
void kiosk_expect_log(const char *needle);

#endif
