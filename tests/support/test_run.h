/* Running the built tools from integration tests, in a scratch directory
 * that the group setup creates and the teardown removes. */
#ifndef TEST_RUN_H
#define TEST_RUN_H

/* cmocka group setup/teardown: a fresh /tmp/skp_test_XXXXXX */
int test_scratch_setup(void **state);
int test_scratch_teardown(void **state);

/* the scratch directory itself */
const char *test_scratch_dir(void);

/* "<scratch>/<name>" in one of 64 rotating static buffers */
const char *test_scratch(const char *name);

/* The clip (BVH or AMC) at path cut to its first `frames` frames, under
 * its own name in head/ of directory in (NULL: the scratch directory), in
 * one static buffer: the short clip a test packs or measures under the
 * sanitizers or an emulator, where the encoder takes about 12 ms a frame. */
const char *test_clip_head(const char *path, int frames, const char *in);

/* skintool mannequin's option for the generated body a test binds only to
 * run a command on it: natively none (the default body); under the
 * sanitizers or an emulator "--detail 36", a coarser one (2814 vertices
 * for CMU subject 02, not 11702: a quarter of the time to bind or skin). */
const char *test_mannequin_detail(void);

/* Polls the file at path for text for up to seconds (a log a program
 * writes as it runs); 1 when it came. */
int test_wait_for_text(const char *path, const char *text, double seconds);

/* The same, looking only past the file's first `from` bytes (what a log
 * said after a given moment); the offset of the text, or -1. */
long test_wait_for_text_after(const char *path, long from, const char *text, double seconds);

/* The file's size now (0 when it does not exist). */
long test_file_size(const char *path);

/* Writes text to path (the test fails when it cannot). */
void test_write_text(const char *path, const char *text);

/* Fails the test, naming the text and the file, unless the file at path
 * holds every text of the NULL-terminated list. */
void test_assert_contains_all(const char *path, const char *const *texts);

/* The default show (build/assets/demo.skn) headless on the visitor's
 * screen in the compare view at size (WxH), hz frames a second of the
 * virtual display, more options, into out (emptied first); fails the test
 * unless skinplay exits 0. */
void test_show_compare(const char *size, double hz, const char *more, const char *out);

/* Runs a shell command built like printf; returns its exit status, or -1
 * when it did not exit normally (a crash). */
int test_run(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* Skips the running cmocka test, saying why, when under the emulator
 * tests/cross_run.sh names in SKP_TEST_EMULATED a probe thread does not
 * start: pthread_create of a dynamically linked aarch64 program never
 * returns under qemu-user on some hosts (7.2 and 10.0 on a 6.18 kernel;
 * static programs' threads run). Natively nothing is probed. */
void test_skip_threads_if_emulated(void);

#endif
