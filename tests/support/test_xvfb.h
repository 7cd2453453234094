/* An X server for the tests of the x11 backend: Xvfb, when installed. */
#ifndef TEST_XVFB_H
#define TEST_XVFB_H

#include <stddef.h>
#include <sys/types.h>

/* Starts Xvfb with one screen of geometry (e.g. "320x240x24") on a free
 * display number (-displayfd); its name (":N") into name. Returns its pid,
 * 0 when it is not installed or did not start. */
pid_t test_xvfb_start(const char *geometry, char *name, size_t size);

/* Stops it (pid 0: nothing). */
void test_xvfb_stop(pid_t pid);

#endif
