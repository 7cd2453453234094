/* `skintool compare` through the real command line on bodies of several
 * parts, and its bad arguments:
 *   - a box inside the generated arm is left out of the volume (the volume
 *     column and the elbow region's volume are the plain arm's to the
 *     digit, the page says what was measured on); with a hole in every
 *     part the volume verdicts say "not measured";
 *   - each bad argument is refused, with a message naming it.
 * No shared data needed; the clips' report is test_compare_report's. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_paths.h"
#include "test_report.h"

static void expect_fail(const char *args, const char *message)
{
	char cmd[2048], err[1200];
	snprintf(cmd, sizeof cmd, "%s %s", test_tool_path("skintool"), args);
	assert_int_equal(test_report_sh(cmd, NULL), 1);
	snprintf(err, sizeof err, "%s/stderr.txt", test_report_dir());
	char *text = test_report_slurp(err);
	if (!strstr(text, message))
		fail_msg("'skintool %s' said '%s', expected '%s'", args, text, message);
	free(text);
}

/* The volume on a body with parts: a box inside the body is left out of
 * the volume (the volume column and the elbow region's volume are the
 * plain body's to the digit, the page says what was measured), and a body whose parts each have a hole (the
 * generated arm's two tubes, every 400th face taken out) has no volume: both
 * volume verdicts say "not measured" instead of yes or no. */
static void write_variant(const char *body_obj, const char *out, int inner_box, int drop_faces)
{
	char *text = test_report_slurp(body_obj);
	FILE *f = fopen(out, "w");
	assert_non_null(f);
	fputs("g body\n", f);
	int verts = 0, faces = 0;
	for (char *line = text; *line;) {
		char *end = strchr(line, '\n');
		size_t n = end ? (size_t)(end - line + 1) : strlen(line);
		verts += line[0] == 'v' && line[1] == ' ';
		faces += line[0] == 'f' && line[1] == ' ';
		if (!(drop_faces && line[0] == 'f' && faces % 400 == 1) && line[0] != 'g' && line[0] != 'o')
			fwrite(line, 1, n, f);
		line += n;
	}
	if (inner_box) {
		/* a closed box, faces outward, inside the forearm */
		static const float c[8][3] = { { 2.7f, -0.05f, -0.05f }, { 2.8f, -0.05f, -0.05f }, { 2.8f, 0.05f, -0.05f },
					       { 2.7f, 0.05f, -0.05f }, { 2.7f, -0.05f, 0.05f }, { 2.8f, -0.05f, 0.05f },
					       { 2.8f, 0.05f, 0.05f }, { 2.7f, 0.05f, 0.05f } };
		static const int q[6][4] = { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 },
					     { 2, 3, 7, 6 }, { 1, 2, 6, 5 }, { 0, 4, 7, 3 } };
		for (int k = 0; k < 8; k++)
			fprintf(f, "v %g %g %g\n", (double)c[k][0], (double)c[k][1], (double)c[k][2]);
		for (int k = 0; k < 6; k++)
			fprintf(f, "f %d %d %d %d\n", verts + 1 + q[k][0], verts + 1 + q[k][1], verts + 1 + q[k][2],
				verts + 1 + q[k][3]);
	}
	fclose(f);
	free(text);
}

static char *compare_page(const char *obj, const char *name, char **csv)
{
	char cmd[4096], dir[1100], path[1200];
	snprintf(dir, sizeof dir, "%s/%s", test_report_dir(), name);
	snprintf(cmd, sizeof cmd, "%s compare %s/arm.asf %s/arm.amc --mesh %s --balance off "
		 "--group body --renders 0 -o %s 2>/dev/null", test_tool_path("skintool"), test_report_dir(),
		 test_report_dir(), obj, dir);
	assert_int_equal(test_report_sh(cmd, NULL), 0);
	snprintf(path, sizeof path, "%s/metrics.csv", dir);
	*csv = test_report_slurp(path);
	test_report_first_five_columns(*csv);
	snprintf(path, sizeof path, "%s/index.html", dir);
	return test_report_slurp(path);
}

static void test_parts_and_holes(void **state)
{
	(void)state;
	char cmd[4096], made[1100], body[1100], inner[1100], open[1100];
	snprintf(made, sizeof made, "%s/tiny_made.obj", test_report_dir());
	snprintf(body, sizeof body, "%s/tiny_body.obj", test_report_dir());
	snprintf(inner, sizeof inner, "%s/tiny_inner.obj", test_report_dir());
	snprintf(open, sizeof open, "%s/tiny_open.obj", test_report_dir());
	/* the tiny arm with CMU's names, so that its lower bone is an elbow
	 * region (report.c) and the region volumes are measured too */
	for (int i = 0; i < 2; i++) {
		static const char *const ext[2] = { "asf", "amc" };
		char arm[1100];
		snprintf(cmd, sizeof cmd, "sed 's/\\<upper\\>/lhumerus/g; s/\\<lower\\>/lradius/g' tests/data/tiny.%s",
			 ext[i]);
		snprintf(arm, sizeof arm, "%s/arm.%s", test_report_dir(), ext[i]);
		assert_int_equal(test_report_sh(cmd, arm), 0);
	}
	snprintf(cmd, sizeof cmd, "%s mannequin %s/arm.asf -o %s", test_tool_path("skintool"), test_report_dir(), made);
	assert_int_equal(test_report_sh(cmd, NULL), 0);
	write_variant(made, body, 0, 0);
	write_variant(made, inner, 1, 0);
	write_variant(made, open, 0, 1);
	char *plain_csv, *inner_csv, *open_csv;
	char *plain = compare_page(body, "plain", &plain_csv), *with_box = compare_page(inner, "inner", &inner_csv);
	char *holed = compare_page(open, "open", &open_csv);
	assert_null(strstr(plain, "id=\"volume-parts\""));
	/* the generated arm is two closed parts: a ball at the shoulder, the forearm */
	if (!strstr(with_box, "Measured on the mesh's 2 outer closed parts of 3; 1 inside them (joint balls, eyes, "
			      "teeth) left out."))
		fail_msg("the page does not say what its volume was measured on");
	assert_string_equal(plain_csv, inner_csv);
	/* the elbow's own volume leaves the box out too (it took 18.29% to
	 * 17.53% when counted) */
	const char *elbow_plain = strstr(test_report_element(plain, "region-volume"), "<tr><td>elbows</td><td>");
	const char *elbow_inner = strstr(test_report_element(with_box, "region-volume"), "<tr><td>elbows</td><td>");
	assert_non_null(elbow_plain);
	assert_non_null(elbow_inner);
	assert_true(strchr(elbow_plain + strlen("<tr><td>elbows</td><td>"), '%') != NULL);
	assert_int_equal(strcspn(elbow_plain, "\n"), strcspn(elbow_inner, "\n"));
	assert_memory_equal(elbow_plain, elbow_inner, strcspn(elbow_plain, "\n"));
	const char *v = test_report_element(holed, "verdict-dqbs-volume");
	static const char unmeasured[] = "<b>not measured</b> &mdash; no part of the mesh is closed (";
	assert_true(strncmp(strstr(v, "<b>"), unmeasured, strlen(unmeasured)) == 0);
	v = test_report_element(holed, "verdict-lbs-loss");
	assert_true(strncmp(strstr(v, "<b>"), "<b>not measured</b>", strlen("<b>not measured</b>")) == 0);
	free(plain), free(with_box), free(holed);
	free(plain_csv), free(inner_csv), free(open_csv);
}

static void test_bad_arguments(void **state)
{
	(void)state;
	char args[2048];
	expect_fail("compare tests/data/tiny.asf tests/data/tiny.amc", "skintool compare: give SKELETON MOTION and -o DIR");
	expect_fail("compare tests/data/tiny.asf", "skintool compare: give SKELETON MOTION and -o DIR");
	snprintf(args, sizeof args, "compare tests/data/tiny.asf tests/data/tiny.amc --bogus -o %s/x", test_report_dir());
	expect_fail(args, "unknown option '--bogus'");
	snprintf(args, sizeof args, "compare tests/data/tiny.asf tests/data/tiny.amc --renders 99 -o %s/x", test_report_dir());
	expect_fail(args, "--renders takes 0 to");
	snprintf(args, sizeof args, "compare tests/data/missing.asf tests/data/tiny.amc -o %s/x", test_report_dir());
	expect_fail(args, "missing.asf");
	snprintf(args, sizeof args, "compare tests/data/tiny.asf tests/data/tiny.amc --mesh missing.obj -o %s/x",
		 test_report_dir());
	expect_fail(args, "missing.obj");
	expect_fail("compare tests/data/tiny.asf tests/data/tiny.amc -o /proc/no/such/dir", "/proc/no/such/dir");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_parts_and_holes),
		cmocka_unit_test(test_bad_arguments),
	};
	return cmocka_run_group_tests_name("compare_parts", tests, test_report_setup, test_report_teardown);
}
