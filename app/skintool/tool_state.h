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

#endif
