#include "test_run.h"

#include "test_paths.h"

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static char dir[64];

void test_assert_contains_all(const char *path, const char *const *texts)
{
	for (; *texts; texts++)
		if (!test_file_contains(path, *texts))
			fail_msg("%s: no '%s' in it", path, *texts);
}

int test_wait_for_text(const char *path, const char *text, double seconds)
{
	return test_wait_for_text_after(path, 0, text, seconds) >= 0;
}

static long text_after(const char *path, long from, const char *text)
{
	size_t size = 0;
	char *d = test_read_file(path, &size);
	const char *at = d && (size_t)from <= size ? strstr(d + from, text) : NULL;
	long found = at ? (long)(at - d) : -1;
	free(d);
	return found;
}

long test_wait_for_text_after(const char *path, long from, const char *text, double seconds)
{
	for (int i = 0; i < (int)(seconds * 10); i++) {
		long found = text_after(path, from, text);
		if (found >= 0)
			return found;
		usleep(100000);
	}
	return -1;
}

long test_file_size(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0 ? (long)st.st_size : 0;
}

void test_write_text(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	assert_true(fputs(text, f) >= 0);
	assert_int_equal(fclose(f), 0);
}

int test_scratch_setup(void **state)
{
	(void)state;
	strcpy(dir, "/tmp/skp_test_XXXXXX");
	return mkdtemp(dir) ? 0 : -1;
}

int test_scratch_teardown(void **state)
{
	(void)state;
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
	return system(cmd) == 0 ? 0 : -1;
}

const char *test_scratch_dir(void)
{
	return dir;
}

const char *test_scratch(const char *name)
{
	static char buf[64][512];
	static int next;
	char *out = buf[next++ % 64];
	snprintf(out, sizeof buf[0], "%s/%s", dir, name);
	return out;
}

/* The awk program that keeps a clip's first n frames: a BVH's MOTION
 * lines after "Frame Time:" (its "Frames:" rewritten), an AMC's frames
 * numbered up to n (CRLF files too). */
static const char *head_program(const char *path)
{
	size_t len = strlen(path);
	if (len > 4 && !strcasecmp(path + len - 4, ".bvh"))
		return "f && ++k > n { exit } /^Frames:/ { $0 = \"Frames: \" n } { print } /^Frame Time:/ { f = 1 }";
	return "/^[0-9]+\r?$/ { k = $1 + 0 } k <= n";
}

const char *test_clip_head(const char *path, int frames, const char *in)
{
	static char out[1024];
	const char *name = strrchr(path, '/');
	snprintf(out, sizeof out, "%s/head/%s", in ? in : dir, name ? name + 1 : path);
	if (test_run("mkdir -p '%s/head' && awk -v n=%d '%s' '%s' > '%s'", in ? in : dir, frames, head_program(path), path,
		     out) != 0)
		fail_msg("cannot cut %s to %d frames", path, frames);
	return out;
}

const char *test_mannequin_detail(void)
{
	return test_slow() ? "--detail 36" : "";
}

int test_run(const char *fmt, ...)
{
	char cmd[4096];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(cmd, sizeof cmd, fmt, ap);
	va_end(ap);
	int st = system(cmd);
	return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void *probe_thread(void *arg)
{
	return arg;
}

/* Whether a child process can start and join a thread within 5 s: where
 * pthread_create hangs, only the child is lost (and killed). */
static int threads_start(void)
{
	pid_t pid = fork();
	if (pid == 0) {
		pthread_t t;
		_exit(pthread_create(&t, NULL, probe_thread, NULL) == 0 && pthread_join(t, NULL) == 0 ? 0 : 1);
	}
	if (pid < 0)
		return 0;
	const struct timespec tick = { 0, 50 * 1000 * 1000 };
	for (int i = 0; i < 100; i++) {
		int st;
		if (waitpid(pid, &st, WNOHANG) == pid)
			return WIFEXITED(st) && WEXITSTATUS(st) == 0;
		nanosleep(&tick, NULL);
	}
	kill(pid, SIGKILL);
	waitpid(pid, NULL, 0);
	return 0;
}

void test_skip_threads_if_emulated(void)
{
	const char *emulator = test_emulator();
	if (emulator && !threads_start()) {
		print_message("skipped: a thread did not start within 5 s under %s\n", emulator);
		skip();
	}
}

void test_show_compare(const char *size, double hz, const char *more, const char *out)
{
	char show[512]; /* test_tool_path's buffers rotate */
	snprintf(show, sizeof show, "%s", test_tool_path("assets/demo.skn"));
	if (test_run("rm -rf '%s' && ASAN_OPTIONS=detect_leaks=0 %s --image %s --platform surfaceless --algo compare "
		     "--hud visitor --hud-fps off --input none --size %s --display-rate %g %s --out '%s' 2>/dev/null",
		     out, test_tool_path("skinplay"), show, size, hz, more, out) != 0)
		fail_msg("skinplay --image %s --size %s --display-rate %g %s did not exit 0", show, size, hz, more);
}
