/* Acceptance: `skintool fk` agrees with an independent double-precision
 * implementation of the FK semantics on every clip in ../shared/data/mocap,
 * within 1e-4 of the skeleton's height. The reference below shares no code
 * with app/: its own (simple, trusting) parser, 3x3 matrices in double. */
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

#define RMAX 160

typedef dmat3 mat;

typedef struct {
	char name[64];
	int parent;
	double dir[3], len;
	mat c;              /* axis rotation */
	int nch, ch[7];     /* 0..2 rx ry rz, 3..5 tx ty tz, 6 l */
} rbone;

typedef struct {
	int n;
	int deg;
	double per_unit;    /* 1 / :units length: Acclaim lengths are divided by it */
	double pos[3];
	rbone b[RMAX];
} rskel;

/* first letter applied first: C = R3 * R2 * R1 */
static mat axis_mat(const double a[3], const char *order, double unit)
{
	mat r = dmat3_rot(0, 0);
	for (int k = 0; k < 3; k++) {
		int ax = (order[k] | 0x20) - 'x';
		r = dmat3_mul(dmat3_rot(ax, a[ax] * unit), r);
	}
	return r;
}

static int find(const rskel *s, const char *name)
{
	for (int i = 0; i < s->n; i++)
		if (strcmp(s->b[i].name, name) == 0)
			return i;
	return -1;
}

static int chan(const char *t)
{
	static const char *names[] = { "rx", "ry", "rz", "tx", "ty", "tz", "l" };
	for (int i = 0; i < 7; i++)
		if (strcasecmp(t, names[i]) == 0)
			return i;
	return -1;
}

static void clean(char *line)
{
	for (char *p = line; *p; p++)
		if (*p == '(' || *p == ')' || *p == ',' || *p == '\r' || *p == '\n' || *p == '\t')
			*p = ' ';
}

static void load_asf(const char *path, rskel *s)
{
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	char line[4096], sec[64] = "", w[8][64];
	double orient[3] = { 0, 0, 0 };
	char root_axis[64] = "XYZ";
	rbone *b = NULL;
	memset(s, 0, sizeof *s);
	s->deg = 1;
	s->per_unit = 1;
	s->n = 1;
	strcpy(s->b[0].name, "root");
	s->b[0].parent = -1;
	for (int i = 0; i < 6; i++)
		s->b[0].ch[i] = (i + 3) % 6; /* TX TY TZ RX RY RZ until told */
	s->b[0].nch = 6;
	while (fgets(line, sizeof line, f)) {
		clean(line);
		int n = sscanf(line, "%63s %63s %63s %63s %63s %63s %63s %63s", w[0], w[1], w[2], w[3],
			       w[4], w[5], w[6], w[7]);
		if (n <= 0 || w[0][0] == '#')
			continue;
		if (w[0][0] == ':') {
			snprintf(sec, sizeof sec, "%s", w[0]);
			continue;
		}
		if (!strcmp(sec, ":units") && !strcmp(w[0], "angle"))
			s->deg = strcmp(w[1], "rad") != 0;
		if (!strcmp(sec, ":units") && !strcmp(w[0], "length"))
			s->per_unit = 1.0 / atof(w[1]);
		if (!strcmp(sec, ":root")) {
			if (!strcasecmp(w[0], "order")) {
				s->b[0].nch = n - 1;
				for (int i = 1; i < n; i++)
					s->b[0].ch[i - 1] = chan(w[i]);
			} else if (!strcmp(w[0], "axis"))
				snprintf(root_axis, sizeof root_axis, "%s", w[1]);
			else if (!strcmp(w[0], "position"))
				for (int i = 0; i < 3; i++) s->pos[i] = atof(w[i + 1]);
			else if (!strcmp(w[0], "orientation"))
				for (int i = 0; i < 3; i++) orient[i] = atof(w[i + 1]);
		}
		if (!strcmp(sec, ":bonedata")) {
			if (!strcmp(w[0], "begin")) {
				b = &s->b[s->n++];
				memset(b, 0, sizeof *b);
				b->c = dmat3_rot(0, 0);
			} else if (!strcmp(w[0], "name"))
				snprintf(b->name, sizeof b->name, "%s", w[1]);
			else if (!strcmp(w[0], "direction"))
				for (int i = 0; i < 3; i++) b->dir[i] = atof(w[i + 1]);
			else if (!strcmp(w[0], "length"))
				b->len = atof(w[1]);
			else if (!strcmp(w[0], "axis")) {
				double a[3] = { atof(w[1]), atof(w[2]), atof(w[3]) };
				b->c = axis_mat(a, w[4], s->deg ? M_PI / 180 : 1);
			} else if (!strcmp(w[0], "dof")) {
				b->nch = n - 1;
				for (int i = 1; i < n; i++)
					b->ch[i - 1] = chan(w[i]);
			}
		}
		if (!strcmp(sec, ":hierarchy") && strcmp(w[0], "begin") && strcmp(w[0], "end")) {
			/* a hierarchy line may hold more than 8 words: re-scan it */
			char *save, *tok = strtok_r(line, " ", &save);
			int parent = find(s, tok);
			while ((tok = strtok_r(NULL, " ", &save)))
				s->b[find(s, tok)].parent = parent;
		}
	}
	fclose(f);
	s->b[0].c = axis_mat(orient, root_axis, s->deg ? M_PI / 180 : 1);
	for (int i = 1; i < s->n; i++) {
		double *d = s->b[i].dir, l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
		if (l > 0)
			for (int k = 0; k < 3; k++) d[k] /= l;
	}
}

typedef struct {
	mat g[RMAX];
	double tip[RMAX][3];
	int done[RMAX];
} rpose;

static void pose_bone(const rskel *s, const double v[RMAX][7], int i, rpose *p)
{
	if (p->done[i])
		return;
	const rbone *b = &s->b[i];
	double unit = s->deg ? M_PI / 180 : 1;
	mat m = dmat3_rot(0, 0);
	double t[3] = { 0, 0, 0 };
	for (int k = 0; k < b->nch; k++) {
		if (b->ch[k] < 3)
			m = dmat3_mul(dmat3_rot(b->ch[k], v[i][k] * unit), m);
		else if (b->ch[k] < 6)
			t[b->ch[k] - 3] = v[i][k] * s->per_unit;
	}
	if (i == 0) {
		p->g[0] = dmat3_mul(dmat3_mul(b->c, m), dmat3_transpose(b->c));
		for (int k = 0; k < 3; k++)
			p->tip[0][k] = s->pos[k] * s->per_unit + t[k];
	} else {
		pose_bone(s, v, b->parent, p);
		p->g[i] = dmat3_mul(p->g[b->parent], dmat3_mul(dmat3_mul(b->c, m), dmat3_transpose(b->c)));
		for (int r = 0; r < 3; r++) {
			double d = 0;
			for (int k = 0; k < 3; k++)
				d += p->g[i].m[r][k] * b->dir[k];
			p->tip[i][r] = p->tip[b->parent][r] + b->len * s->per_unit * d;
		}
	}
	p->done[i] = 1;
}

static mat quat_mat(const double q[4])
{
	double w = q[0], x = q[1], y = q[2], z = q[3];
	mat r = { { { 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y) },
		    { 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x) },
		    { 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y) } } };
	return r;
}

static double skeleton_height(const rskel *s)
{
	static double zero[RMAX][7];
	rpose p;
	memset(&p, 0, sizeof p);
	double lo = 1e30, hi = -1e30;
	for (int i = 0; i < s->n; i++) {
		pose_bone(s, zero, i, &p);
		lo = fmin(lo, p.tip[i][1]);
		hi = fmax(hi, p.tip[i][1]);
	}
	return hi - lo;
}


typedef struct {
	double pos_err, rot_err, height;
	long frames, rows;
} result;

/* Reads the reference frames from the AMC in lockstep with skintool's CSV. */
static void compare_clip(const test_clip *c, result *res)
{
	static rskel s;
	static double v[RMAX][7];
	const char *asf = test_data_path(c->asf);
	const char *amc = test_data_path(c->amc);
	load_asf(asf, &s);
	res->height = skeleton_height(&s);

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
		clean(line);
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
			rpose p;
			memset(&p, 0, sizeof p);
			for (int i = 0; i < s.n; i++) {
				pose_bone(&s, v, i, &p);
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
				mat g = quat_mat(q);
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
		int b = find(&s, name);
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
	for (size_t i = 0; i < (size_t)test_clip_count; i++) {
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
