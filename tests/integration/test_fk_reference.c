/* Acceptance: `skintool fk` agrees with an independent double-precision
 * implementation of the FK semantics on every clip in ../shared/data/mocap,
 * within 1e-4 of the skeleton's height, and --frame prints that frame
 * alone. The reference (tests/support/test_fkref.c) shares no code with
 * app/: its own (simple, trusting) parser, 3x3 matrices and quaternions in
 * double. `skintool fk --time`: test_fk_reference_time.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test_clips.h"
#include "test_fkref.h"
#include "test_paths.h"

typedef struct {
	double pos_err, rot_err, height;
	long frames, rows;
} result;

/* Reads the reference frames from the AMC in lockstep with skintool's CSV. */
static void compare_clip(const test_clip *c, result *res)
{
	static fkref_skel s;
	static double v[FKREF_MAX][7];
	const char *asf = test_data_path(c->asf);
	const char *amc = test_data_path(c->amc);
	fkref_load_asf(asf, &s);
	res->height = fkref_skeleton_height(&s);

	char cmd[2048];
	snprintf(cmd, sizeof cmd, "%s fk '%s' '%s'", test_tool_path("skintool"), asf, amc);
	FILE *csv = popen(cmd, "r");
	FILE *f = fopen(amc, "rb");
	assert_non_null(csv);
	assert_non_null(f);
	char line[4096], row[512];
	assert_non_null(fgets(row, sizeof row, csv));
	assert_string_equal(row, "frame,bone,x,y,z,qw,qx,qy,qz\n");

	long frame = -1;
	int have_frame = 0, eof = 0;
	while (!eof) {
		eof = !fgets(line, sizeof line, f);
		fkref_clean(line);
		char name[64];
		int off = 0;
		if (!eof && sscanf(line, "%63s%n", name, &off) != 1)
			continue;
		if (!eof && name[0] == ':' )
			continue;
		if (!eof && name[0] == '#')
			continue;
		char *end;
		long num = eof ? 0 : strtol(name, &end, 10);
		int is_number = !eof && *end == '\0';
		if ((is_number || eof) && have_frame) {
			fkref_pose p;
			memset(&p, 0, sizeof p);
			for (int i = 0; i < s.n; i++) {
				fkref_pose_bone(&s, v, i, &p);
				long fr;
				char bone[64];
				double x, y, z, q[4];
				assert_non_null(fgets(row, sizeof row, csv));
				assert_int_equal(sscanf(row, "%ld,%63[^,],%lf,%lf,%lf,%lf,%lf,%lf,%lf", &fr, bone, &x,
							&y, &z, &q[0], &q[1], &q[2], &q[3]), 9);
				assert_int_equal(fr, frame);
				assert_string_equal(bone, s.b[i].name);
				assert_true(q[0] >= 0.0);
				double d = fmax(fabs(x - p.tip[i][0]), fmax(fabs(y - p.tip[i][1]), fabs(z - p.tip[i][2])));
				res->pos_err = fmax(res->pos_err, d);
				dmat3 g = fkref_quat_mat(q);
				for (int r = 0; r < 3; r++)
					for (int k = 0; k < 3; k++)
						res->rot_err = fmax(res->rot_err, fabs(g.m[r][k] - p.g[i].m[r][k]));
				res->rows++;
			}
			res->frames++;
			have_frame = 0;
		}
		if (eof)
			break;
		if (is_number) {
			frame = num;
			have_frame = 1;
			memset(v, 0, sizeof v);
			continue;
		}
		int b = fkref_find(&s, name);
		assert_true(b >= 0);
		char *p = line + off;
		for (int k = 0; k < s.b[b].nch; k++)
			v[b][k] = strtod(p, &p);
	}
	assert_null(fgets(row, sizeof row, csv));
	assert_int_equal(pclose(csv), 0);
	fclose(f);
}

static void test_all_clips_match_reference(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	const int slow = test_slow();
	for (int i = 0; i < test_clip_count; i++) {
		/* under the sanitizers or an emulator (skintool fk's 10,500
		 * frames took 14 s under qemu) the first clip of each source,
		 * whose skeletons and units differ; natively every clip */
		if (slow && test_clip_source_seen(i))
			continue;
		result r = { 0, 0, 0, 0, 0 };
		compare_clip(&test_clips[i], &r);
		print_message("%-45s %5ld frames, height %7.3f, max position error %.3g (%.2g of height), max rotation error %.3g\n",
			      test_clips[i].amc, r.frames, r.height, r.pos_err, r.pos_err / r.height, r.rot_err);
		assert_int_equal(r.frames, test_clips[i].frames);
		assert_true(r.pos_err <= 1e-4 * r.height);
		assert_true(r.rot_err <= 1e-4);
	}
}

static void test_single_frame_option(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	char cmd[2048];
	snprintf(cmd, sizeof cmd, "%s fk '%s' '%s' --frame 200", test_tool_path("skintool"),
		 test_data_path("mocap/cmu/02.asf"), test_data_path("mocap/cmu/02_01.amc"));
	FILE *csv = popen(cmd, "r");
	char row[512];
	int rows = 0;
	assert_non_null(fgets(row, sizeof row, csv));
	while (fgets(row, sizeof row, csv)) {
		assert_true(strncmp(row, "200,", 4) == 0);
		if (rows == 0)
			assert_true(strncmp(row, "200,root,", 9) == 0);
		rows++;
	}
	assert_int_equal(pclose(csv), 0);
	assert_int_equal(rows, 31);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_all_clips_match_reference),
		cmocka_unit_test(test_single_frame_option),
	};
	return cmocka_run_group_tests_name("fk_reference", tests, NULL, NULL);
}
