/* Flash images through the real tools: every clip in ../shared/data packs
 * and decodes within the stated quantisation; skintool info names the
 * block of any flipped byte (every block of a small image, random bytes of
 * a big one) and exits 2; truncated and wrong-version images are refused;
 * skinplay rebuilds a bad block from parity (logging it once), holds over
 * one in an image without parity, and, given two slots, plays the newest
 * one with no block beyond repair. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "amc.h"
#include "crc32.h"
#include "file_reader.h"
#include "image_stream.h"
#include "show_source.h"
#include "storage_file.h"
#include "test_clips.h"
#include "test_parse.h"
#include "test_paths.h"
#include "test_run.h"


static char *slurp(const char *path)
{
	size_t n;
	char *t = test_read_file(path, &n);
	assert_non_null(t);
	return t;
}

static void flip_byte(const char *path, long at, int bit)
{
	FILE *f = fopen(path, "r+b");
	assert_non_null(f);
	assert_int_equal(fseek(f, at, SEEK_SET), 0);
	int c = fgetc(f);
	assert_true(c != EOF);
	assert_int_equal(fseek(f, at, SEEK_SET), 0);
	fputc(c ^ (1 << bit), f);
	fclose(f);
}

static void copy(const char *from, const char *to)
{
	assert_int_equal(test_run("cp '%s' '%s'", from, to), 0);
}

static long file_size(const char *path)
{
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	fclose(f);
	return n;
}

/* Runs skintool info; returns its status and checks that the only blocks
 * it names bad are want (-1: none). */
static int info_names(const char *image, long want)
{
	const char *out = test_scratch("info.txt");
	int st = test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), image, out);
	char *text = slurp(out);
	int named = 0;
	for (char *p = text; (p = strstr(p, "block ")) != NULL; p += 6) {
		long b;
		char word[8];
		if (sscanf(p + 6, "%ld %7s", &b, word) == 2 && !strcmp(word, "bad:")) {
			if (b != want)
				fail_msg("%s: block %ld named, expected %ld:\n%s", image, b, want, text);
			named++;
		}
	}
	if (want >= 0 && !named)
		fail_msg("%s: block %ld not named:\n%s", image, want, text);
	free(text);
	return st;
}

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
	for (int i = 0; i < test_clip_count; i++) {
		char asf[1024], amc[1024];
		snprintf(asf, sizeof asf, "%s", test_data_path(test_clips[i].asf));
		snprintf(amc, sizeof amc, "%s", test_data_path(test_clips[i].amc));
		const char *image = test_scratch("clip.skn");
		assert_int_equal(test_run("%s pack --raw '%s' '%s' -o '%s' >/dev/null", test_tool_path("skintool"), asf, amc,
					  image), 0);
		assert_int_equal(info_names(image, -1), 0);
		compare_clip(image, asf, amc, test_clips[i].frames);
		/* compressed (what pack writes by default): three clips, the
		 * encoder's time kept short (every clip's error is test_codec's) */
		if (i > 2)
			continue;
		assert_int_equal(test_run("%s pack '%s' '%s' -o '%s' >/dev/null", test_tool_path("skintool"), asf, amc, image), 0);
		assert_int_equal(info_names(image, -1), 0);
		compare_clip(image, asf, amc, test_clips[i].frames);
	}
}

/* A box mesh for the tiny arm: a small image in 512-byte blocks. */
static const char *small_image(void)
{
	static const char box[] =
		"v -0.1 -0.3 -0.3\nv 3.5 -0.3 -0.3\nv 3.5 0.3 -0.3\nv -0.1 0.3 -0.3\n"
		"v -0.1 -0.3 0.3\nv 3.5 -0.3 0.3\nv 3.5 0.3 0.3\nv -0.1 0.3 0.3\n"
		"f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
	static char image[512];
	const char *obj = test_scratch("box.obj"), *amc = test_scratch("wave.amc");
	snprintf(image, sizeof image, "%s", test_scratch("small.skn"));
	FILE *f = fopen(obj, "w");
	assert_non_null(f);
	fputs(box, f);
	fclose(f);
	/* a second clip long enough for several frame blocks */
	f = fopen(amc, "w");
	assert_non_null(f);
	fputs(":FULLY-SPECIFIED\n:DEGREES\n", f);
	for (int i = 1; i <= 150; i++)
		fprintf(f, "%d\nroot %g 0 0 0 %g 0\nupper %g 0 %g\nlower %g %g\n", i, i * 0.01, i * 0.5,
			30 * sin(i * 0.1), 10 * cos(i * 0.07), 45 * sin(i * 0.05), -20.0 + i * 0.1);
	fclose(f);
	assert_int_equal(test_run("%s pack tests/data/tiny.asf tests/data/tiny.amc '%s' --mesh '%s' "
			     "--block-size 512 --sequence 3 -o '%s' >/dev/null",
			     test_tool_path("skintool"), amc, obj, image), 0);
	return image;
}

static void test_info_names_every_block(void **state)
{
	(void)state;
	const char *image = small_image();
	char bad[512];
	snprintf(bad, sizeof bad, "%s", test_scratch("small_bad.skn"));
	long blocks = file_size(image) / 512;
	assert_true(blocks >= 5);
	assert_int_equal(info_names(image, -1), 0);
	srand(7);
	for (long b = 0; b < blocks; b++) {
		copy(image, bad);
		flip_byte(bad, b * 512 + rand() % 512, rand() % 8);
		assert_int_equal(info_names(bad, b), 2);
	}
}

/* The shared CMU walk (02.asf, 02_01.amc) into asf and amc (1024 bytes
 * each); 0 when the shared data is not there. */
static int cmu_walk(char *asf, char *amc)
{
	if (!test_data_path("mocap"))
		return 0;
	snprintf(asf, 1024, "%s", test_data_path("mocap/cmu/02.asf"));
	snprintf(amc, 1024, "%s", test_data_path("mocap/cmu/02_01.amc"));
	return 1;
}

static void test_info_random_bytes_of_big_image(void **state)
{
	(void)state;
	char asf[1024], amc[1024];
	if (!cmu_walk(asf, amc))
		skip();
	char image[512], bad[512];
	snprintf(image, sizeof image, "%s", test_scratch("big.skn"));
	snprintf(bad, sizeof bad, "%s", test_scratch("big_bad.skn"));
	assert_int_equal(test_run("%s pack '%s' '%s' -o '%s' >/dev/null", test_tool_path("skintool"), asf, amc, image), 0);
	long size = file_size(image);
	srand(11);
	for (int k = 0; k < 12; k++) {
		long at = ((long)rand() * 65536L + rand()) % size;
		copy(image, bad);
		flip_byte(bad, at, rand() % 8);
		assert_int_equal(info_names(bad, at / 4096), 2);
	}
}

/* Rewrites the version in both headers of an image (block size 512: block
 * 0 and the copy at the end), then their CRCs as a careful forger would:
 * only the version check can refuse it. */
static void set_version(const char *path, int version)
{
	static uint8_t block[512];
	FILE *f = fopen(path, "r+b");
	assert_non_null(f);
	assert_int_equal(fseek(f, 0, SEEK_END), 0);
	long end = ftell(f);
	const long at[2] = { 0, end - 512 }, header[2] = { SKP_IMAGE_BLOCK_HDR, 512 - 4 - SKP_IMAGE_HEADER_SIZE };
	for (int i = 0; i < 2; i++) {
		assert_int_equal(fseek(f, at[i], SEEK_SET), 0);
		assert_int_equal(fread(block, 1, 512, f), 512);
		uint8_t *h = block + header[i];
		h[8] = (uint8_t)version;
		le_put32(h + SKP_IMAGE_HEADER_SIZE - 4, crc32_compute(h, SKP_IMAGE_HEADER_SIZE - 4));
		le_put32(block + 508, crc32_compute(block, 508));
		assert_int_equal(fseek(f, at[i], SEEK_SET), 0);
		assert_int_equal(fwrite(block, 1, 512, f), 512);
	}
	fclose(f);
}

static void expect_info(const char *image, int status, const char *needle)
{
	const char *out = test_scratch("info2.txt");
	assert_int_equal(test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), image, out), status);
	char *text = slurp(out);
	if (!strstr(text, needle))
		fail_msg("expected '%s' in:\n%s", needle, text);
	free(text);
}

static void test_info_refuses_truncated_and_wrong_version(void **state)
{
	(void)state;
	const char *image = small_image();
	char bad[512];
	snprintf(bad, sizeof bad, "%s", test_scratch("cut.skn"));
	long size = file_size(image);
	copy(image, bad);
	assert_int_equal(truncate(bad, 1024), 0);
	expect_info(bad, 2, "image truncated");
	/* the copies gone: it plays, and info says what repair puts back */
	copy(image, bad);
	assert_int_equal(truncate(bad, size - 1024), 0);
	expect_info(bad, 2, "note: the storage ends 2 blocks before the image");
	copy(image, bad);
	assert_int_equal(truncate(bad, size - 100), 0);
	expect_info(bad, 2, "short read (header copy): repairable");
	copy(image, bad);
	set_version(bad, 6);
	expect_info(bad, 2, "image format version 6, this build reads versions 4 to 5");
	copy(image, bad);
	set_version(bad, 5);
	expect_info(bad, 0, "all good");
	expect_info(test_scratch("missing.skn"), 1, "cannot open");
}

/* skinplay headless on the image; returns its status, log in log. */
static int play(const char *args, const char *log)
{
	return test_run("%s %s --platform surfaceless --size 320x180 >'%s' 2>&1", test_tool_path("skinplay"), args, log);
}

static int count(const char *text, const char *needle)
{
	int n = 0;
	for (const char *p = text; (p = strstr(p, needle)) != NULL; p++)
		n++;
	return n;
}

/* Frame block k of the image's clip 0, and the image's parity count. */
static long frame_block(const char *image, int k, long *parity)
{
	static skp_image im;
	static storage_file sf;
	skp_error err;
	assert_int_equal(show_storage_open(&sf, image), 0);
	assert_int_equal(skp_image_open(&im, &sf.bd, &err), SKP_OK);
	long block = (long)im.clip[0].frames_first + k;
	*parity = (long)im.hdr.parity_blocks;
	storage_file_close(&sf);
	return block;
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
	if (!cmu_walk(asf, amc))
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
	char *text = slurp(out);
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

static void test_skinplay_rebuilds_and_holds(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	char asf[1024], amc[1024], args[2048], needle[160];
	snprintf(asf, sizeof asf, "%s", test_data_path("mocap/cmu/09.asf"));
	snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/09_06.amc"));
	const char *image = test_scratch("walk.skn"), *bad = test_scratch("walk_bad.skn"), *log = test_scratch("play.log");
	const char *bare = test_scratch("walk_bare.skn");
	/* --raw: a frames block holds 32 frames (compressed, the whole clip
	 * fits two blocks: tests/unit/test_image_codec.c damages those) */
	assert_int_equal(test_run("%s pack --raw '%s' '%s' --sequence 10 -o '%s' >/dev/null", test_tool_path("skintool"), asf,
			     amc, image), 0);
	assert_int_equal(test_run("%s pack --raw '%s' '%s' --sequence 10 --parity none -o '%s' >/dev/null",
				  test_tool_path("skintool"), asf, amc, bare), 0);
	/* the image's third frame block: the clip's frames 65..96 */
	long parity, block = frame_block(image, 2, &parity);
	assert_true(parity > 0);
	/* with parity: rebuilt, logged once, nothing held */
	copy(image, bad);
	flip_byte(bad, block * 4096 + 1000, 5);
	snprintf(args, sizeof args, "--image '%s'", bad);
	int st = play(args, log);
	char *text = slurp(log);
	if (st != 0)
		fail_msg("skinplay exited %d:\n%s", st, text);
	snprintf(needle, sizeof needle, "block %ld rebuilt from parity (clip frames, parity group %ld)\n", block,
		 block % parity);
	if (count(text, needle) != 1 || strstr(text, "holding"))
		fail_msg("expected '%s' once and nothing held in:\n%s", needle, text);
	assert_non_null(strstr(text, "played 71 frames")); /* 141 at 120 Hz: 71 at 60 */
	free(text);
	/* without parity: held over, logged once */
	long bare_parity, bare_block = frame_block(bare, 2, &bare_parity);
	assert_int_equal(bare_parity, 0);
	copy(bare, bad);
	flip_byte(bad, bare_block * 4096 + 1000, 5);
	assert_int_equal(play(args, log), 0);
	text = slurp(log);
	snprintf(needle, sizeof needle, "image: block %ld bad (CRC mismatch), holding frame 64\n", bare_block);
	if (count(text, needle) != 1 || count(text, "image: block ") != 1)
		fail_msg("expected '%s' once in:\n%s", needle, text);
	assert_non_null(strstr(text, "played 71 frames")); /* 141 at 120 Hz: 71 at 60 */
	free(text);

	/* two slots: the damaged one is newer, the intact one plays */
	const char *newer = test_scratch("walk_newer.skn");
	assert_int_equal(test_run("%s pack --raw '%s' '%s' --sequence 20 -o '%s' >/dev/null", test_tool_path("skintool"), asf,
			     amc, newer), 0);
	snprintf(args, sizeof args, "--image '%s' --image '%s' --frames 2", newer, image);
	assert_int_equal(play(args, log), 0);
	text = slurp(log);
	snprintf(needle, sizeof needle, "image: playing %s (sequence 20", newer);
	if (!strstr(text, needle))
		fail_msg("expected '%s' in:\n%s", needle, text);
	free(text);
	/* one bad block is rebuilt: the newer slot still plays */
	flip_byte(newer, block * 4096 + 7, 1);
	assert_int_equal(play(args, log), 0);
	text = slurp(log);
	if (!strstr(text, needle))
		fail_msg("expected '%s' (rebuilt) in:\n%s", needle, text);
	free(text);
	/* a second one in its group (a bind block) is beyond repair: the body
	 * cannot load, the intact older slot wins */
	flip_byte(newer, (block - parity) * 4096 + 7, 1);
	assert_int_equal(play(args, log), 0);
	text = slurp(log);
	char refusal[64];
	snprintf(refusal, sizeof refusal, "refused: block %ld: bind section: CRC mismatch", block - parity);
	snprintf(needle, sizeof needle, "image: playing %s (sequence 10", image);
	if (!strstr(text, needle) || !strstr(text, refusal))
		fail_msg("expected '%s' after '%s' in:\n%s", needle, refusal, text);
	free(text);
	/* both headers of the newer slot damaged: refused */
	flip_byte(newer, 100, 0);
	flip_byte(newer, file_size(newer) - 100, 0);
	assert_int_equal(play(args, log), 0);
	text = slurp(log);
	if (!strstr(text, needle) || !strstr(text, "refused: block 0"))
		fail_msg("expected '%s' and the refusal in:\n%s", needle, text);
	free(text);
	/* one slot, both headers damaged: refused with a message, nothing played */
	snprintf(args, sizeof args, "--image '%s'", newer);
	assert_int_equal(play(args, log), 1);
	text = slurp(log);
	if (!strstr(text, "refused: block 0") || !strstr(text, "no valid image"))
		fail_msg("expected the refusal in:\n%s", text);
	free(text);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_pack_decode_every_clip),
		cmocka_unit_test(test_info_names_every_block),
		cmocka_unit_test(test_info_random_bytes_of_big_image),
		cmocka_unit_test(test_info_refuses_truncated_and_wrong_version),
		cmocka_unit_test(test_skinplay_rebuilds_and_holds),
		cmocka_unit_test(test_fk_and_bench_of_a_packed_clip),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
