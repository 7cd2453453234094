/* skinplay -o F.mp4 / F.webm: the headless run as one video, read back
 * by ffprobe. The CMU 02_01 walk (343 frames at 120 Hz: 2.858 s) played
 * at display rates of 30 and 24 Hz is an H.264 and a VP9 video of
 * exactly the frames shown (floor(2.858 x rate) + 1: 86 and 69), at that
 * rate, lasting the clip's duration within one frame; with --every 4 at
 * 60 Hz a quarter of the frames at 15 Hz, as long. A video container it
 * does not write (.avi), a directory that cannot take the file and an odd
 * size are refused naming the file, and nothing is left behind: not on a
 * refusal, not when the run is killed mid-video (the file was an unnamed
 * temporary); a file that was there keeps its contents. In a build
 * without video output (--version says none) -o F.mp4 is refused at
 * once, saying so and what to install. Skips under an emulator (no
 * rendering there) and, for the ffprobe checks, without ffprobe. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test_paths.h"
#include "test_run.h"

#define MOTION "--asf assets/cmu/02.asf --amc assets/cmu/02_01.amc"
#define CLIP_S (343.0 / 120.0)

static int video_built(void)
{
	const char *out = test_scratch("version.txt");
	assert_int_equal(test_run("%s --version > '%s'", test_tool_path("skinplay"), out), 0);
	return test_file_contains(out, "video output: mp4");
}

/* Skips unless skinplay renders here and writes video (and, with probe,
 * ffprobe is installed). */
static void need_video(int probe)
{
	if (test_emulator()) {
		print_message("under %s: no rendering\n", test_emulator());
		skip();
	}
	if (!video_built()) {
		print_message("this skinplay has no video output (test_no_video_build checks its refusal)\n");
		skip();
	}
	if (probe && test_run("command -v ffprobe >/dev/null") != 0) {
		print_message("no ffprobe (Debian: ffmpeg): the videos cannot be read back\n");
		skip();
	}
}

/* Entries of a directory other than . and .., named into list. */
static int entries(const char *dir, char *list, size_t size)
{
	DIR *d = opendir(dir);
	int n = 0;
	assert_non_null(d);
	list[0] = '\0';
	for (struct dirent *e; (e = readdir(d)) != NULL;)
		if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) {
			n++;
			strncat(list, e->d_name, size - strlen(list) - 2);
			strcat(list, " ");
		}
	closedir(d);
	return n;
}

typedef struct probe {
	char codec[16];
	long frames, width, height, rate_num, rate_den;
	double duration;
} probe;

static probe ffprobe(const char *video)
{
	const char *out = test_scratch("probe.txt");
	probe p;
	memset(&p, 0, sizeof p);
	assert_int_equal(test_run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
				  "stream=codec_name,nb_read_frames,width,height,r_frame_rate -show_entries "
				  "format=duration -of default=nw=1 '%s' > '%s'", video, out),
			 0);
	FILE *f = fopen(out, "r");
	assert_non_null(f);
	char line[128];
	while (fgets(line, sizeof line, f)) {
		sscanf(line, "codec_name=%15s", p.codec);
		sscanf(line, "nb_read_frames=%ld", &p.frames);
		sscanf(line, "width=%ld", &p.width);
		sscanf(line, "height=%ld", &p.height);
		sscanf(line, "r_frame_rate=%ld/%ld", &p.rate_num, &p.rate_den);
		sscanf(line, "duration=%lf", &p.duration);
	}
	fclose(f);
	return p;
}

/* The clip at hz, every k-th frame, into name; checked against ffprobe. */
static void play_into(const char *name, int hz, int k, const char *codec)
{
	const char *video = test_scratch(name), *err = test_scratch("err.txt");
	assert_int_equal(test_run("%s " MOTION " --platform surfaceless --size 320x180 --display-rate %d --every %d "
				  "-o '%s' 2>'%s'", test_tool_path("skinplay"), hz, k, video, err),
			 0);
	long shown = (long)floor(CLIP_S * hz + 1e-9) + 1, frames = (shown + k - 1) / k;
	probe p = ffprobe(video);
	double frame_s = (double)k / hz;
	print_message("%s: %s, %ldx%ld, %ld/%ld Hz, %ld frames (of %ld shown), %.3f s for a clip of %.3f s\n", name,
		      p.codec, p.width, p.height, p.rate_num, p.rate_den, p.frames, shown, p.duration, CLIP_S);
	assert_string_equal(p.codec, codec);
	assert_int_equal(p.width, 320);
	assert_int_equal(p.height, 180);
	assert_int_equal(p.frames, frames);
	assert_true(p.rate_den > 0 && fabs((double)p.rate_num / (double)p.rate_den - (double)hz / k) < 1e-6);
	/* frames / rate, within the container's millisecond ticks */
	assert_true(fabs(p.duration - (double)frames * frame_s) < 0.0015);
	/* true time: the clip's duration within one frame */
	assert_true(fabs(p.duration - CLIP_S) <= frame_s);
}

static void test_rates_and_codecs(void **state)
{
	(void)state;
	need_video(1);
	/* under the sanitizers or an emulator one rate a codec (each video
	 * of the walk took 5 to 6.5 s there); natively both rates for both */
	const int all = !test_slow();
	play_into("walk30.mp4", 30, 1, "h264");
	if (all) {
		play_into("walk24.mp4", 24, 1, "h264");
		play_into("walk30.webm", 30, 1, "vp9");
	}
	play_into("walk24.webm", 24, 1, "vp9");
	play_into("walk60every4.mp4", 60, 4, "h264");
}

/* skinplay with the output and more options fails naming what; dir then
 * holds what it held (want entries). */
static void refused(const char *out, const char *more, const char *says, const char *dir, int want)
{
	const char *err = test_scratch("err.txt");
	char list[512];
	int rc = test_run("%s " MOTION " --platform surfaceless --size 320x180 --frames 5 %s -o '%s' 2>'%s'",
			  test_tool_path("skinplay"), more, out, err);
	assert_int_equal(rc, 1);
	const char *const texts[] = { out, says, NULL };
	test_assert_contains_all(err, texts);
	int n = entries(dir, list, sizeof list);
	if (n != want)
		fail_msg("%s: left %s in %s", out, list, dir);
}

static void test_refusals(void **state)
{
	(void)state;
	need_video(0);
	const char *dir = test_scratch("refused");
	assert_int_equal(test_run("mkdir -p '%s' && : > '%s/plain'", dir, dir), 0);
	char out[600];
	snprintf(out, sizeof out, "%s/walk.avi", dir);
	refused(out, "", "F.mp4 (H.264) or F.webm (VP9)", dir, 1);
	/* a directory that cannot take the file: its parent is a plain file */
	snprintf(out, sizeof out, "%s/plain/walk.mp4", dir);
	refused(out, "", "cannot create", dir, 1);
	snprintf(out, sizeof out, "%s/walk.webm", dir);
	refused(out, "--background=transparent", "alpha", dir, 1);
	/* odd sizes: yuv420p halves both; an old file keeps its contents */
	snprintf(out, sizeof out, "%s/walk.mp4", dir);
	test_write_text(out, "old\n");
	refused(out, "--size 321x180", "even width and height", dir, 2);
	assert_true(test_file_contains(out, "old"));
}

/* Killed mid-video: no file, no temporary; the old file as it was. */
static void test_killed_leaves_nothing(void **state)
{
	(void)state;
	need_video(0);
	const char *dir = test_scratch("killed"), *log = test_scratch("killed.log"), *pid = test_scratch("pid");
	char out[600], list[512];
	assert_int_equal(test_run("mkdir -p '%s'", dir), 0);
	snprintf(out, sizeof out, "%s/long.mp4", dir);
	test_write_text(out, "old\n");
	assert_int_equal(test_run("%s " MOTION " --platform surfaceless --size 320x180 --frames 100000 -o '%s' "
				  ">/dev/null 2>'%s' & echo $! > '%s'", test_tool_path("skinplay"), out, log, pid),
			 0);
	/* the video open and frames going into it: a status line says so */
	int opened = test_wait_for_text(log, "frames a second", 60) && test_wait_for_text(log, "shown (", 60);
	assert_int_equal(test_run("kill -KILL $(cat '%s'); while kill -0 $(cat '%s') 2>/dev/null; do sleep 0.1; done",
				  pid, pid),
			 0);
	if (!opened)
		fail_msg("skinplay wrote no video in 60 s: %s", log);
	assert_int_equal(entries(dir, list, sizeof list), 1);
	assert_true(test_file_contains(out, "old"));
}

/* A build without video: refused before anything starts. */
static void test_no_video_build(void **state)
{
	(void)state;
	if (video_built()) {
		print_message("this skinplay writes video (the other tests check it)\n");
		skip();
	}
	const char *err = test_scratch("err.txt");
	assert_int_equal(test_run("%s " MOTION " -o '%s' 2>'%s'", test_tool_path("skinplay"), test_scratch("x.mp4"), err),
			 1);
	static const char *const texts[] = { "x.mp4", "no video output", "libavcodec-dev", "-o DIR", NULL };
	test_assert_contains_all(err, texts);
	assert_int_equal(access(test_scratch("x.mp4"), F_OK), -1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_rates_and_codecs),
		cmocka_unit_test(test_refusals),
		cmocka_unit_test(test_killed_leaves_nothing),
		cmocka_unit_test(test_no_video_build),
	};
	return cmocka_run_group_tests_name("video", tests, test_scratch_setup, test_scratch_teardown);
}
