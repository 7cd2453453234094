/* Under the sanitizers (SANITIZE=1 make test), the programs a test starts
 * run with SKP_CHILD_ASAN_OPTIONS as their ASAN_OPTIONS, while the test
 * program itself keeps the options it started with. The Makefile sets it
 * to detect_leaks=0: LeakSanitizer's scan at exit costs skintool and
 * skinplay 0.1 to 0.3 s a run (it grows with their 32 MB of static
 * arrays; a --version of the ASan build takes 0.20 s with it, 0.05 s
 * without) and test_image_cli 36% of its time (88.7 s with it, 56.7 s
 * without, on the development machine). Leaks stay checked where the
 * code runs in the test's own process (the unit tier, the integration
 * tests that call the libraries) and in `make import-sweep` (skintool
 * bind over every sample model: the importer, the host code that
 * allocates most); the device runtime allocates nothing (check-core). */
#include <stdlib.h>

/* Linked into every test program: before main, so that every way a test
 * starts a program (system, popen, fork and exec) inherits it. */
__attribute__((constructor)) static void test_sanitizer_children(void)
{
	const char *options = getenv("SKP_CHILD_ASAN_OPTIONS");
	if (options && *options)
		setenv("ASAN_OPTIONS", options, 1);
}
