/* A command's large working state (a bound body, a comparison's frames,
 * a chart's pixels: megabytes each) made zeroed at its first use and kept
 * for the rest of the process, as a static would be, but off the program's
 * image. A leak checker (ASan's) reads every byte of the image's data at
 * exit: with these as statics skintool's was 236 MB, and each run of the
 * sanitizer build spent about 2 s in that read, `skintool --version` too. */
#ifndef TOOL_STATE_H
#define TOOL_STATE_H

#include <stddef.h>

/* *slot, made size zero bytes at the first call; out of memory: says so
 * on stderr and exits with status 1, as GNU's xmalloc does. */
void *tool_state(void **slot, size_t size);

/* Declares name, a T * to the command's kept state: TOOL_STATE(bound_body,
 * body); stands for a `static bound_body body;` made at first use. */
#define TOOL_STATE(T, name) \
	static void *name##_kept; \
	T *name = tool_state(&name##_kept, sizeof *name)

/* The same for an array of n T. */
#define TOOL_STATE_ARRAY(T, name, n) \
	static void *name##_kept; \
	T *name = tool_state(&name##_kept, (size_t)(n) * sizeof *name)

#endif
