/* Flash images through the real tools: every clip in ../shared/data packs
 * (raw, and compressed for three) and decodes within the stated
 * quantisation, skintool info finding nothing bad; skintool fk of a packed
 * clip gives the source's rows within ACL's error, at frames and at
 * times, and bench-image its figures. Damaged images: test_image_cli_damage.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amc.h"
#include "file_reader.h"
#include "image_stream.h"
#include "show_source.h"
#include "storage_file.h"
#include "test_clips.h"
#include "test_imgcli.h"
#include "test_parse.h"
#include "test_paths.h"
#include "test_run.h"

/* Each frame of the image's clip against the AMC parsed from text: within
 * the clip's step / 2 on every dof (quantised), or within the directory's
 * worst-case errors, which pack measured on its own decode (compressed). */
static void compare_clip(const char *image, const char *asf_path, const char *amc_path, long frames)
{
	static skel s, s2;
	static storage_file sf;
	static skp_image im;
	static skp_clip_stream pl;
	static file_reader fr;
	static text_lines tl;
	static amc_stream as;
	static amc_frame want, got;
	skp_error err;
	assert_int_equal(test_parse_asf_file(asf_path, &s, &err), SKP_OK);
	assert_int_equal(show_storage_open(&sf, image), 0);
	assert_int_equal(skp_image_open(&im, &sf.bd, &err), SKP_OK);
	assert_int_equal(skp_image_load_skel(&im, &s2, &err), SKP_OK);
	assert_int_equal(s2.count, s.count);
	assert_int_equal(s2.dof_count, s.dof_count);
	assert_memory_equal(s2.bone, s.bone, sizeof(skel_bone) * (size_t)s.count);
	assert_int_equal(skp_clip_stream_open(&pl, &im, 0, &err), SKP_OK);
	assert_int_equal(im.clip[0].frame_count, frames);
	assert_int_equal(file_reader_open(&fr, amc_path), 0);
	text_lines_init(&tl, file_reader_as_reader(&fr));
	amc_open(&as, &s, &tl);
	double worst = 0, bound = 0;
	long n = 0;
	while (amc_next(&as, &want, &err) > 0) {
		assert_int_equal(skp_clip_stream_next(&pl, &got, &err), 1);
		assert_int_equal(got.number, want.number);
		for (int d = 0; d < s.dof_count; d++) {
			double e = fabs((double)got.value[d] - want.value[d]);
			double tol = pl.c.coded ? fmax(pl.c.max_rot_err, pl.c.max_trans_err) * (1 + 1e-6) + 1e-7
						: pl.qstep[d] * 0.5 * (1 + 1e-6) + 2e-7 * fabs(want.value[d]);
			if (e > tol)
				fail_msg("%s frame %ld dof %d: %.9g decoded, %.9g in the AMC (step %.3g)", amc_path,
					 want.number, d, (double)got.value[d], (double)want.value[d], (double)pl.qstep[d]);
			worst = fmax(worst, e);
			bound = fmax(bound, pl.c.coded ? fmax(pl.c.max_rot_err, pl.c.max_trans_err) : pl.qstep[d] * 0.5);
		}
		n++;
	}
	assert_int_equal(n, frames);
	assert_int_equal(skp_clip_stream_next(&pl, &got, &err), 0);
	printf("%s: %ld frames, worst error %.3g (stated bound %.3g)\n", amc_path, n, worst, bound);
	file_reader_close(&fr);
	storage_file_close(&sf);
}

static void test_pack_decode_every_clip(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	const int slow = test_slow();
	for (int i = 0; i < test_clip_count; i++) {
		/* under the sanitizers or an emulator the clips of 400 frames or
		 * fewer, as test_codec_corpus: the same code; natively every one */
		if (slow && test_clips[i].frames > 400)
			continue;
		char asf[1024], amc[1024];
		snprintf(asf, sizeof asf, "%s", test_data_path(test_clips[i].asf));
		snprintf(amc, sizeof amc, "%s", test_data_path(test_clips[i].amc));
		const char *image = test_scratch("clip.skn");
		assert_int_equal(test_run("%s pack --raw '%s' '%s' -o '%s' >/dev/null", test_tool_path("skintool"), asf, amc,
					  image), 0);
		assert_int_equal(imgcli_info_names(image, -1), 0);
		compare_clip(image, asf, amc, test_clips[i].frames);
		/* compressed (what pack writes by default): three clips, the
		 * encoder's time kept short (every clip's error is test_codec's);
		 * one when sampled */
		if (i > (slow ? 0 : 2))
			continue;
		assert_int_equal(test_run("%s pack '%s' '%s' -o '%s' >/dev/null", test_tool_path("skintool"), asf, amc, image), 0);
		assert_int_equal(imgcli_info_names(image, -1), 0);
		compare_clip(image, asf, amc, test_clips[i].frames);
	}
}

/* The largest distance between the positions of two fk CSVs (the same
 * rows, bone for bone), and of their quaternion components. */
static void csv_gap(const char *a, const char *b, long *rows, double *pos, double *rot)
{
	FILE *fa = fopen(a, "r"), *fb = fopen(b, "r");
	char la[512], lb[512];
	assert_non_null(fa);
	assert_non_null(fb);
	*rows = 0;
	*pos = *rot = 0;
	assert_non_null(fgets(la, sizeof la, fa));
	assert_non_null(fgets(lb, sizeof lb, fb));
	assert_string_equal(la, lb);
	while (fgets(la, sizeof la, fa)) {
		assert_non_null(fgets(lb, sizeof lb, fb));
		char wa[64], wb[64], ba[64], bb[64];
		double x[7], y[7];
		assert_int_equal(sscanf(la, "%63[^,],%63[^,],%lf,%lf,%lf,%lf,%lf,%lf,%lf", wa, ba, &x[0], &x[1], &x[2], &x[3],
					&x[4], &x[5], &x[6]), 9);
		assert_int_equal(sscanf(lb, "%63[^,],%63[^,],%lf,%lf,%lf,%lf,%lf,%lf,%lf", wb, bb, &y[0], &y[1], &y[2], &y[3],
					&y[4], &y[5], &y[6]), 9);
		assert_string_equal(wa, wb); /* frame or time */
		assert_string_equal(ba, bb); /* the bone */
		*pos = fmax(*pos, sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2])));
		for (int i = 3; i < 7; i++)
			*rot = fmax(*rot, fabs(x[i] - y[i]));
		++*rows;
	}
	assert_null(fgets(lb, sizeof lb, fb));
	fclose(fa);
	fclose(fb);
}

/* skintool fk of a packed (compressed) clip: the source's CSV, row for row,
 * every bone's tip within 0.03 cm (the joints within ACL's 0.01 cm shell
 * error; a tip past the last joint carries its rotation's error along the
 * bone), at frames and at times; bench-image's figures, ACL's skipped when
 * its anchor is not there. */
static void test_fk_and_bench_of_a_packed_clip(void **state)
{
	(void)state;
	char asf[1024], amc[1024];
	if (!imgcli_cmu_walk(asf, amc))
		skip();
	const char *image = test_scratch("fk.skn"), *a = test_scratch("a.csv"), *b = test_scratch("b.csv");
	const char *tool = test_tool_path("skintool");
	assert_int_equal(test_run("%s pack '%s' '%s' -o '%s' >/dev/null", tool, asf, amc, image), 0);
	static const char *const opts[] = { "", "--frame=100", "--time=0.5 --time=1.234 --time=9" };
	for (int i = 0; i < 3; i++) {
		long rows;
		double pos, rot;
		assert_int_equal(test_run("%s fk '%s' %s >'%s'", tool, image, opts[i], a), 0);
		assert_int_equal(test_run("%s fk '%s' '%s' %s >'%s'", tool, asf, amc, opts[i], b), 0);
		csv_gap(a, b, &rows, &pos, &rot);
		printf("fk %s: %ld rows, tips within %.4f cm, quaternions within %.2g\n", opts[i], rows, pos * 2.54, rot);
		assert_int_equal(rows, i == 0 ? 343 * 31 : i == 1 ? 31 : 3 * 31);
		assert_true(pos * 2.54 <= 0.03);
		assert_true(rot <= 2e-3);
	}
	assert_int_equal(test_run("%s fk '%s' --clip=02_01 --frame=1 >/dev/null", tool, image), 0);
	assert_int_equal(test_run("%s fk '%s' --clip=nope >/dev/null 2>&1", tool, image), 1);
	const char *out = test_scratch("bench.txt");
	assert_int_equal(test_run("%s bench-image '%s' --amc='%s' --runs=1 --acl=/nonexistent/acl_bench >'%s'", tool, image,
				  amc, out), 0);
	char *text = imgcli_slurp(out);
	double bytes, ratio, worst, p99;
	const char *at = strstr(text, "clip 02_01: compressed, ");
	assert_non_null(at);
	assert_int_equal(sscanf(at, "clip 02_01: compressed, %lf bytes a frame (%lf:1", &bytes, &ratio), 2);
	at = strstr(text, "worst ");
	assert_non_null(at);
	assert_int_equal(sscanf(at, "worst %lf cm, 99th percentile %lf cm", &worst, &p99), 2);
	assert_true(ratio >= 30 && fabs(bytes * ratio / (40.0 * 31) - 1) < 0.003); /* printed to 0.1 */
	assert_true(worst <= 0.01 && p99 <= worst && p99 > 0);
	assert_non_null(strstr(text, "ACL: skipped (/nonexistent/acl_bench"));
	free(text);
}

/* pack's default sequence is the clock's: one that says 1969 is refused
 * (no output), --sequence stands in for it, and an image packed by a
 * clock in 2100 is said by info to lie ahead of this machine's clock.
 * faketime sets the clock (skipped without it). */
static void test_sequence_from_the_clock(void **state)
{
	(void)state;
	if (test_run("command -v faketime >/dev/null") != 0) {
		print_message("faketime not installed (apt-get install faketime)\n");
		skip();
	}
	const char *tool = test_tool_path("skintool"), *image = test_scratch("clock.skn"), *err = test_scratch("clock.txt");
	const char *motion = "assets/cmu/02.asf assets/cmu/02_01.amc";
	/* libfaketime is preloaded: under ASan (SANITIZE=1) its runtime is then
	 * not the first library, which it refuses unless told */
	setenv("ASAN_OPTIONS", "verify_asan_link_order=0:detect_leaks=0", 1);
	assert_int_equal(test_run("faketime '1969-12-31 12:00:00' %s pack %s -q -o '%s' 2>'%s'", tool, motion, image, err),
			 1);
	static const char *const said[] = { "the clock says 1969-12-31", "--sequence N", NULL };
	test_assert_contains_all(err, said);
	assert_int_equal(test_run("test -e '%s'", image), 1);
	assert_int_equal(test_run("faketime '1969-12-31 12:00:00' %s pack %s -q --sequence=7 -o '%s'", tool, motion, image),
			 0);
	assert_int_equal(test_run("faketime '2100-01-01 12:00:00' %s pack %s -q -o '%s'", tool, motion, image), 0);
	assert_int_equal(test_run("%s info '%s' >'%s'", tool, image, err), 0);
	/* faketime's clock starts at its date and runs on: a slow pack (a
	 * loaded machine) is packed a few seconds past 12:00:00 */
	static const char *const ahead[] = { "sequence    41024880", "(packed 2100-01-01 12:0",
					     " UTC: ahead of this machine's clock", NULL };
	test_assert_contains_all(err, ahead);
	unsetenv("ASAN_OPTIONS");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_pack_decode_every_clip),
		cmocka_unit_test(test_fk_and_bench_of_a_packed_clip),
		cmocka_unit_test(test_sequence_from_the_clock),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
