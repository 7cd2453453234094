/* AMC streaming: header keywords, any bone order, absent bones, units,
 * broken input, and every real clip in ../shared/data. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_parse.h"
#include "test_clips.h"
#include "test_paths.h"

static skel s;

static const char *asf =
	":units\n angle deg\n:root\n order TX TY TZ RX RY RZ\n:bonedata\n"
	" begin\n name a\n direction 0 1 0\n length 1\n axis 0 0 0 XYZ\n dof rz rx\n end\n"
	" begin\n name b\n direction 1 0 0\n length 2\n axis 0 0 0 XYZ\n dof ry\n end\n"
	":hierarchy\n begin\n root a\n a b\n end\n";

static void load_skel(void)
{
	skp_error err;
	assert_int_equal(test_parse_asf(asf, strlen(asf), &s, &err), SKP_OK);
}

typedef struct frames {
	long n;
	long number[8];
	float value[8][16];
} frames;

static void keep(const amc_frame *f, void *ctx)
{
	frames *fr = ctx;
	if (fr->n < 8) {
		fr->number[fr->n] = f->number;
		memcpy(fr->value[fr->n], f->value, sizeof fr->value[0]);
	}
	fr->n++;
}

static long stream(const char *text, frames *fr, skp_error *err)
{
	memset(fr, 0, sizeof *fr);
	return test_stream_amc(text, strlen(text), &s, err, keep, fr);
}

static void test_any_order_absent_bones_unwrapped(void **state)
{
	(void)state;
	load_skel();
	const char *amc = "#!OML:ASF C:\\x\\f\xfcr.asf\r\n:FULLY-SPECIFIED\r\n:DEGREES\r\n"
			  "1\r\nroot 1 2 3 0 90 0\r\nb 987\r\na 10 -20\r\n"
			  "2\r\na 0 1251\r\n"
			  "3\r\n";
	frames fr;
	skp_error err;
	/* frame 3 has no bone at all, after frames that had some: the file was
	 * cut short there, and the frame is dropped (test_cut_last_frame_dropped) */
	assert_int_equal(stream(amc, &fr, &err), 2);
	assert_int_equal(fr.number[0], 1);
	const float d2r = (float)(M_PI / 180.0);
	assert_true(fr.value[0][0] == 1.0f && fr.value[0][2] == 3.0f); /* translation unscaled */
	assert_true(fabsf(fr.value[0][4] - 90 * d2r) < 1e-6f);
	assert_true(fabsf(fr.value[0][6] - 10 * d2r) < 1e-6f);   /* a: rz */
	assert_true(fabsf(fr.value[0][7] + 20 * d2r) < 1e-6f);   /* a: rx */
	assert_true(fabsf(fr.value[0][8] - 987 * d2r) < 1e-5f);  /* b: not wrapped */
	/* frame 2: root and b absent -> zero; a's rx is 1251 degrees */
	assert_true(fr.value[1][0] == 0.0f && fr.value[1][8] == 0.0f);
	assert_true(fabsf(fr.value[1][7] - 1251 * d2r) < 1e-5f);
}

/* A file that ends inside its last frame (fewer bones than the frame before
 * it) drops that frame and says which; a last frame as long as the others,
 * or the only frame, is kept. */
static void test_cut_last_frame_dropped(void **state)
{
	(void)state;
	load_skel();
	frames fr;
	skp_error err;
	static text_lines tl;
	static amc_stream as;
	static amc_frame f;
	skp_mem_source src;
	const char *cut = "1\nroot 1 2 3 4 5 6\na 1 2\nb 3\n2\nroot 1 2 3 4 5 6\na 1 2\nb 3\n3\nroot 1 2 3 4 5 6\n";
	text_lines_init(&tl, skp_mem_reader(&src, cut, strlen(cut)));
	amc_open(&as, &s, &tl);
	int n = 0;
	while (amc_next(&as, &f, &err) > 0)
		n++;
	assert_int_equal(n, 2);
	assert_int_equal(as.cut_frame, 3);
	assert_int_equal(as.cut_line, 9);
	assert_int_equal(stream("1\nroot 1 2 3 4 5 6\na 1 2\n2\nroot 1 2 3 4 5 6\na 1 2\n", &fr, &err), 2);
	assert_int_equal(stream("1\na 1 2\n", &fr, &err), 1);
}

static void test_radians_header(void **state)
{
	(void)state;
	load_skel();
	frames fr;
	skp_error err;
	assert_int_equal(stream(":RADIANS\n7\nb 1.5\n", &fr, &err), 1);
	assert_int_equal(fr.number[0], 7);
	assert_true(fr.value[0][8] == 1.5f);
}

typedef struct bad_case {
	const char *text;
	long line;
	const char *needle;
} bad_case;

static const bad_case bad[] = {
	{ ":DEGREES\nroot 1 2 3 4 5 6\n", 2, "expected a frame number" },
	{ "1\nroot 1 2 3 4 5\n", 2, "expected 6 value(s), found 5" },
	{ "1\nb 1 2\n", 2, "expected 1 value(s), found 2" },
	{ "1\nc 1\n", 2, "unknown bone 'c'" },
	{ "1\nb 1\nb 2\n", 3, "appears twice in frame 1" },
	{ "1\nb x\n", 2, "found 'x'" },
	{ "1\nb inf\n", 2, "finite number" },
	{ "1\nb 1\n2\na 3", 4, "expected 2 value(s), found 1" },
	{ "1\nroot 1 2 3 4 5 6 7 8 9 0 1 2 3 4 5 6 7 8 9 0 1 2 3 4 5 6 7 8 9 0 1 2 3\n", 2, "SKP_MAX_TOKENS" },
	/* finite as a double, infinite as the float a frame holds */
	{ "1\nb 1\n2\nb 1e308\n", 4, "value '1e308' is beyond a float's range" },
	{ "1\nroot 1 2 3e39 4 5 6\n", 2, "beyond a float's range" },
	/* a float, but a pose that far holds no finite joint */
	{ "1\nroot 1e30 2 3 4 5 6\n", 2, "translation '1e30' is beyond the skeleton's range" },
	/* a frame number too big for playback: not a bone's name */
	{ "1\nb 1\n99999999999999999999\n", 3, "frame number '99999999999999999999' out of range" },
	{ "2147483648\n", 1, "out of range (at most 2147483647)" },
	/* control characters in a quoted token are escaped */
	{ "1\nc\x1b[31m 1\n", 2, "unknown bone 'c\\x1b[31m'" },
};

static void test_broken_inputs(void **state)
{
	(void)state;
	load_skel();
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		frames fr;
		skp_error err;
		long r = stream(bad[i].text, &fr, &err);
		if (r >= 0 || err.line != bad[i].line || !strstr(err.msg, bad[i].needle))
			fail_msg("case %zu: r %ld line %ld '%s' (wanted line %ld '%s')", i, r, err.line,
				 err.msg, bad[i].line, bad[i].needle);
	}
}


typedef struct extremes {
	long frames, last;
	int consecutive;
	float max_abs_deg;
} extremes;

static void track(const amc_frame *f, void *ctx)
{
	extremes *e = ctx;
	if (e->frames && f->number != e->last + 1)
		e->consecutive = 0;
	e->last = f->number;
	e->frames++;
	for (int b = 0; b < s.count; b++)
		for (int i = 0; i < s.bone[b].channel_count; i++)
			if (s.bone[b].channel[i] <= SKEL_RZ)
				e->max_abs_deg = fmaxf(e->max_abs_deg,
						       fabsf(f->value[s.bone[b].dof_offset + i]) * 57.29578f);
}

static void test_real_clips(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	for (size_t i = 0; i < (size_t)test_clip_count; i++) {
		skp_error err;
		assert_int_equal(test_parse_asf_file(test_data_path(test_clips[i].asf), &s, &err), SKP_OK);
		size_t n;
		char *data = test_read_file(test_data_path(test_clips[i].amc), &n);
		assert_non_null(data);
		extremes e = { 0, 0, 1, 0 };
		long r = test_stream_amc(data, n, &s, &err, track, &e);
		if (r < 0)
			fail_msg("%s:%ld: %s", test_clips[i].amc, err.line, err.msg);
		assert_int_equal(r, test_clips[i].frames);
		assert_true(e.consecutive);
		assert_int_equal(e.last, test_clips[i].frames);
		print_message("%-40s %5ld frames, largest angle %.0f deg\n", test_clips[i].amc, r, e.max_abs_deg);
		/* every prefix of the first 40 KiB: a frame stream or a clean error */
		for (size_t cut = 0; cut < n && cut < 40000; cut += 997) {
			long rr = test_stream_amc(data, cut, &s, &err, NULL, NULL);
			assert_true(rr >= 0 || err.msg[0] != '\0');
		}
		free(data);
	}
}

/* :units length 0.5: the root's translations read in the same unit as
 * the bone lengths, both divided by 0.5. */
static void test_length_unit_applies_to_translations(void **state)
{
	(void)state;
	const char *scaled = ":units\n length 0.5\n angle deg\n:root\n order TX TY TZ RX RY RZ\n position 0 1 0\n"
			     ":bonedata\n begin\n name a\n direction 0 1 0\n length 1\n dof l\n end\n"
			     ":hierarchy\n begin\n root a\n end\n";
	skp_error err;
	assert_int_equal(test_parse_asf(scaled, strlen(scaled), &s, &err), SKP_OK);
	assert_true(fabsf(s.root_position.y - 2.0f) < 1e-6f);
	assert_true(fabsf(s.bone[1].length - 2.0f) < 1e-6f);
	frames fr;
	memset(&fr, 0, sizeof fr);
	const char *amc = ":DEGREES\n1\nroot 1 2 3 0 0 0\na 0.25\n";
	assert_int_equal(test_stream_amc(amc, strlen(amc), &s, &err, keep, &fr), 1);
	assert_true(fabsf(fr.value[0][0] - 2.0f) < 1e-6f && fabsf(fr.value[0][2] - 6.0f) < 1e-6f);
	assert_true(fabsf(fr.value[0][6] - 0.5f) < 1e-6f);   /* l */
	assert_true(fabsf(fr.value[0][3]) < 1e-9f);          /* angles untouched */
}

static void test_stream_state_is_fixed_size(void **state)
{
	(void)state;
	/* The whole streaming state is two fixed structs: no per-frame growth.
	 * One line (SKP_MAX_LINE), a 4 KiB read chunk and one frame of values. */
	size_t bytes = sizeof(amc_stream) + sizeof(text_lines) + sizeof(amc_frame);
	print_message("AMC streaming state: %zu bytes, whatever the clip length\n", bytes);
	assert_true(bytes < SKP_MAX_LINE + 12 * 1024);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_any_order_absent_bones_unwrapped),
		cmocka_unit_test(test_radians_header),
		cmocka_unit_test(test_length_unit_applies_to_translations),
		cmocka_unit_test(test_cut_last_frame_dropped),
		cmocka_unit_test(test_broken_inputs),
		cmocka_unit_test(test_real_clips),
		cmocka_unit_test(test_stream_state_is_fixed_size),
	};
	return cmocka_run_group_tests_name("amc", tests, NULL, NULL);
}
