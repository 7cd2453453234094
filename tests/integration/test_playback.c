/* Playback in time on real motion capture (../shared/data): the engine as
 * skinplay runs it (app/play over the AMC/BVH stream source), at a 60 Hz
 * display: a looping walk in place and a NEXT to another clip move no joint
 * more in one displayed frame than twice the clip's median frame-to-frame
 * motion. (skinplay itself against the wall clock: test_playback_window.c.) */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clip_file.h"
#include "motion_file.h"
#include "play_engine.h"
#include "test_paths.h"

#define HZ 60.0
#define MAX_SHOWN 20000

static skel sk;
static clip_file files[2];
static play_engine eng;
static skel_pose prev;
static double moves[MAX_SHOWN];

static double largest_move(const skel_pose *a, const skel_pose *b)
{
	double m = 0;
	for (int i = 0; i < sk.count; i++) {
		double x = (double)a->tip[i].x - b->tip[i].x, y = (double)a->tip[i].y - b->tip[i].y,
		       z = (double)a->tip[i].z - b->tip[i].z;
		m = fmax(m, sqrt(x * x + y * y + z * z));
	}
	return m;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}

static double median(const double *v, int n)
{
	static double tmp[MAX_SHOWN];
	memcpy(tmp, v, sizeof *v * (size_t)n);
	qsort(tmp, (size_t)n, sizeof *tmp, cmp_double);
	return tmp[n / 2];
}

typedef struct seam {
	double median, seam, worst_elsewhere;
} seam;

/* Plays asf/amc from time 0 for `seconds` of display frames, switching to
 * next_amc (when given) at next_at seconds; measures the largest move a
 * frame within 0.5 s after each seam (the loop, the switch) against the
 * median move over the whole clip. */
static seam play_through(const char *asf, const char *amc, const char *next_amc, double seconds, double next_at,
			 uint32_t blend_ms)
{
	play_source a, b;
	skp_error err;
	seam out = { 0, 0, 0 };
	assert_int_equal(motion_load_skel(asf, &sk), 0);
	assert_int_equal(clip_file_open(&files[0], amc, &sk, 120.0, &a), 0);
	if (next_amc)
		assert_int_equal(clip_file_open(&files[1], next_amc, &sk, 120.0, &b), 0);
	play_config cfg = { 1.0, blend_ms, PLAY_ROOT_IN_PLACE, 1 };
	play_init(&eng, &sk, &cfg);
	assert_int_equal(play_start(&eng, &a, 0, &err), SKP_OK);
	double d = play_duration(&eng);
	int n = 0;
	long frames = (long)(seconds * HZ), switch_frame = next_amc ? (long)(next_at * HZ) : -1;
	for (long f = 0; f < frames && n < MAX_SHOWN; f++) {
		uint64_t now = play_display_time(f, HZ);
		if (f == switch_frame)
			assert_int_equal(play_start(&eng, &b, now, &err), SKP_OK);
		assert_int_equal(play_update(&eng, now, &err), SKP_OK);
		if (f) {
			double m = largest_move(&eng.pose, &prev), t = (double)now * 1e-9;
			/* within half a second after a loop of the first clip or the switch */
			int near = (switch_frame < 0 || f < switch_frame) ? fmod(t, d) < 0.5 && t > d
									   : f - switch_frame < (long)(0.5 * HZ);
			if (near)
				out.seam = fmax(out.seam, m);
			else
				out.worst_elsewhere = fmax(out.worst_elsewhere, m);
			if (switch_frame < 0 || f < switch_frame)
				moves[n++] = m;
		}
		prev = eng.pose;
	}
	out.median = median(moves, n);
	clip_file_close(&files[0]);
	if (next_amc)
		clip_file_close(&files[1]);
	return out;
}

static void test_walk_loops_in_place(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	char asf[512], amc[512];
	snprintf(asf, sizeof asf, "%s", test_data_path("mocap/cmu/02.asf"));
	snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/02_01.amc"));
	seam cut = play_through(asf, amc, NULL, 9.0, 0, 0);
	seam fade = play_through(asf, amc, NULL, 9.0, 0, PLAY_BLEND_MS_DEFAULT);
	print_message("02_01 looping at 60 Hz in place: median move %.3f a frame; at the seam %.3f cut, %.3f with the "
		      "crossfade (%.2fx the median); elsewhere at most %.3f\n", fade.median, cut.seam, fade.seam,
		      fade.seam / fade.median, fade.worst_elsewhere);
	assert_true(cut.seam > 2.0 * cut.median); /* the seam is there to hide */
	assert_true(fade.seam <= 2.0 * fade.median);
}

static void test_next_clip_fades(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	char asf[512], amc[512], next[512];
	snprintf(asf, sizeof asf, "%s", test_data_path("mocap/cmu/02.asf"));
	snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/02_01.amc"));
	snprintf(next, sizeof next, "%s", test_data_path("mocap/cmu/02_01.amc"));
	/* NEXT pressed mid-walk (1.3 s in): the clip from its start */
	seam s = play_through(asf, amc, next, 4.0, 1.3, PLAY_BLEND_MS_DEFAULT);
	print_message("02_01, NEXT at 1.3 s to its start: median move %.3f, after NEXT %.3f (%.2fx)\n", s.median, s.seam,
		      s.seam / s.median);
	assert_true(s.seam <= 2.0 * s.median);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_walk_loops_in_place),
		cmocka_unit_test(test_next_clip_fades),
	};
	return cmocka_run_group_tests_name("playback", tests, NULL, NULL);
}
