/* A kiosk that never goes dark, on a real packed image (the demo skeleton
 * and body, two short clips): every block damaged in turn (one byte
 * flipped, then the whole block zeroed) plays exactly as the undamaged
 * image, checked by a checksum of the skinned vertices of every frame of
 * every clip, through the code skinplay plays with (show_source.h, one slot);
 * skinplay itself exits 0 on a sample of them. Beyond repair: two bad
 * blocks of one frame group hold the last frame, a clip whose quantisation
 * is lost is skipped while the other plays, and with no clip left the body
 * holds its bind pose. skintool repair restores the image bit for bit;
 * pack survives kill -9 and a concurrent pack to the same file. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "crc32.h"
#include "runtime_skin.h"
#include "show_source.h"
#include "test_paths.h"
#include "test_run.h"

#define BS 4096

static char image[512], two[512];

/* The demo clip's first 40 frames (the AMC header kept). */
static void short_clip(const char *out, int frames)
{
	FILE *in = fopen(test_tool_path("assets/demo.amc"), "r"), *o = fopen(out, "w");
	assert_true(in && o);
	char line[4096], stop[16];
	snprintf(stop, sizeof stop, "%d\n", frames + 1);
	while (fgets(line, sizeof line, in) && strcmp(line, stop))
		fputs(line, o);
	fclose(in);
	fclose(o);
}

static int setup(void **state)
{
	if (test_scratch_setup(state))
		return -1;
	const char *a = test_scratch("walk.amc"), *b = test_scratch("turn.amc");
	short_clip(a, 40);
	short_clip(b, 24);
	snprintf(image, sizeof image, "%s", test_scratch("show.skn"));
	snprintf(two, sizeof two, "%s", test_scratch("two.skn"));
	/* --raw: several frames blocks a clip, for the block-level cases (a
	 * compressed clip's are tests/unit/test_image_codec.c's) */
	if (test_run("%s pack --raw assets/demo.asf '%s' --sequence 3 -o '%s' >/dev/null", test_tool_path("skintool"), a,
		     image) ||
	    test_run("%s pack --raw assets/demo.asf '%s' '%s' --parity 4 --sequence 3 -o '%s' >/dev/null",
		     test_tool_path("skintool"), a, b, two))
		return -1;
	return 0;
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
	const uint8_t *b = p;
	for (size_t i = 0; i < n; i++)
		h = (h ^ b[i]) * 1099511628211ull;
	return h;
}

/* What skinplay would show from path, one slot: the skinned vertices of
 * every frame of every clip that plays (held frames included), hashed; 0
 * when the image is refused. *clips: how many clips played. */
static uint64_t played(const char *path, int *clips)
{
	static show_source show;
	static bound_body body;
	static runtime_skin sk;
	static amc_frame f;
	static float pos[3 * SKP_MAX_VERTS], nrm[3 * SKP_MAX_VERTS];
	const char *paths[1] = { path };
	uint64_t h = 1469598103934665603ull;
	*clips = 0;
	if (show_open(&show, paths, 1, &body) < 0)
		return 0;
	assert_int_equal(runtime_skin_init(&sk, &body.skel, &body.pose, &body.mesh, &body.weights, path), 0);
	for (int c = 0; c < show_clip_count(&show); c++) {
		play_source src;
		skp_error err;
		if (!show.playable[c] || show_select_clip(&show, show_clip(&show, c)->name, &src) < 0)
			continue;
		(*clips)++;
		while (src.next(src.ctx, &f, &err) == 1) {
			runtime_skin_frame(&sk, f.value);
			runtime_skin_run(&sk, SKIN_DQBS, pos, nrm);
			h = fnv(h, pos, sizeof(float) * 3 * (size_t)body.mesh.vert_count);
		}
	}
	show_close(&show);
	return h;
}

static uint8_t *load(const char *path, size_t *n)
{
	uint8_t *d = (uint8_t *)test_read_file(path, n);
	assert_non_null(d);
	return d;
}

static void save(const char *path, const uint8_t *d, size_t n)
{
	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	assert_int_equal(fwrite(d, 1, n, f), n);
	fclose(f);
}

/* Quiet: the damaged images log their rebuilds. */
static int quiet_stderr(void)
{
	fflush(stderr);
	int saved = dup(2);
	FILE *null = freopen("/dev/null", "w", stderr);
	assert_non_null(null);
	return saved;
}

static void loud_stderr(int saved)
{
	fflush(stderr);
	dup2(saved, 2);
	close(saved);
}

static void test_every_block_damaged_plays_the_same(void **state)
{
	(void)state;
	size_t n;
	int clips;
	uint8_t *orig = load(image, &n), *copy = malloc(n);
	const char *bad = test_scratch("bad.skn");
	uint64_t ref = played(image, &clips);
	assert_true(ref != 0);
	assert_int_equal(clips, 1);
	int saved = quiet_stderr();
	long blocks = (long)(n / BS), differ = 0, runs = 0;
	/* under the sanitizers or an emulator every block one way, the way
	 * turning with the block (a third of the runs); natively all three */
	const int slow = test_slow();
	for (long b = 0; b < blocks; b++) {
		for (int how = 0; how < 3; how++) {
			if (slow && how != b % 3)
				continue;
			runs++;
			static const char *const hows[] = { "flipped", "zeroed", "forged (its CRC made good)" };
			memcpy(copy, orig, n);
			if (how == 1)
				memset(copy + b * BS, 0, BS);
			else
				copy[b * BS + (b * 131) % BS] ^= 0x20;
			if (how == 2)
				le_put32(copy + b * BS + BS - 4, crc32_compute(copy + b * BS, BS - 4));
			save(bad, copy, n);
			if (played(bad, &clips) != ref || clips != 1) {
				differ++;
				fprintf(stdout, "block %ld %s: played differently\n", b, hows[how]);
			}
		}
	}
	loud_stderr(saved);
	assert_int_equal(differ, 0);
	print_message("%ld blocks, each %s: playback identical (%ld runs)\n", blocks,
		      slow ? "flipped, zeroed or forged in turn" : "flipped, zeroed and forged", runs);
	/* skinplay itself, on a sample: exit 0, the same frames */
	for (long b = 0; b < blocks; b += blocks / 8) {
		memcpy(copy, orig, n);
		memset(copy + b * BS, 0, BS);
		save(bad, copy, n);
		int st = test_run("%s --image '%s' --platform surfaceless --size 64x36 >/dev/null 2>&1",
				  test_tool_path("skinplay"), bad);
		if (st != 0)
			fail_msg("skinplay exited %d with block %ld zeroed", st, b);
	}
	free(orig);
	free(copy);
}

static long data_blocks;

/* Where clip's quantisation and frames are, and the image's parity count. */
static void clip_blocks(const char *path, int clip, long *quant, long *frames, long *parity)
{
	static show_image img;
	skp_error err;
	assert_int_equal(show_image_open(&img, path, &err), 0);
	*quant = (long)img.im.clip[clip].quant_first;
	*frames = (long)img.im.clip[clip].frames_first;
	*parity = (long)img.im.hdr.parity_blocks;
	data_blocks = (long)img.im.hdr.data_blocks;
	show_image_close(&img);
}

/* The parity block of b's group: damaging both puts b beyond repair and
 * touches nothing else. */
static long group_parity(long b, long parity)
{
	return data_blocks + b % parity;
}

static void test_beyond_repair_skips_or_holds(void **state)
{
	(void)state;
	size_t n;
	int clips;
	long quant, frames, parity, q1, f1, p1;
	clip_blocks(two, 0, &quant, &frames, &parity);
	clip_blocks(two, 1, &q1, &f1, &p1);
	uint8_t *d = load(two, &n);
	const char *bad = test_scratch("two_bad.skn"), *log = test_scratch("two.log");
	/* clip 0's quantisation beyond repair: clip 1 still plays, skinplay lives */
	long mate = group_parity(quant, parity);
	d[quant * BS + 40] ^= 1;
	d[mate * BS + 40] ^= 1;
	save(bad, d, n);
	int saved = quiet_stderr();
	uint64_t h = played(bad, &clips);
	loud_stderr(saved);
	assert_true(h != 0);
	assert_int_equal(clips, 1);
	assert_int_equal(test_run("%s --image '%s' --platform surfaceless --size 64x36 >'%s' 2>&1",
				  test_tool_path("skinplay"), bad, log), 0);
	char *text = test_read_file(log, &n);
	assert_non_null(strstr(text, "image: clip walk skipped"));
	assert_non_null(strstr(text, "played 13 frames of turn"));
	free(text);
	/* clip 1's too: nothing can play; headless holds the bind pose once
	 * and says so (status 2); a kiosk would hold it until stopped */
	mate = group_parity(q1, parity);
	free(d);
	d = load(bad, &n);
	d[q1 * BS + 40] ^= 1;
	d[mate * BS + 40] ^= 1;
	save(bad, d, n);
	assert_int_equal(test_run("%s --image '%s' --platform surfaceless --size 64x36 >'%s' 2>&1",
				  test_tool_path("skinplay"), bad, log), 2);
	text = test_read_file(log, &n);
	assert_non_null(strstr(text, "holding the bind pose"));
	assert_non_null(strstr(text, "played 1 frames"));
	free(text);
	/* two bad frame blocks of one group: the clip holds over them */
	free(d);
	d = load(two, &n);
	mate = group_parity(frames + 1, parity);
	d[(frames + 1) * BS + 40] ^= 1;
	d[mate * BS + 40] ^= 1;
	save(bad, d, n);
	assert_int_equal(test_run("%s --image '%s' --loop clip --platform surfaceless --size 64x36 >'%s' 2>&1",
				  test_tool_path("skinplay"), bad, log), 0);
	text = test_read_file(log, &n);
	if (!strstr(text, "holding frame") || !strstr(text, "played 21 frames")) /* 40 at 120 Hz: 21 at 60 */
		fail_msg("expected a held frame in:\n%s", text);
	free(text);
	free(d);
}

/* A forger's edit of block b: a byte changed, the CRC made good again. */
static void forge(uint8_t *d, long b)
{
	d[b * BS + 60] ^= 1;
	le_put32(d + b * BS + BS - 4, crc32_compute(d + b * BS, BS - 4));
}

static void test_repair_restores_the_image(void **state)
{
	(void)state;
	size_t n, m;
	const char *bad = test_scratch("repair.skn");
	uint8_t *d = load(image, &n);
	long blocks = (long)(n / BS);
	/* one block in each of three groups, the header, the copy */
	d[5 * BS + 9] ^= 4;
	memset(d + 6 * BS, 0, BS);
	d[(blocks - 3) * BS] ^= 1;
	memset(d, 0, BS);
	d[(blocks - 1) * BS + 100] ^= 8;
	save(bad, d, n);
	assert_int_equal(test_run("%s info '%s' >/dev/null 2>&1", test_tool_path("skintool"), bad), 2);
	assert_int_equal(test_run("%s repair '%s' >/dev/null", test_tool_path("skintool"), bad), 0);
	uint8_t *r = load(bad, &m);
	assert_int_equal(m, n);
	free(d);
	d = load(image, &n);
	assert_memory_equal(r, d, n);
	assert_int_equal(test_run("%s info '%s' >/dev/null 2>&1", test_tool_path("skintool"), bad), 0);
	/* beyond repair: refused, the file left as it was */
	long p, q, f;
	clip_blocks(image, 0, &q, &f, &p);
	r[f * BS + 50] ^= 1;
	r[group_parity(f, p) * BS + 50] ^= 1;
	save(bad, r, n);
	assert_int_equal(test_run("%s repair '%s' >/dev/null 2>&1", test_tool_path("skintool"), bad), 2);
	free(d);
	d = load(bad, &m);
	assert_memory_equal(d, r, n);
	/* info advises repair only where repair would write: not here */
	const char *said = test_scratch("said.txt");
	static const char *const beyond[] = { "not repairable as a whole (blocks beyond repair)", NULL };
	assert_int_equal(test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), bad, said), 2);
	test_assert_contains_all(said, beyond);
	assert_false(test_file_contains(said, "(skintool repair"));
	/* a block altered with its CRC made good fails its own digest (version
	 * 7): named, rebuilt from parity like a CRC-bad one beside it */
	free(d);
	d = load(image, &n);
	forge(d, f);
	d[(f + 1) * BS + 60] ^= 1;
	save(bad, d, n);
	char named[64];
	snprintf(named, sizeof named, "block %ld bad: content differs from its digest", f);
	const char *const forged[] = { named, "(skintool repair", NULL };
	assert_int_equal(test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), bad, said), 2);
	test_assert_contains_all(said, forged);
	assert_int_equal(test_run("%s repair '%s' >/dev/null 2>&1", test_tool_path("skintool"), bad), 0);
	free(r);
	r = load(bad, &m);
	free(d);
	d = load(image, &n);
	assert_memory_equal(r, d, n);
	/* the digest block forged and its parity lost: the digests no longer
	 * give the root, which info says, and repair refuses */
	long digests = data_blocks - 1;
	forge(d, digests);
	d[group_parity(digests, p) * BS + 50] ^= 1;
	save(bad, d, n);
	static const char *const rootless[] = { "NOT the header's root", "digest: MISMATCH", NULL };
	assert_int_equal(test_run("%s info '%s' >'%s' 2>&1", test_tool_path("skintool"), bad, said), 2);
	test_assert_contains_all(said, rootless);
	assert_false(test_file_contains(said, "(skintool repair"));
	assert_int_equal(test_run("%s repair '%s' >/dev/null 2>&1", test_tool_path("skintool"), bad), 2);
	free(d);
	free(r);
}

/* No file in the scratch directory but the ones named. */
static int stray_files(void)
{
	DIR *dir = opendir(test_scratch_dir());
	struct dirent *e;
	int n = 0;
	while (dir && (e = readdir(dir)))
		n += e->d_name[0] == '.' && strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
	if (dir)
		closedir(dir);
	return n;
}

static void test_pack_survives_kill_and_a_race(void **state)
{
	(void)state;
	const char *out = test_scratch("live.skn"), *a = test_scratch("walk.amc");
	char cmd[2048];
	snprintf(cmd, sizeof cmd, "exec %s pack assets/demo.asf '%s' --sequence 5 -o '%s' >/dev/null 2>&1",
		 test_tool_path("skintool"), a, out);
	assert_int_equal(test_run("%s", cmd), 0);
	size_t n;
	uint8_t *before = load(out, &n);
	/* kill -9 at spread-out moments of a pack over it */
	srand(7);
	for (int k = 0; k < 8; k++) {
		pid_t pid = fork();
		if (pid == 0) {
			execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
			_exit(127);
		}
		struct timespec ts = { 0, (long)(rand() % 400) * 1000000L };
		nanosleep(&ts, NULL);
		kill(pid, SIGKILL);
		waitpid(pid, NULL, 0);
		size_t m;
		uint8_t *now = load(out, &m);
		/* the old image, or a whole new one: never a half */
		assert_int_equal(test_run("%s info '%s' >/dev/null 2>&1", test_tool_path("skintool"), out), 0);
		free(now);
	}
	assert_int_equal(stray_files(), 0);
	/* two packs at once to one file: each writes whole, the last wins */
	assert_int_equal(test_run("(%s) & (%s) & wait", cmd, cmd), 0);
	assert_int_equal(test_run("%s info '%s' >/dev/null 2>&1", test_tool_path("skintool"), out), 0);
	assert_int_equal(stray_files(), 0);
	free(before);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_block_damaged_plays_the_same),
		cmocka_unit_test(test_beyond_repair_skips_or_holds),
		cmocka_unit_test(test_repair_restores_the_image),
		cmocka_unit_test(test_pack_survives_kill_and_a_race),
	};
	return cmocka_run_group_tests(tests, setup, test_scratch_teardown);
}
