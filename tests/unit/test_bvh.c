/* BVH: the hierarchy as a skeleton and the frames streamed, checked
 * against FK computed here with double matrices straight from the BVH
 * rules (a joint's world rotation is its parent's times the product of its
 * rotation channels in the order listed; a child sits at the parent's
 * position plus the parent's rotation of its OFFSET, or of its position
 * channels); channel orders, 1 to 6 channels, siblings, End Sites, CRLF,
 * tabs, broken input with the line named, streaming memory, and the real
 * CMU conversion in ../shared/data. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fk.h"
#include "test_dref.h"
#include "test_parse.h"
#include "test_paths.h"

#define PI 3.14159265358979323846

static skel s;
static skel_pose pose;

typedef dmat3 mat;

/* axis 'X', 'Y' or 'Z', degrees */
static mat rot(char axis, double deg)
{
	return dmat3_rot(axis - 'X', deg * PI / 180);
}

static void apply(mat m, const double v[3], double out[3])
{
	for (int i = 0; i < 3; i++)
		out[i] = m.m[i][0] * v[0] + m.m[i][1] * v[1] + m.m[i][2] * v[2];
}

static void add(double a[3], const double b[3])
{
	a[0] += b[0]; a[1] += b[1]; a[2] += b[2];
}

static void assert_near(vec3 got, const double want[3], const char *what)
{
	double d = fabs(got.x - want[0]) + fabs(got.y - want[1]) + fabs(got.z - want[2]);
	if (d > 1e-4)
		fail_msg("%s: got %g %g %g, want %g %g %g", what, (double)got.x, (double)got.y, (double)got.z,
			 want[0], want[1], want[2]);
}

typedef struct frames {
	long n;
	float value[4][64];
} frames;

static void keep(const amc_frame *f, void *ctx)
{
	frames *fr = ctx;
	if (fr->n < 4)
		memcpy(fr->value[fr->n], f->value, sizeof fr->value[0]);
	fr->n++;
}

static long stream(const char *text, frames *fr, skp_error *err)
{
	memset(fr, 0, sizeof *fr);
	return test_stream_bvh(text, strlen(text), &s, err, keep, fr);
}

/* Each joint's rotation channels in its own order, the root's position. */
static void test_channel_orders_match_the_bvh_rules(void **state)
{
	(void)state;
	const char *t =
		"HIERARCHY\n"
		"ROOT hips\n{\n  OFFSET 0 0 0\n"
		"  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
		"  JOINT arm\n  {\n    OFFSET 0 2 0\n    CHANNELS 3 Yrotation Zrotation Xrotation\n"
		"    End Site\n    {\n      OFFSET 1 0 0\n    }\n  }\n}\n"
		"MOTION\nFrames: 1\nFrame Time: 0.01\n"
		"1 2 3 30 -20 45 10 70 -35\n";
	frames fr;
	skp_error err;
	assert_int_equal(stream(t, &fr, &err), 1);
	assert_int_equal(s.count, 2);
	assert_int_equal(s.dof_count, 9);
	fk_pose(&s, fr.value[0], &pose);

	mat w0 = dmat3_mul(dmat3_mul(rot('Z', 30), rot('X', -20)), rot('Y', 45));
	mat w1 = dmat3_mul(w0, dmat3_mul(dmat3_mul(rot('Y', 10), rot('Z', 70)), rot('X', -35)));
	double p0[3] = { 1, 2, 3 }, off[3] = { 0, 2, 0 }, end[3] = { 1, 0, 0 }, d[3];
	assert_near(pose.tip[0], p0, "root");
	double p1[3] = { p0[0], p0[1], p0[2] };
	apply(w0, off, d);
	add(p1, d);
	assert_near(pose.head[1], p1, "arm joint");
	apply(w1, end, d);
	add(p1, d);
	assert_near(pose.tip[1], p1, "arm end site");
}

/* A second child away from the first one's OFFSET, a joint with position
 * channels (they replace its OFFSET), a root without positions, 1 and 2
 * channel joints. */
static void test_siblings_and_joint_positions(void **state)
{
	(void)state;
	const char *t =
		"HIERARCHY\nROOT r\n{\n OFFSET 5 0 0\n CHANNELS 3 Xrotation Yrotation Zrotation\n"
		" JOINT a\n {\n  OFFSET 0 1 0\n  CHANNELS 1 Zrotation\n"
		"  JOINT b\n  {\n   OFFSET 0 1 0\n   CHANNELS 2 Xrotation Yrotation\n"
		"   End Site\n   {\n    OFFSET 0 1 0\n   }\n  }\n"
		"  JOINT c\n  {\n   OFFSET 1 0 0\n"
		"   CHANNELS 6 Xposition Yposition Zposition Xrotation Yrotation Zrotation\n"
		"   End Site\n   {\n    OFFSET 0 0 1\n   }\n  }\n }\n}\n"
		"MOTION\nFrames: 2\nFrame Time: 0.5\n"
		"0 0 0  0  0 0  1 0 0 0 0 0\n"
		"10 20 30  40  -50 60  2 0.5 -1 15 25 35\n";
	frames fr;
	skp_error err;
	assert_int_equal(stream(t, &fr, &err), 2);
	assert_int_equal(s.count, 4);
	for (int f = 0; f < 2; f++) {
		const float *v = fr.value[f];
		fk_pose(&s, v, &pose);
		double in[12];
		const char *l = f ? "10 20 30 40 -50 60 2 0.5 -1 15 25 35" : "0 0 0 0 0 0 1 0 0 0 0 0";
		for (int i = 0; i < 12; i++)
			in[i] = strtod(l, (char **)&l);
		mat wr = dmat3_mul(dmat3_mul(rot('X', in[0]), rot('Y', in[1])), rot('Z', in[2]));
		mat wa = dmat3_mul(wr, rot('Z', in[3]));
		mat wb = dmat3_mul(wa, dmat3_mul(rot('X', in[4]), rot('Y', in[5])));
		mat wc = dmat3_mul(wa, dmat3_mul(dmat3_mul(rot('X', in[9]), rot('Y', in[10])), rot('Z', in[11])));
		double pr[3] = { 5, 0, 0 }, d[3], y1[3] = { 0, 1, 0 }, z1[3] = { 0, 0, 1 };
		double pa[3] = { pr[0], pr[1], pr[2] };
		apply(wr, y1, d);
		add(pa, d);
		double pb[3] = { pa[0], pa[1], pa[2] }, pc[3] = { pa[0], pa[1], pa[2] };
		apply(wa, y1, d);
		add(pb, d);
		apply(wa, in + 6, d);
		add(pc, d);
		double eb[3] = { pb[0], pb[1], pb[2] }, ec[3] = { pc[0], pc[1], pc[2] };
		apply(wb, y1, d);
		add(eb, d);
		apply(wc, z1, d);
		add(ec, d);
		assert_near(pose.tip[0], pr, "root");
		assert_near(pose.head[1], pa, "a");
		assert_near(pose.head[2], pb, "b");
		assert_near(pose.tip[2], eb, "b's end site");
		assert_near(pose.head[3], pc, "c (position channels)");
		assert_near(pose.tip[3], ec, "c's end site");
	}
}

/* CRLF, tabs, keywords in any case, a blank line between frames, a joint
 * without channels. */
static void test_crlf_tabs_and_case(void **state)
{
	(void)state;
	const char *t = "hierarchy\r\nroot\tHips\r\n{\r\n\toffset\t0\t1\t0\r\n"
			"\tchannels 3 Zrotation Yrotation Xrotation\r\n\tjoint\tj\r\n\t{\r\n\t\tOFFSET 0 1 0\r\n"
			"\t\tCHANNELS 0\r\n\t\tend site\r\n\t\t{\r\n\t\t\tOFFSET 0 0 2\r\n\t\t}\r\n\t}\r\n}\r\n"
			"motion\r\nFrames:\t2\r\nFrame Time:\t0.0083333\r\n90\t0\t0\r\n\r\n0 0 90\r\n";
	frames fr;
	skp_error err;
	long n = stream(t, &fr, &err);
	if (n != 2)
		fail_msg("%ld frames: line %ld %s", n, err.line, err.msg);
	assert_int_equal(s.count, 2);
	assert_int_equal(s.dof_count, 3);
	/* Zrotation 90 turns +Y into -X; the joint's end site follows */
	fk_pose(&s, fr.value[0], &pose);
	assert_near(pose.tip[0], (double[3]){ 0, 1, 0 }, "root");
	assert_near(pose.head[1], (double[3]){ -1, 1, 0 }, "j, frame 1");
	assert_near(pose.tip[1], (double[3]){ -1, 1, 2 }, "j's end site, frame 1");
	/* Xrotation 90 turns +Y into +Z and +Z into -Y */
	fk_pose(&s, fr.value[1], &pose);
	assert_near(pose.head[1], (double[3]){ 0, 1, 1 }, "j, frame 2");
	assert_near(pose.tip[1], (double[3]){ 0, -1, 1 }, "j's end site, frame 2");
}

typedef struct bad_case {
	const char *text;
	long line;
	const char *needle;
} bad_case;

#define HEAD "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n CHANNELS 3 Xrotation Yrotation Zrotation\n" \
	" End Site\n {\n  OFFSET 0 1 0\n }\n}\n"

static const bad_case bad[] = {
	{ "", 0, "unexpected end of file: expected 'HIERARCHY'" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n", 4, "unexpected end of file in the HIERARCHY" },
	{ "ASF\n", 1, "expected 'HIERARCHY', found 'ASF'" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0\n}\n", 5, "OFFSET: expected a finite number, found '}'" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 nan\n}\n", 4, "found 'nan'" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 1e39\n}\n", 4, "found '1e39'" },
	{ "HIERARCHY\nROOT r\n{\n CHANNELS 3 Xrotation Yrotation Wrotation\n", 4, "unknown channel 'Wrotation'" },
	{ "HIERARCHY\nROOT r\n{\n CHANNELS 7 Xrotation\n", 4, "expected a count from 0 to 6, found 7" },
	{ "HIERARCHY\nROOT r\n{\n CHANNELS 2 Xrotation Xrotation\n", 4, "channel 'Xrotation' listed twice" },
	{ "HIERARCHY\nROOT r\n{\n CHANNELS 0\n}\n", 5, "joint 'r' has no OFFSET" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n wobble\n", 5, "expected OFFSET, CHANNELS, JOINT, End Site or '}', found 'wobble'" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n JOINT r\n", 5, "joint name 'r' used twice" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n JOINT a\x01\x62\n", 5, "joint name 'a\\x01b': expected letters" },
	{ "HIERARCHY\nROOT a_very_long_joint_name_that_goes_on_and_on_forever_and_ever\n", 2, "SKP_MAX_NAME" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n End Place\n", 5, "expected 'Site', found 'Place'" },
	{ HEAD, 10, "unexpected end of file: expected 'MOTION'" },
	{ HEAD "Motion\n", 11, "unexpected end of file: expected 'Frames:'" },
	{ HEAD "MOTION\nFrames: -1\n", 12, "Frames: expected a whole count, found -1" },
	{ HEAD "MOTION\nFrames: 1.5\n", 12, "whole count" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 0\n", 13, "expected seconds per frame from 0.000001 to 10, found 0" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 1e-300\n", 13, "from 0.000001 to 10" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 0.0000009\n", 13, "from 0.000001 to 10" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 10.5\n", 13, "from 0.000001 to 10" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n JOINT a\n {\n  OFFSET 3e38 0 0\n  End Site\n  {\n   OFFSET 1 0 0\n  }\n"
	  " }\n}\nMOTION\nFrames: 0\nFrame Time: 0.1\n", 0, "joint 'a': the skeleton reaches beyond" },
	{ "HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n CHANNELS 3 Xposition Yposition Zposition\n End Site\n {\n  OFFSET 0 1 0\n"
	  " }\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n1e30 0 0\n", 14, "'1e30' is beyond the skeleton's range" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 0.1 x\n", 13, "unexpected 'x' after Frame Time" },
	{ HEAD "MOTION\nFrames: 2\nFrame Time: 0.1\n1 2 3\n1 2\n", 15, "frame 2: expected 3 values, found 2" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 0.1\n1 2 3 4\n", 14, "frame 1: more than the 3 values" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 0.1\n1 two 3\n", 14, "frame 1: expected a finite number, found 'two'" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 0.1\n1 inf 3\n", 14, "found 'inf'" },
	{ HEAD "MOTION\nFrames: 1\nFrame Time: 0.1\n1 2 1e41\n", 14, "beyond a float's range" },
};

static void test_broken_inputs_name_line_and_expectation(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		frames fr;
		skp_error err;
		memset(&err, 0, sizeof err);
		long n = stream(bad[i].text, &fr, &err);
		if (n >= 0 || err.line != bad[i].line || !strstr(err.msg, bad[i].needle))
			fail_msg("case %zu: %ld, line %ld '%s' (wanted line %ld, '%s')", i, n, err.line,
				 err.msg, bad[i].line, bad[i].needle);
	}
}

/* "Frames: 3" with two frame lines: two frames, then the shortfall. */
static void test_file_ending_early_counts_the_missing_frames(void **state)
{
	(void)state;
	const char *t = HEAD "MOTION\nFrames: 3\nFrame Time: 0.1\n1 2 3\n4 5 6\n";
	static text_lines tl;
	static bvh_layout lay;
	static bvh_stream b;
	static amc_frame f;
	skp_mem_source src;
	skp_error err;
	text_lines_init(&tl, skp_mem_reader(&src, t, strlen(t)));
	assert_int_equal(bvh_parse(&s, &lay, &tl, &err), SKP_OK);
	assert_int_equal(lay.frames, 3);
	assert_true(fabs(lay.frame_time - 0.1) < 1e-12);
	bvh_open(&b, &s, &lay, &tl);
	assert_int_equal(bvh_next(&b, &f, &err), 1);
	assert_int_equal(f.number, 1);
	assert_int_equal(bvh_next(&b, &f, &err), 1);
	/* skel applies the last listed rotation (Zrotation) first */
	assert_true(fabsf(f.value[0] - 6.0f * (float)(PI / 180)) < 1e-6f);
	assert_int_equal(bvh_next(&b, &f, &err), 0);
	assert_int_equal(b.cut_frames, 1);
}

/* A generated clip of n frames, one line at a time: nothing is kept. */
typedef struct gen {
	long frames, line;
	const char *head;
	size_t head_pos;
	char buf[64];
	size_t len, pos;
} gen;

static long gen_read(void *ctx, void *out, size_t cap)
{
	gen *g = ctx;
	if (g->pos == g->len) {
		if (g->head[g->head_pos]) {
			size_t n = strlen(g->head + g->head_pos);
			n = n < sizeof g->buf ? n : sizeof g->buf;
			memcpy(g->buf, g->head + g->head_pos, n);
			g->head_pos += n;
			g->len = n;
		} else if (g->line < g->frames) {
			g->len = (size_t)snprintf(g->buf, sizeof g->buf, "%ld 0.5 -3\n", g->line++ % 360);
		} else {
			return 0;
		}
		g->pos = 0;
	}
	size_t n = g->len - g->pos < cap ? g->len - g->pos : cap;
	memcpy(out, g->buf + g->pos, n);
	g->pos += n;
	return (long)n;
}

static void test_streaming_memory_is_flat_in_clip_length(void **state)
{
	(void)state;
	size_t bytes = sizeof(bvh_stream) + sizeof(bvh_layout) + sizeof(text_lines) + sizeof(amc_frame);
	print_message("BVH streaming state: %zu bytes (a %d-byte line), whatever the clip length\n", bytes,
		      SKP_MAX_LINE);
	assert_true(bytes < SKP_MAX_LINE + 32 * 1024);
	static char head[256];
	static text_lines tl;
	static bvh_layout lay;
	static bvh_stream b;
	static amc_frame f;
	const long lengths[2] = { 10, 200000 };
	for (int k = 0; k < 2; k++) {
		snprintf(head, sizeof head, "%sMOTION\nFrames: %ld\nFrame Time: 0.01\n", HEAD, lengths[k]);
		gen g = { lengths[k], 0, head, 0, { 0 }, 0, 0 };
		skp_reader rd = { gen_read, &g };
		skp_error err;
		text_lines_init(&tl, rd);
		assert_int_equal(bvh_parse(&s, &lay, &tl, &err), SKP_OK);
		bvh_open(&b, &s, &lay, &tl);
		long n = 0;
		while (bvh_next(&b, &f, &err) > 0)
			n++;
		assert_int_equal(n, lengths[k]);
		assert_int_equal(b.cut_frames, 0);
	}
}

/* The CMU conversion: 31 joints, 96 values a frame, 994 frames; its
 * offsets are the ASF's direction x length (SOURCES.md). */
static void test_real_cmu_conversion(void **state)
{
	(void)state;
	const char *path = test_data_path("mocap/cmu_bvh/131_01.bvh");
	if (!path)
		skip();
	size_t size;
	char *text = test_read_file(path, &size);
	assert_non_null(text);
	frames fr;
	skp_error err;
	memset(&fr, 0, sizeof fr);
	long n = test_stream_bvh(text, size, &s, &err, keep, &fr);
	free(text);
	if (n != 994)
		fail_msg("%ld frames: line %ld %s", n, err.line, err.msg);
	assert_int_equal(s.count, 31);
	assert_int_equal(s.dof_count, 96);
	int hip = skel_find(&s, "LeftHip");
	assert_true(hip > 0);
	vec3 o = vec3_add(s.bone[hip].offset, vec3_scale(s.bone[s.bone[hip].parent].direction,
							 s.bone[s.bone[hip].parent].length));
	assert_true(fabsf(o.x - 1.24777f) < 1e-5f && fabsf(o.y + 1.64261f) < 1e-5f && fabsf(o.z - 0.71711f) < 1e-5f);
	/* first frame: Hips position as written */
	fk_pose(&s, fr.value[0], &pose);
	assert_true(fabsf(pose.tip[0].x - 5.23f) < 1e-4f && fabsf(pose.tip[0].y - 16.9002f) < 1e-4f);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_channel_orders_match_the_bvh_rules),
		cmocka_unit_test(test_siblings_and_joint_positions),
		cmocka_unit_test(test_crlf_tabs_and_case),
		cmocka_unit_test(test_broken_inputs_name_line_and_expectation),
		cmocka_unit_test(test_file_ending_early_counts_the_missing_frames),
		cmocka_unit_test(test_streaming_memory_is_flat_in_clip_length),
		cmocka_unit_test(test_real_cmu_conversion),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
