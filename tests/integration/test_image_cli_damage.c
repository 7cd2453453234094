/* Damaged flash images through the real tools: skintool info names the
 * block of any flipped byte (every block of a small image, random bytes of
 * a big one) and exits 2; truncated and wrong-version images are refused;
 * skinplay rebuilds a bad block from parity (logging it once), holds over
 * one in an image without parity, and, given two slots, plays the newest
 * one with no block beyond repair. Whole images: test_image_cli.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "crc32.h"
#include "image_stream.h"
#include "show_source.h"
#include "storage_file.h"
#include "test_imgcli.h"
#include "test_paths.h"
#include "test_run.h"

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
	assert_int_equal(imgcli_info_names(image, -1), 0);
	srand(7);
	for (long b = 0; b < blocks; b++) {
		copy(image, bad);
		flip_byte(bad, b * 512 + rand() % 512, rand() % 8);
		assert_int_equal(imgcli_info_names(bad, b), 2);
	}
}

static void test_info_random_bytes_of_big_image(void **state)
{
	(void)state;
	char asf[1024], amc[1024];
	if (!imgcli_cmu_walk(asf, amc))
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
		assert_int_equal(imgcli_info_names(bad, at / 4096), 2);
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
	char *text = imgcli_slurp(out);
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
	set_version(bad, 9);
	expect_info(bad, 2, "image format version 9, this build reads versions 4 to 8");
	expect_info(test_scratch("missing.skn"), 1, "cannot open");
}

/* Bytes [from, to) of the file set to 0. */
static void zero_bytes(const char *path, long from, long to)
{
	FILE *f = fopen(path, "r+b");
	assert_non_null(f);
	assert_int_equal(fseek(f, from, SEEK_SET), 0);
	for (long i = from; i < to; i++)
		fputc(0, f);
	fclose(f);
}

/* A slot with nothing in it (4 GiB of zeros, sparse) is refused by info
 * and skinplay after its first 16 MiB, not read to its end (timeout is a
 * hang guard: the whole read took 30 s for 2 GiB); an image refused for
 * its header still has its bad blocks named, runs of them as ranges. */
static void test_barren_slot_and_bad_runs(void **state)
{
	(void)state;
	const char *zero = test_scratch("zero.skn"), *out = test_scratch("zero.txt");
	assert_int_equal(test_run("truncate -s 4G '%s'", zero), 0);
	assert_int_equal(test_run("timeout 60 %s info '%s' >'%s' 2>&1", test_tool_path("skintool"), zero, out), 2);
	static const char *const none[] = { "not a skinplay image", "no block of the first 16 MiB checks", NULL };
	test_assert_contains_all(out, none);
	assert_int_equal(test_run("timeout 60 %s --image '%s' --platform none --frames 2 >'%s' 2>&1",
				  test_tool_path("skinplay"), zero, out),
			 1);
	static const char *const refused[] = { "no valid image among 1 slot", NULL };
	test_assert_contains_all(out, refused);
	unlink(zero);
	char bad[512];
	snprintf(bad, sizeof bad, "%s", test_scratch("runs.skn"));
	copy(small_image(), bad);
	set_version(bad, 9);
	zero_bytes(bad, 2 * 512, 5 * 512);
	assert_int_equal(test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), bad, out), 2);
	static const char *const runs[] = { "blocks 2..4 bad: CRC mismatch", "blocks of 512 bytes (block size found from their CRCs)",
					    NULL };
	test_assert_contains_all(out, runs);
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
	char *text = imgcli_slurp(log);
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
	text = imgcli_slurp(log);
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
	text = imgcli_slurp(log);
	snprintf(needle, sizeof needle, "image: playing %s (sequence 20", newer);
	if (!strstr(text, needle))
		fail_msg("expected '%s' in:\n%s", needle, text);
	free(text);
	/* one bad block is rebuilt: the newer slot still plays */
	flip_byte(newer, block * 4096 + 7, 1);
	assert_int_equal(play(args, log), 0);
	text = imgcli_slurp(log);
	if (!strstr(text, needle))
		fail_msg("expected '%s' (rebuilt) in:\n%s", needle, text);
	free(text);
	/* a second one in its group (a bind block) is beyond repair: the body
	 * cannot load, the intact older slot wins */
	flip_byte(newer, (block - parity) * 4096 + 7, 1);
	assert_int_equal(play(args, log), 0);
	text = imgcli_slurp(log);
	char refusal[64];
	snprintf(refusal, sizeof refusal, "refused: block %ld: bind section: CRC mismatch", block - parity);
	snprintf(needle, sizeof needle, "image: playing %s (sequence 10", image);
	if (!strstr(text, needle) || !strstr(text, refusal))
		fail_msg("expected '%s' after '%s' in:\n%s", needle, refusal, text);
	free(text);
	/* both headers of the newer slot damaged, and a block of parity group
	 * 0 that would rebuild block 0: refused */
	flip_byte(newer, 100, 0);
	flip_byte(newer, file_size(newer) - 100, 0);
	flip_byte(newer, parity * 4096 + 7, 1);
	assert_int_equal(play(args, log), 0);
	text = imgcli_slurp(log);
	if (!strstr(text, needle) || !strstr(text, "refused: block 0"))
		fail_msg("expected '%s' and the refusal in:\n%s", needle, text);
	free(text);
	/* one slot, both headers damaged: refused with a message, nothing played */
	snprintf(args, sizeof args, "--image '%s'", newer);
	assert_int_equal(play(args, log), 1);
	text = imgcli_slurp(log);
	if (!strstr(text, "refused: block 0") || !strstr(text, "no valid image"))
		fail_msg("expected the refusal in:\n%s", text);
	free(text);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_info_names_every_block),
		cmocka_unit_test(test_info_random_bytes_of_big_image),
		cmocka_unit_test(test_info_refuses_truncated_and_wrong_version),
		cmocka_unit_test(test_barren_slot_and_bad_runs),
		cmocka_unit_test(test_skinplay_rebuilds_and_holds),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
