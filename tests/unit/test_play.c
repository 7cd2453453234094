/* The playback engine (app/play) driven by a fake clock over a table of
 * frames: time to pose at any render rate, interpolation on the shortest
 * arc, pauses, speed, loops and clip changes without seams, root motion,
 * the frames a display skips read and dropped. Facing and the slot and
 * clip policy: test_play_policy.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "play_engine.h"
#include "test_parse.h"
#include "test_rng.h"

#define DEG ((float)(M_PI / 180.0))
#define MAX_FRAMES 2000

/* root: TX TY TZ RX RY RZ; upper: rx ry rz; lower: rx rz */
static const char *arm =
	":root\n order TX TY TZ RX RY RZ\n position 0 1 0\n:bonedata\n"
	" begin\n name upper\n direction 1 0 0\n length 2\n axis 0 0 0 XYZ\n dof rx ry rz\n end\n"
	" begin\n name lower\n direction 1 0 0\n length 1.5\n axis 0 0 90 XYZ\n dof rx rz\n end\n"
	":hierarchy\n begin\n root upper\n upper lower\n end\n";

static skel s;

/* A clip in memory, with counts of what the engine asked of it. */
typedef struct table {
	float v[MAX_FRAMES][11];
	long frames, next;
	long reads, seeks;
} table;

static table clip;

static int table_next(void *ctx, amc_frame *f, skp_error *err)
{
	table *t = ctx;
	(void)err;
	if (t->next >= t->frames)
		return 0;
	memset(f->value, 0, sizeof f->value);
	memcpy(f->value, t->v[t->next], sizeof t->v[0]);
	f->number = t->next + 1;
	t->next++;
	t->reads++;
	return 1;
}

static skp_status table_seek(void *ctx, long index, skp_error *err)
{
	table *t = ctx;
	(void)err;
	t->next = index;
	t->seeks++;
	return SKP_OK;
}

static play_source table_source(table *t, double rate, int fast)
{
	play_source src = { t, table_next, table_seek, t->frames, rate, fast };
	t->next = t->reads = t->seeks = 0;
	return src;
}

static void load_arm(void)
{
	skp_error err;
	assert_int_equal(test_parse_asf(arm, strlen(arm), &s, &err), SKP_OK);
	assert_int_equal(s.dof_count, 11);
}

/* A swinging arm walking along x: frame i at time i / rate. */
static void fill_swing(table *t, long frames, double rate, float walk_per_s)
{
	t->frames = frames;
	for (long i = 0; i < frames; i++) {
		double ts = (double)i / rate;
		float *v = t->v[i];
		memset(v, 0, sizeof t->v[0]);
		v[0] = walk_per_s * (float)ts;
		v[7] = (float)(0.9 * sin(2.0 * M_PI * 0.7 * ts)); /* upper rz */
		v[6] = (float)(0.5 * sin(2.0 * M_PI * 1.3 * ts)); /* upper ry */
		v[9] = (float)(0.8 * sin(2.0 * M_PI * 0.9 * ts + 1.0)); /* lower rx */
	}
}

static double dist3(vec3 a, vec3 b)
{
	double x = (double)a.x - b.x, y = (double)a.y - b.y, z = (double)a.z - b.z;
	return sqrt(x * x + y * y + z * z);
}

static double pose_gap(const skel_pose *a, const skel_pose *b)
{
	double m = 0;
	for (int i = 0; i < s.count; i++)
		m = fmax(m, dist3(a->tip[i], b->tip[i]));
	return m;
}

static void setup_engine(play_engine *e, double speed, uint32_t blend, int root, int loop)
{
	play_config c = { speed, blend, root, loop };
	play_init(e, &s, &c);
}

static void test_slerp_matches_double_reference(void **state)
{
	(void)state;
	test_rng_seed(7);
	double worst = 0;
	for (int k = 0; k < 20000; k++) {
		quat a = quat_normalize((quat){ test_rng_range(-1, 1), test_rng_range(-1, 1), test_rng_range(-1, 1), test_rng_range(-1, 1) });
		quat d = quat_from_axis_angle(vec3_normalize(vec3_make(test_rng_range(-1, 1), test_rng_range(-1, 1), test_rng_range(-1, 1))),
					      (float)(k % 3 == 0 ? 3.1 * test_rng_range(0, 1) : 0.05 * test_rng_range(0, 1)));
		quat b = quat_mul(d, a);
		if (k & 1)
			b = (quat){ -b.w, -b.x, -b.y, -b.z }; /* the same rotation: the short way still */
		float t = (float)test_rng_range(0, 1);
		quat q = quat_slerp(a, b, t);
		/* reference: double, acos */
		double bw = b.w, bx = b.x, by = b.y, bz = b.z;
		double dot = (double)a.w * bw + (double)a.x * bx + (double)a.y * by + (double)a.z * bz;
		if (dot < 0) {
			dot = -dot; bw = -bw; bx = -bx; by = -by; bz = -bz;
		}
		double th = acos(fmin(1.0, dot)), wa = 1 - t, wb = t;
		if (th > 1e-9) {
			wa = sin((1 - t) * th) / sin(th);
			wb = sin(t * th) / sin(th);
		}
		double rw = wa * a.w + wb * bw, rx = wa * a.x + wb * bx, ry = wa * a.y + wb * by, rz = wa * a.z + wb * bz;
		double n = sqrt(rw * rw + rx * rx + ry * ry + rz * rz);
		double e = fabs(q.w - rw / n) + fabs(q.x - rx / n) + fabs(q.y - ry / n) + fabs(q.z - rz / n);
		worst = fmax(worst, e);
	}
	print_message("slerp against double: worst component sum %.3g\n", worst);
	assert_true(worst < 2e-6);
}

static void test_local_then_fk_is_fk_pose_bit_for_bit(void **state)
{
	(void)state;
	static skel_local l;
	static skel_pose a, b;
	load_arm();
	fill_swing(&clip, 50, 120.0, 30.0f);
	for (int i = 0; i < 50; i++) {
		float v[SKP_MAX_DOF] = { 0 };
		memcpy(v, clip.v[i], sizeof clip.v[0]);
		fk_pose(&s, v, &a);
		fk_local(&s, v, &l);
		fk_from_local(&s, &l, &b);
		assert_memory_equal(&a, &b, sizeof a);
	}
}

/* At a captured frame's time the engine shows exactly that frame. */
static void test_captured_times_are_the_frames(void **state)
{
	(void)state;
	static play_engine e;
	static skel_pose want;
	skp_error err;
	load_arm();
	fill_swing(&clip, 300, 120.0, 30.0f);
	play_source src = table_source(&clip, 120.0, 0);
	setup_engine(&e, 1.0, 0, PLAY_ROOT_TRAVEL, 0);
	assert_int_equal(play_start(&e, &src, 0, &err), SKP_OK);
	for (long i = 0; i < 300; i += 7) {
		float v[SKP_MAX_DOF] = { 0 };
		memcpy(v, clip.v[i], sizeof clip.v[0]);
		fk_pose(&s, v, &want);
		assert_int_equal(play_update(&e, play_display_time(i, 120.0), &err), SKP_OK);
		assert_int_equal(e.number, i + 1);
		assert_memory_equal(&e.pose, &want, sizeof want);
	}
}

/* Between frames: each rotation slerped, so a turn of 90 degrees about one
 * axis is 45 degrees half way, and Euler values that wrap (179 then -179,
 * 10 then 370) turn the short way. */
static void test_interpolation_short_arc(void **state)
{
	(void)state;
	static play_engine e;
	static skel_pose want;
	skp_error err;
	static const float pairs[][3] = { { 0, 90, 45 }, { 179, -179, 180 }, { 10, 370, 10 }, { -170, 170, 180 } };
	load_arm();
	for (int k = 0; k < 4; k++) {
		memset(&clip, 0, sizeof clip);
		clip.frames = 2;
		clip.v[0][8] = pairs[k][0] * DEG; /* upper rz */
		clip.v[1][8] = pairs[k][1] * DEG;
		play_source src = table_source(&clip, 10.0, 0);
		setup_engine(&e, 1.0, 0, PLAY_ROOT_TRAVEL, 0);
		assert_int_equal(play_start(&e, &src, 0, &err), SKP_OK);
		assert_int_equal(play_sample_at(&e, 0.05, &err), SKP_OK);
		float v[SKP_MAX_DOF] = { 0 };
		v[8] = pairs[k][2] * DEG;
		fk_pose(&s, v, &want);
		double gap = pose_gap(&e.pose, &want);
		if (gap > 1e-5)
			fail_msg("%g then %g degrees: half way %g from %g degrees", pairs[k][0], pairs[k][1], gap,
				 pairs[k][2]);
	}
}

/* Render rates 24, 60 and 144 Hz and a jittered one: the captured frame
 * shown is the one the clock says, the frames between read and dropped,
 * nothing sought until the loop. */
static void test_clock_drives_the_clip_at_any_rate(void **state)
{
	(void)state;
	static play_engine e;
	skp_error err;
	static const double rates[] = { 24.0, 60.0, 144.0, 0.0 };
	test_rng_seed(11);
	load_arm();
	fill_swing(&clip, 1200, 120.0, 30.0f); /* 10 s */
	for (int k = 0; k < 4; k++) {
		play_source src = table_source(&clip, 120.0, 0);
		setup_engine(&e, 1.0, 300, PLAY_ROOT_IN_PLACE, 1);
		assert_int_equal(play_start(&e, &src, 0, &err), SKP_OK);
		uint64_t now = 0;
		for (int n = 0; now < 9000000000ull; n++) {
			/* jittered: 5 to 45 ms a frame */
			now = rates[k] > 0 ? play_display_time(n, rates[k]) : now + (uint64_t)(5e6 + 40e6 * test_rng_range(0, 1));
			assert_int_equal(play_update(&e, now, &err), SKP_OK);
			double t = (double)now * 1e-9;
			assert_true(fabs(e.clip_time - t) < 1e-9);
			assert_int_equal(e.number, (long)floor(t * 120.0 + 1e-6) + 1);
		}
		assert_int_equal(clip.seeks, 1); /* the start only */
		/* every frame up to the last shown and the one after it, once */
		if (clip.reads != e.number + 1)
			fail_msg("%g Hz: %ld frames read to show frame %ld", rates[k], clip.reads, e.number);
	}
}

static void test_pause_and_speed(void **state)
{
	(void)state;
	static play_engine e;
	skp_error err;
	load_arm();
	fill_swing(&clip, 1200, 120.0, 30.0f);
	play_source src = table_source(&clip, 120.0, 0);
	setup_engine(&e, 0.5, 0, PLAY_ROOT_IN_PLACE, 1);
	assert_int_equal(play_start(&e, &src, 1000000000ull, &err), SKP_OK);
	assert_int_equal(play_update(&e, 3000000000ull, &err), SKP_OK);
	assert_true(fabs(e.clip_time - 1.0) < 1e-9); /* 2 s at half speed */
	play_pause(&e, 1, 3000000000ull);
	assert_int_equal(play_update(&e, 7000000000ull, &err), SKP_OK);
	assert_true(fabs(e.clip_time - 1.0) < 1e-9);
	play_pause(&e, 0, 7000000000ull);
	assert_int_equal(play_update(&e, 8000000000ull, &err), SKP_OK);
	assert_true(fabs(e.clip_time - 1.5) < 1e-9);
	/* 343 frames at 120 Hz: 172 display frames at 60 Hz, 344 at half speed */
	clip.frames = 343;
	src = table_source(&clip, 120.0, 0);
	setup_engine(&e, 1.0, 0, PLAY_ROOT_IN_PLACE, 1);
	assert_int_equal(play_start(&e, &src, 0, &err), SKP_OK);
	assert_int_equal(play_pass_frames(&e, 60.0), 172);
	setup_engine(&e, 0.5, 0, PLAY_ROOT_IN_PLACE, 1);
	assert_int_equal(play_start(&e, &src, 0, &err), SKP_OK);
	assert_int_equal(play_pass_frames(&e, 60.0), 344);
}

/* Display frames at 60 Hz over two loops: the largest joint move a frame
 * within the fade after each seam, and elsewhere. */
static void seam_moves(uint32_t blend_ms, int root, double *seam, double *elsewhere, double *root_step)
{
	static play_engine e;
	static skel_pose prev;
	skp_error err;
	play_source src = table_source(&clip, 120.0, 0);
	setup_engine(&e, 1.0, blend_ms, root, 1);
	assert_int_equal(play_start(&e, &src, 0, &err), SKP_OK);
	double d = play_duration(&e), fade = (blend_ms ? blend_ms : 50) * 1e-3;
	*seam = *elsewhere = *root_step = 0;
	for (long f = 0; f < 360; f++) {
		uint64_t now = play_display_time(f, 60.0);
		assert_int_equal(play_update(&e, now, &err), SKP_OK);
		double t = (double)now * 1e-9;
		if (f) {
			double m = pose_gap(&e.pose, &prev);
			if (t > d && fmod(t, d) <= fade + 1e-9)
				*seam = fmax(*seam, m);
			else
				*elsewhere = fmax(*elsewhere, m);
			*root_step = fmax(*root_step, fabs((double)e.pose.tip[0].x - prev.tip[0].x));
		}
		prev = e.pose;
	}
}

static double frames_gap(const table *t, long a, long b)
{
	static skel_pose pa, pb;
	float va[SKP_MAX_DOF] = { 0 }, vb[SKP_MAX_DOF] = { 0 };
	memcpy(va, t->v[a], sizeof t->v[0]);
	memcpy(vb, t->v[b], sizeof t->v[0]);
	va[0] = vb[0] = 0; /* in place */
	fk_pose(&s, va, &pa);
	fk_pose(&s, vb, &pb);
	return pose_gap(&pa, &pb);
}

static void test_loops_without_seams(void **state)
{
	(void)state;
	double cut, fade, travel, natural, root_cut, root_fade, root_travel;
	load_arm();
	fill_swing(&clip, 300, 120.0, 30.0f); /* 2.5 s, ending far from its start */
	double gap = frames_gap(&clip, 299, 0);
	seam_moves(0, PLAY_ROOT_IN_PLACE, &cut, &natural, &root_cut);
	seam_moves(300, PLAY_ROOT_IN_PLACE, &fade, &natural, &root_fade);
	seam_moves(300, PLAY_ROOT_TRAVEL, &travel, &natural, &root_travel);
	/* the fade spreads the gap over its 18 frames at a rate of at most
	 * 1 / 0.85 of the even share, on top of the clip's own motion */
	double bound = natural + gap / 0.85 / 18.0;
	print_message("loop: end-to-start gap %.3f; largest move a frame: cut %.3f, crossfade %.3f (bound %.3f), "
		      "travel %.3f, elsewhere %.3f\n", gap, cut, fade, bound, travel, natural);
	assert_true(cut > 0.9 * gap);
	assert_true(fade <= bound);
	assert_true(travel <= bound + 0.5); /* and the root walking on */
	assert_true(root_fade == 0.0);      /* in place: the root never moves along x */
	/* travel: the root walks on at 30 a second (0.5 a frame), never back */
	assert_true(root_travel < 0.5 + 1e-3);
}

/* NEXT: a crossfade from the pose on screen into the new clip. */
static void test_clip_change_fades_from_the_pose_shown(void **state)
{
	(void)state;
	static play_engine e;
	static table other;
	static skel_pose before;
	skp_error err;
	load_arm();
	fill_swing(&clip, 600, 120.0, 0.0f);
	fill_swing(&other, 600, 120.0, 0.0f);
	for (long i = 0; i < 600; i++)
		other.v[i][8] = 1.2f; /* the new clip holds the lower arm up */
	play_source a = table_source(&clip, 120.0, 0), b = table_source(&other, 120.0, 0);
	setup_engine(&e, 1.0, 300, PLAY_ROOT_IN_PLACE, 1);
	assert_int_equal(play_start(&e, &a, 0, &err), SKP_OK);
	assert_int_equal(play_update(&e, 1000000000ull, &err), SKP_OK);
	before = e.pose;
	assert_int_equal(play_start(&e, &b, 1000000000ull, &err), SKP_OK);
	assert_int_equal(play_update(&e, 1000000000ull, &err), SKP_OK);
	assert_true(pose_gap(&e.pose, &before) < 1e-6); /* the first frame is the old pose */
	double worst = 0;
	skel_pose prev = e.pose;
	for (int f = 1; f <= 30; f++) {
		assert_int_equal(play_update(&e, 1000000000ull + play_display_time(f, 60.0), &err), SKP_OK);
		worst = fmax(worst, pose_gap(&e.pose, &prev));
		prev = e.pose;
	}
	assert_false(e.fading); /* over after 300 ms */
	/* the gap between the poses spread over the fade's 18 frames, plus
	 * the new clip's own motion over a display frame (two captured) */
	double natural = 0;
	for (long i = 0; i + 2 <= 40; i++)
		natural = fmax(natural, frames_gap(&other, i, i + 2));
	double bound = pose_gap(&before, &e.pose) / 0.85 / 18.0 + natural;
	print_message("clip change: largest move a frame %.3f (bound %.3f)\n", worst, bound);
	assert_true(worst <= bound);
}

/* A display at 10 Hz over a source that seeks by block: far jumps seek
 * instead of reading every frame. */
static void test_fast_sources_seek_ahead(void **state)
{
	(void)state;
	static play_engine e;
	skp_error err;
	load_arm();
	fill_swing(&clip, 1200, 120.0, 30.0f);
	play_source src = table_source(&clip, 120.0, 1);
	setup_engine(&e, 1.0, 0, PLAY_ROOT_IN_PLACE, 0);
	assert_int_equal(play_start(&e, &src, 0, &err), SKP_OK);
	for (int n = 0; n < 90; n++)
		assert_int_equal(play_update(&e, play_display_time(n, 10.0), &err), SKP_OK);
	assert_true(clip.reads < 200);
	assert_int_equal(e.number, 89 * 12 + 1);
}

/* A clip that ends before its count: its last frame holds. */
static void test_short_source_holds_its_last_frame(void **state)
{
	(void)state;
	static play_engine e;
	skp_error err;
	load_arm();
	fill_swing(&clip, 100, 120.0, 30.0f);
	play_source src = table_source(&clip, 120.0, 0);
	src.frames = 150; /* the header said more */
	setup_engine(&e, 1.0, 0, PLAY_ROOT_TRAVEL, 0);
	assert_int_equal(play_start(&e, &src, 0, &err), SKP_OK);
	assert_int_equal(play_update(&e, 1200000000ull, &err), SKP_OK);
	assert_int_equal(e.number, 100);
	assert_int_equal(e.cur.last, 99);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_slerp_matches_double_reference),
		cmocka_unit_test(test_local_then_fk_is_fk_pose_bit_for_bit),
		cmocka_unit_test(test_captured_times_are_the_frames),
		cmocka_unit_test(test_interpolation_short_arc),
		cmocka_unit_test(test_clock_drives_the_clip_at_any_rate),
		cmocka_unit_test(test_pause_and_speed),
		cmocka_unit_test(test_loops_without_seams),
		cmocka_unit_test(test_clip_change_fades_from_the_pose_shown),
		cmocka_unit_test(test_fast_sources_seek_ahead),
		cmocka_unit_test(test_short_source_holds_its_last_frame),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
