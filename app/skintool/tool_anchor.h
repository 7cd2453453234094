/* The anchors skintool measures against in the same run (../shared/tools:
 * ozz-animation's skinning, ACL's compression): external programs whose
 * one line of output is read back. */
#ifndef TOOL_ANCHOR_H
#define TOOL_ANCHOR_H

#include <stddef.h>

/* Runs argv[0] (a path) with argv, stdin from /dev/null, and keeps the
 * first n - 1 bytes of its standard output in out (NUL-terminated); its
 * standard error passes through. Returns its exit status, or -1 when it
 * could not run or was killed (errno-style reason in out). */
int tool_anchor_run(char *const argv[], char *out, size_t n);

/* ozz-animation's LBS rate for verts vertices (its bench program ozz,
 * one round), M vertices a second; 0 after saying why when it gives none. */
double tool_anchor_ozz_rate(const char *ozz, long verts);

#endif
