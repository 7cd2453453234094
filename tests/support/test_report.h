/* What the tests of `skintool compare` share (test_compare_report,
 * test_compare_pictures, test_compare_parts): a scratch directory for the
 * reports, the commands run in it, and reading what they wrote. */
#ifndef TEST_REPORT_H
#define TEST_REPORT_H

#include <stdint.h>

/* cmocka group setup/teardown: a fresh /tmp/skp_compare_XXXXXX, removed
 * at the end unless SKP_KEEP_REPORT is set (then named on stderr). */
int test_report_setup(void **state);
int test_report_teardown(void **state);

/* the scratch directory itself */
const char *test_report_dir(void);

/* Runs cmd (stdout to out when not NULL, stderr to <scratch>/stderr.txt);
 * returns its exit status, failing the test when it did not exit. */
int test_report_sh(const char *cmd, const char *out);

/* `skintool compare asf amc [options] -o <scratch>/<name>` (options "" for
 * none); fails the test unless it exits 0. The report directory, in a
 * static buffer. */
const char *test_report_compare(const char *asf, const char *amc, const char *options, const char *name);

/* The whole file, for the caller to free; fails the test when it cannot
 * be read. */
char *test_report_slurp(const char *path);

/* Seconds on the monotonic clock. */
double test_report_now(void);

/* Cuts each line of a CSV text after its fifth field. */
void test_report_first_five_columns(char *text);

/* The text of the element with this id, tags included, up to its end;
 * fails the test when the page has none. */
const char *test_report_element(const char *html, const char *id);

/* The luminance's standard deviation over columns x0..x1, rows y0..y1 of
 * an RGBA picture w pixels wide. */
double test_report_luminance_stddev(const uint8_t *px, int w, int x0, int x1, int y0, int y1);

#endif
