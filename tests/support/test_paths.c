#include "test_paths.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

const char *test_data_path(const char *rel)
{
	static char buf[4][1024];
	static int next;
	const char *root = getenv("SKP_SHARED");
	struct stat st;
	char *out = buf[next++ % 4];

	if (!root || !*root)
		root = "../shared";
	snprintf(out, sizeof buf[0], "%s/data", root);
	if (stat(out, &st) != 0)
		return NULL;
	snprintf(out, sizeof buf[0], "%s/data/%s", root, rel);
	return out;
}

const char *test_tool_path(const char *tool)
{
	/* rotating, so that one printf may name several: the order its
	 * arguments are evaluated in differs between compilers and targets */
	static char buf[8][1024];
	static int next;
	const char *b = getenv("SKP_BUILD");
	char *out = buf[next++ % 8];
	snprintf(out, sizeof buf[0], "%s/%s", b && *b ? b : "build", tool);
	return out;
}

const char *test_emulator(void)
{
	const char *e = getenv("SKP_TEST_EMULATED");
	return e && *e ? e : NULL;
}

int test_slow(void)
{
#ifdef __SANITIZE_ADDRESS__
	return 1;
#else
	return test_emulator() != NULL;
#endif
}

char *test_read_file(const char *path, size_t *size)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	fseek(f, 0, SEEK_SET);
	char *data = malloc((size_t)n + 1);
	if (data && fread(data, 1, (size_t)n, f) != (size_t)n) {
		free(data);
		data = NULL;
	}
	fclose(f);
	if (data) {
		data[n] = '\0';
		if (size)
			*size = (size_t)n;
	}
	return data;
}

int test_file_contains(const char *path, const char *text)
{
	size_t size = 0;
	char *d = test_read_file(path, &size);
	int found = d && strstr(d, text) != NULL;
	free(d);
	return found;
}
