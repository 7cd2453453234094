/* Where tests find the shared data and the built tools. */
#ifndef TEST_PATHS_H
#define TEST_PATHS_H

#include <stddef.h>

/* "<SKP_SHARED or ../shared>/data/<rel>" in a static buffer; NULL when the
 * shared data directory is absent (tests then skip()). */
const char *test_data_path(const char *rel);

/* "<SKP_BUILD or build>/<tool>" in one of 8 rotating static buffers. */
const char *test_tool_path(const char *tool);

/* The emulator tests/cross_run.sh runs the tests under (SKP_TEST_EMULATED),
 * or NULL natively. */
const char *test_emulator(void);

/* 1 under the sanitizers or an emulator (10x slower and more): corpus
 * tests then take a sample, and the native run takes all. */
int test_slow(void);

/* 1 when the file at path holds text (0 also when it cannot be read). */
int test_file_contains(const char *path, const char *text);

/* Reads a whole file into a static-per-call heap buffer the caller frees. */
char *test_read_file(const char *path, size_t *size);

#endif
