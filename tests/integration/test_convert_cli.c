/* BVH through the real command lines. `skintool convert` both ways on every
 * clip in ../shared/data: `skintool fk` on the converted file prints the
 * same rows (names; positions within 1e-5 of the body's height) as on its
 * source. `skintool fk` on the CMU BVH agrees with FK computed here from
 * the file by the BVH rules, sharing no code with app/. And the rest of the
 * BVH front: pack, skinplay --bvh, and bad arguments or files. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "test_clips.h"
#include "test_dref.h"
#include "test_paths.h"
#include "test_run.h"

#define TOLERANCE 1e-5  /* of the body's height */

typedef struct fk_row {
	char name[64];
	double p[3];
} fk_row;

typedef struct fk_rows {
	long n;
	fk_row *row;
	double height;      /* y extent of every position */
} fk_rows;

/* `skintool fk ARGS` into rows. */
static void fk_rows_of(const char *args, fk_rows *out)
{
	const char *csv = test_scratch("fk.csv");
	if (test_run("%s fk %s > %s", test_tool_path("skintool"), args, csv) != 0)
		fail_msg("skintool fk %s failed", args);
	FILE *f = fopen(csv, "r");
	assert_non_null(f);
	char line[512];
	long cap = 1024;
	double lo = INFINITY, hi = -INFINITY;
	out->n = 0;
	out->row = malloc(sizeof *out->row * (size_t)cap);
	assert_non_null(fgets(line, sizeof line, f));
	assert_string_equal(line, "frame,bone,x,y,z,qw,qx,qy,qz\n");
	while (fgets(line, sizeof line, f)) {
		if (out->n == cap)
			out->row = realloc(out->row, sizeof *out->row * (size_t)(cap *= 2));
		fk_row *r = &out->row[out->n++];
		if (sscanf(line, "%*d,%63[^,],%lf,%lf,%lf", r->name, &r->p[0], &r->p[1], &r->p[2]) != 4)
			fail_msg("bad fk row '%s'", line);
		lo = fmin(lo, r->p[1]);
		hi = fmax(hi, r->p[1]);
	}
	fclose(f);
	out->height = hi - lo;
}

/* Same rows; root_renamed: an ASF calls the root "root" whatever a BVH
 * called it. Returns the largest distance over the height. */
static double compare_rows(const fk_rows *a, const fk_rows *b, int root_renamed)
{
	assert_int_equal(a->n, b->n);
	double worst = 0;
	for (long i = 0; i < a->n; i++) {
		const fk_row *x = &a->row[i], *y = &b->row[i];
		int is_root = strcasecmp(x->name, "root") == 0 || strcasecmp(y->name, "root") == 0;
		if (strcmp(x->name, y->name) != 0 && !(root_renamed && is_root))
			fail_msg("row %ld: joint '%s' became '%s'", i, x->name, y->name);
		double d = sqrt(pow(x->p[0] - y->p[0], 2) + pow(x->p[1] - y->p[1], 2) + pow(x->p[2] - y->p[2], 2));
		worst = fmax(worst, d / a->height);
	}
	return worst;
}

/* `fk` on the source, on it converted once and converted back: returns
 * the source's rows; e gets the largest distances of the other two. */
static long against_source(const char *src, const char *once, const char *back, int root_renamed, double e[2])
{
	fk_rows a, b, c;
	fk_rows_of(src, &a);
	fk_rows_of(once, &b);
	fk_rows_of(back, &c);
	e[0] = compare_rows(&a, &b, root_renamed);
	e[1] = compare_rows(&a, &c, root_renamed);
	long n = a.n;
	free(a.row);
	free(b.row);
	free(c.row);
	return n;
}

static void test_every_clip_converts_to_bvh_and_back(void **state)
{
	(void)state;
	if (!test_data_path(test_clips[0].asf))
		skip();
	const int slow = test_slow();
	for (int c = 0; c < test_clip_count; c++) {
		/* under the sanitizers or an emulator the clips of 400 frames or
		 * fewer, as test_codec_corpus (two conversions and three fk runs
		 * a clip, a frame's cost the same); natively every one */
		if (slow && test_clips[c].frames > 400)
			continue;
		char asf[4096], amc[4096], args[8192];
		snprintf(asf, sizeof asf, "%s", test_data_path(test_clips[c].asf));
		snprintf(amc, sizeof amc, "%s", test_data_path(test_clips[c].amc));
		const char *bvh = test_scratch("clip.bvh"), *back = test_scratch("back.asf");
		assert_int_equal(test_run("%s convert %s %s -o %s > /dev/null", test_tool_path("skintool"), asf, amc, bvh), 0);
		assert_int_equal(test_run("%s convert %s -o %s > /dev/null", test_tool_path("skintool"), bvh, back), 0);
		char back_args[8192];
		double e[2];
		snprintf(args, sizeof args, "%s %s", asf, amc);
		snprintf(back_args, sizeof back_args, "%s %s", back, test_scratch("back.amc"));
		long rows = against_source(args, bvh, back_args, 0, e);
		assert_int_equal(rows % test_clips[c].frames, 0);
		print_message("%-40s %6ld rows: to BVH %.2g, and back to ASF/AMC %.2g of the height\n",
			      test_clips[c].amc, rows, e[0], e[1]);
		assert_true(e[0] <= TOLERANCE && e[1] <= TOLERANCE);
	}
}

/* The CMU conversion's path (test_data_path's buffer is reused), or 0. */
static int shared_bvh(char path[4096])
{
	const char *p = test_data_path("mocap/cmu_bvh/131_01.bvh");
	if (p)
		snprintf(path, 4096, "%s", p);
	return p != NULL;
}

/* BVH -> ASF/AMC -> BVH on the CMU conversion. */
static void test_bvh_converts_to_asf_and_back(void **state)
{
	(void)state;
	char src_path[4096], args[8192];
	if (!shared_bvh(src_path))
		skip();
	const char *asf = test_scratch("from_bvh.asf"), *again = test_scratch("again.bvh");
	assert_int_equal(test_run("%s convert %s -o %s > /dev/null", test_tool_path("skintool"), src_path, asf), 0);
	assert_int_equal(test_run("%s convert %s %s -o %s > /dev/null", test_tool_path("skintool"), asf,
				  test_scratch("from_bvh.amc"), again), 0);
	double e[2];
	snprintf(args, sizeof args, "%s %s", asf, test_scratch("from_bvh.amc"));
	assert_int_equal(against_source(src_path, args, again, 1, e), 994 * 31);
	print_message("131_01.bvh: to ASF/AMC %.2g, and back to BVH %.2g of the height\n", e[0], e[1]);
	assert_true(e[0] <= TOLERANCE && e[1] <= TOLERANCE);
}

/* A joint branching off the middle of its parent's segment (c, beside b)
 * and a joint with position channels: both become ASF translations. */
static void test_siblings_and_joint_positions_survive_asf(void **state)
{
	(void)state;
	const char *bvh = test_scratch("sib.bvh"), *asf = test_scratch("sib.asf");
	FILE *f = fopen(bvh, "w");
	assert_non_null(f);
	fputs("HIERARCHY\nROOT r\n{\n OFFSET 5 0 0\n CHANNELS 3 Xrotation Yrotation Zrotation\n"
	      " JOINT a\n {\n  OFFSET 0 1 0\n  CHANNELS 1 Zrotation\n"
	      "  JOINT b\n  {\n   OFFSET 0 1 0\n   CHANNELS 2 Xrotation Yrotation\n"
	      "   End Site\n   {\n    OFFSET 0 1 0\n   }\n  }\n"
	      "  JOINT c\n  {\n   OFFSET 1 0 0\n"
	      "   CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
	      "   End Site\n   {\n    OFFSET 0 0 1\n   }\n  }\n }\n}\n"
	      "MOTION\nFrames: 3\nFrame Time: 0.5\n"
	      "0 0 0  0  0 0  1 0 0 0 0 0\n"
	      "10 20 30  40  -50 60  2 0.5 -1 15 25 35\n"
	      "-170 89.9 3  -120  5 -6  0 0 0 90 90 90\n", f);
	fclose(f);
	assert_int_equal(test_run("%s convert %s -o %s > /dev/null", test_tool_path("skintool"), bvh, asf), 0);
	assert_int_equal(test_run("grep -q 'dof tx ty tz' %s", asf), 0);
	fk_rows src, conv;
	char args[8192];
	fk_rows_of(bvh, &src);
	snprintf(args, sizeof args, "%s %s", asf, test_scratch("sib.amc"));
	fk_rows_of(args, &conv);
	src.height = 3.0;   /* the rows hardly move in y: measure against the figure's size */
	double e = compare_rows(&src, &conv, 1);
	print_message("siblings and joint positions: to ASF/AMC %.2g of the size\n", e);
	assert_true(e <= TOLERANCE);
	free(src.row);
	free(conv.row);
}

/* ---- an independent BVH reader and FK: trusting, double precision ---- */

#define RJ 64

typedef struct rjoint {
	char name[64];
	int parent, nch, ch[6];      /* 0..2 X Y Z position, 3..5 X Y Z rotation */
	double off[3], end[3];
	int has_end, first_child;
} rjoint;

typedef struct rbvh {
	int n;
	rjoint j[RJ];
	dmat3 m[RJ];
	double pos[RJ][3];
} rbvh;

static void rbvh_read(FILE *f, rbvh *b)
{
	char w[64];
	int stack[RJ], depth = 0, cur = -1;
	b->n = 0;
	while (fscanf(f, "%63s", w) == 1 && strcmp(w, "MOTION") != 0) {
		if (!strcmp(w, "ROOT") || !strcmp(w, "JOINT")) {
			rjoint *j = &b->j[b->n];
			assert_int_equal(fscanf(f, "%63s", j->name), 1);
			j->parent = cur;
			j->first_child = -1;
			if (cur >= 0 && b->j[cur].first_child < 0)
				b->j[cur].first_child = b->n;
			cur = b->n++;
		} else if (!strcmp(w, "End")) {
			assert_int_equal(fscanf(f, " Site { OFFSET %lf %lf %lf }", &b->j[cur].end[0], &b->j[cur].end[1],
						&b->j[cur].end[2]), 3);
			b->j[cur].has_end = 1;
		} else if (!strcmp(w, "{")) {
			stack[depth++] = cur;
		} else if (!strcmp(w, "}")) {
			cur = b->j[stack[--depth]].parent;
		} else if (!strcmp(w, "OFFSET")) {
			assert_int_equal(fscanf(f, "%lf %lf %lf", &b->j[cur].off[0], &b->j[cur].off[1], &b->j[cur].off[2]), 3);
		} else if (!strcmp(w, "CHANNELS")) {
			assert_int_equal(fscanf(f, "%d", &b->j[cur].nch), 1);
			for (int i = 0; i < b->j[cur].nch; i++) {
				char c[32];
				assert_int_equal(fscanf(f, "%31s", c), 1);
				b->j[cur].ch[i] = (c[0] - 'X') + (strstr(c, "rotation") ? 3 : 0);
			}
		}
	}
}

static void mat_apply(const dmat3 *m, const double v[3], double out[3])
{
	dvec r = dmat_apply(m->m, dv(v[0], v[1], v[2]));
	out[0] = r.x;
	out[1] = r.y;
	out[2] = r.z;
}

/* One frame: joint world matrices and positions (parents come first). */
static void rbvh_pose(FILE *f, rbvh *b)
{
	for (int i = 0; i < b->n; i++) {
		rjoint *j = &b->j[i];
		double local[3] = { j->off[0], j->off[1], j->off[2] };
		dmat3 m = j->parent >= 0 ? b->m[j->parent] : dmat3_rot(0, 0);
		for (int c = 0; c < j->nch; c++) {
			double v;
			assert_int_equal(fscanf(f, "%lf", &v), 1);
			if (j->ch[c] < 3)
				local[j->ch[c]] = v;
			else
				m = dmat3_mul(m, dmat3_rot(j->ch[c] - 3, v * M_PI / 180));
		}
		if (j->parent < 0) {
			memcpy(b->pos[i], local, sizeof local);
		} else {
			double d[3];
			mat_apply(&b->m[j->parent], local, d);
			for (int a = 0; a < 3; a++)
				b->pos[i][a] = b->pos[j->parent][a] + d[a];
		}
		b->m[i] = m;
	}
}

/* skintool fk's row for a joint is the end of its segment: its first
 * child joint, else its End Site (the root: its own position). */
static void row_position(rbvh *b, int i, double out[3])
{
	const rjoint *j = &b->j[i];
	if (j->parent < 0) {
		memcpy(out, b->pos[i], sizeof b->pos[i]);
	} else if (j->first_child >= 0) {
		memcpy(out, b->pos[j->first_child], sizeof b->pos[i]);
	} else {
		double d[3] = { 0, 0, 0 };
		if (j->has_end)
			mat_apply(&b->m[i], j->end, d);
		for (int a = 0; a < 3; a++)
			out[a] = b->pos[i][a] + d[a];
	}
}

static void test_bvh_fk_matches_an_independent_reading(void **state)
{
	(void)state;
	char src[4096];
	if (!shared_bvh(src))
		skip();
	fk_rows got;
	fk_rows_of(src, &got);
	static rbvh b;
	FILE *f = fopen(src, "r");
	assert_non_null(f);
	rbvh_read(f, &b);
	long frames;
	assert_int_equal(fscanf(f, " Frames: %ld Frame Time: %*f", &frames), 1);
	assert_int_equal(got.n, frames * b.n);
	double worst = 0;
	for (long fr = 0; fr < frames; fr++) {
		rbvh_pose(f, &b);
		for (int i = 0; i < b.n; i++) {
			const fk_row *r = &got.row[fr * b.n + i];
			double want[3];
			row_position(&b, i, want);
			assert_string_equal(r->name, b.j[i].name);
			double d = sqrt(pow(r->p[0] - want[0], 2) + pow(r->p[1] - want[1], 2) + pow(r->p[2] - want[2], 2));
			worst = fmax(worst, d / got.height);
		}
	}
	fclose(f);
	free(got.row);
	print_message("131_01.bvh: skintool fk against the reference: %.2g of the height at worst\n", worst);
	assert_true(worst <= TOLERANCE);
}

/* A BVH packs (Frame Time gives the rate) and plays headless. */
static void test_bvh_packs_and_plays(void **state)
{
	(void)state;
	char src[4096];
	if (!shared_bvh(src))
		skip();
	const char *skn = test_scratch("bvh.skn"), *out = test_scratch("bvh_frames");
	/* under the sanitizers or an emulator its first 100 frames are packed
	 * (the encoder took 12 s of the test's 24 there on all 994) */
	const int slow = test_slow();
	const char *packed = slow ? test_clip_head(src, 100, NULL) : src;
	assert_int_equal(test_run("%s pack %s --block-size 4096 -o %s > /dev/null", test_tool_path("skintool"), packed, skn),
			 0);
	assert_int_equal(test_run("%s info %s | grep -q '131_01.*%d frames.*120'", test_tool_path("skintool"), skn,
				  slow ? 100 : 994), 0);
	assert_int_equal(test_run("%s --bvh %s --platform surfaceless --size 160x120 --frames 2 --start 400 --out %s"
				  " > /dev/null 2>&1", test_tool_path("skinplay"), src, out), 0);
	char png[4200];
	for (int i = 1; i <= 2; i++) {
		snprintf(png, sizeof png, "%s/frame_%06d.png", out, i);
		size_t size = 0;
		char *data = test_read_file(png, &size);
		assert_non_null(data);
		assert_true(size > 1000);
		free(data);
	}
	assert_int_not_equal(test_run("%s --bvh %s --asf x.asf --frames 1 2>/dev/null", test_tool_path("skinplay"), src), 0);
}

typedef struct bad_cli {
	const char *args;       /* %s: the scratch directory */
	const char *needle;
} bad_cli;

static void test_bad_arguments_and_files(void **state)
{
	(void)state;
	const char *dir = test_scratch_dir();
	FILE *f = fopen(test_scratch("cut.bvh"), "w");
	assert_non_null(f);
	fputs("HIERARCHY\nROOT r\n{\n OFFSET 0 0 0\n CHANNELS 3 Xrotation Yrotation Zrotation\n"
	      " End Site\n {\n  OFFSET 0 1 0\n }\n}\nMOTION\nFrames: 2\nFrame Time: 0.1\n1 2 3\n1 2\n", f);
	fclose(f);
	f = fopen(test_scratch("keep.bvh"), "w");
	assert_non_null(f);
	fputs("precious\n", f);
	fclose(f);
	const bad_cli bad[] = {
		{ "convert %s/cut.bvh -o %s/out.txt", "expected a name ending in .bvh or .asf" },
		{ "convert %s/cut.bvh", "skintool convert: give SKELETON.asf MOTION.amc or IN.bvh, and -o OUT" },
		{ "convert %s/none.bvh -o %s/x.asf", "none.bvh: cannot open" },
		{ "convert %s/cut.bvh -o %s/keep.bvh", "cut.bvh:15: frame 2: expected 3 values, found 2" },
		{ "convert %s/cut.bvh -o %s/x.bvh --fps 0", "--fps expects a rate" },
		{ "fk %s/cut.bvh", "cut.bvh:15: frame 2: expected 3 values, found 2" },
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		char args[2048], err_path[4200];
		snprintf(args, sizeof args, bad[i].args, dir, dir);
		snprintf(err_path, sizeof err_path, "%s", test_scratch("err.txt"));
		int st = test_run("%s %s > /dev/null 2> %s", test_tool_path("skintool"), args, err_path);
		char *err = test_read_file(err_path, NULL);
		assert_non_null(err);
		if (st != 1 || !strstr(err, bad[i].needle))
			fail_msg("skintool %s: exit %d, '%s' (wanted 1 and '%s')", args, st, err, bad[i].needle);
		free(err);
	}
	/* the failed conversion left the old file whole, and no temporary */
	char *kept = test_read_file(test_scratch("keep.bvh"), NULL);
	assert_string_equal(kept, "precious\n");
	free(kept);
	assert_int_equal(test_run("ls -A %s | grep -q '^\\.keep'", dir), 1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_every_clip_converts_to_bvh_and_back),
		cmocka_unit_test(test_bvh_converts_to_asf_and_back),
		cmocka_unit_test(test_siblings_and_joint_positions_survive_asf),
		cmocka_unit_test(test_bvh_fk_matches_an_independent_reading),
		cmocka_unit_test(test_bvh_packs_and_plays),
		cmocka_unit_test(test_bad_arguments_and_files),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
