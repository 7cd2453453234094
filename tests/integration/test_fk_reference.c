/* Acceptance: `skintool fk` agrees with an independent double-precision
 * implementation of the FK semantics on every clip in ../shared/data/mocap,
 * within 1e-4 of the skeleton's height; `skintool fk --time` with the same
 * reference interpolated by slerp (each bone's local rotation, between the
 * frames around the time) within 1e-5 of the skeleton's extent, also on
 * clips whose Euler values wrap by 360 degrees between frames. The
 * reference below shares no code with app/: its own (simple, trusting)
 * parser, 3x3 matrices and quaternions in double. */
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
#include <unistd.h>

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


/* ---- time: the reference interpolated ---- */

typedef struct {
	long n;
	double (*v)[RMAX][7];    /* every frame's values */
} rclip;

static void load_amc(const char *path, const rskel *s, rclip *c)
{
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	char line[4096], name[64];
	long cap = 8192;
	c->v = calloc((size_t)cap, sizeof *c->v);
	c->n = 0;
	while (fgets(line, sizeof line, f)) {
		clean(line);
		int off = 0;
		if (sscanf(line, "%63s%n", name, &off) != 1 || name[0] == ':' || name[0] == '#')
			continue;
		char *end;
		strtol(name, &end, 10);
		if (*end == '\0') {
			assert_true(c->n < cap);
			c->n++;
			continue;
		}
		int b = find(s, name);
		assert_true(b >= 0 && c->n > 0);
		char *p = line + off;
		for (int k = 0; k < s->b[b].nch; k++)
			c->v[c->n - 1][b][k] = strtod(p, &p);
	}
	fclose(f);
}

/* Bone i's local rotation C M C^T and translation from its values. */
static mat local_of(const rskel *s, const double v[7], int i, double t[3])
{
	const rbone *b = &s->b[i];
	double unit = s->deg ? M_PI / 180 : 1;
	mat m = dmat3_rot(0, 0);
	t[0] = t[1] = t[2] = 0;
	for (int k = 0; k < b->nch; k++) {
		if (b->ch[k] < 3)
			m = dmat3_mul(dmat3_rot(b->ch[k], v[k] * unit), m);
		else if (b->ch[k] < 6)
			t[b->ch[k] - 3] = v[k] * s->per_unit;
	}
	return dmat3_mul(dmat3_mul(b->c, m), dmat3_transpose(b->c));
}

static void mat_quat(mat m, double q[4])
{
	double tr = m.m[0][0] + m.m[1][1] + m.m[2][2];
	if (tr > 0) {
		double r = sqrt(1 + tr) * 2;
		q[0] = r / 4; q[1] = (m.m[2][1] - m.m[1][2]) / r; q[2] = (m.m[0][2] - m.m[2][0]) / r; q[3] = (m.m[1][0] - m.m[0][1]) / r;
	} else if (m.m[0][0] > m.m[1][1] && m.m[0][0] > m.m[2][2]) {
		double r = sqrt(1 + m.m[0][0] - m.m[1][1] - m.m[2][2]) * 2;
		q[0] = (m.m[2][1] - m.m[1][2]) / r; q[1] = r / 4; q[2] = (m.m[0][1] + m.m[1][0]) / r; q[3] = (m.m[0][2] + m.m[2][0]) / r;
	} else if (m.m[1][1] > m.m[2][2]) {
		double r = sqrt(1 + m.m[1][1] - m.m[0][0] - m.m[2][2]) * 2;
		q[0] = (m.m[0][2] - m.m[2][0]) / r; q[1] = (m.m[0][1] + m.m[1][0]) / r; q[2] = r / 4; q[3] = (m.m[1][2] + m.m[2][1]) / r;
	} else {
		double r = sqrt(1 + m.m[2][2] - m.m[0][0] - m.m[1][1]) * 2;
		q[0] = (m.m[1][0] - m.m[0][1]) / r; q[1] = (m.m[0][2] + m.m[2][0]) / r; q[2] = (m.m[1][2] + m.m[2][1]) / r; q[3] = r / 4;
	}
}

static mat slerp_mat(mat a, mat b, double t)
{
	double qa[4], qb[4], q[4];
	mat_quat(a, qa);
	mat_quat(b, qb);
	double d = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3];
	if (d < 0) {
		d = -d;
		for (int k = 0; k < 4; k++) qb[k] = -qb[k];
	}
	double th = acos(fmin(1.0, d)), wa = 1 - t, wb = t;
	if (th > 1e-12) {
		wa = sin((1 - t) * th) / sin(th);
		wb = sin(t * th) / sin(th);
	}
	double n = 0;
	for (int k = 0; k < 4; k++) {
		q[k] = wa * qa[k] + wb * qb[k];
		n += q[k] * q[k];
	}
	for (int k = 0; k < 4; k++)
		q[k] /= sqrt(n);
	return quat_mat(q);
}

/* The reference pose at clip time t (frame k at k / rate): slerp of each
 * local rotation, translations linear, then FK. */
static void pose_at(const rskel *s, const rclip *c, double t, double rate, rpose *p)
{
	double x = t * rate;
	long i = (long)floor(x);
	double w = x - (double)i;
	if (i >= c->n - 1) {
		i = c->n - 1;
		w = 0;
	}
	long j = i + 1 < c->n ? i + 1 : i;
	memset(p, 0, sizeof *p);
	for (int k = 0; k < s->n; k++) { /* ASF order: parents first */
		const rbone *b = &s->b[k];
		double ta[3], tb[3];
		mat l = slerp_mat(local_of(s, c->v[i][k], k, ta), local_of(s, c->v[j][k], k, tb), w);
		double tr[3] = { ta[0] + (tb[0] - ta[0]) * w, ta[1] + (tb[1] - ta[1]) * w, ta[2] + (tb[2] - ta[2]) * w };
		if (k == 0) {
			p->g[0] = l;
			for (int r = 0; r < 3; r++)
				p->tip[0][r] = s->pos[r] * s->per_unit + tr[r];
			continue;
		}
		p->g[k] = dmat3_mul(p->g[b->parent], l);
		for (int r = 0; r < 3; r++) {
			double d = 0;
			for (int q = 0; q < 3; q++)
				d += p->g[k].m[r][q] * b->dir[q];
			p->tip[k][r] = p->tip[b->parent][r] + b->len * s->per_unit * d;
		}
	}
}

/* Runs skintool fk --time for times[] and compares every row with the
 * reference; returns the largest position error. */
static double compare_times(const char *asf, const char *amc, const double *times, int nt, double *rot_err)
{
	static rskel s;
	static rclip c;
	static char cmd[16384];
	load_asf(asf, &s);
	load_amc(amc, &s, &c);
	int at = snprintf(cmd, sizeof cmd, "%s fk '%s' '%s'", test_tool_path("skintool"), asf, amc);
	for (int i = 0; i < nt; i++)
		at += snprintf(cmd + at, sizeof cmd - (size_t)at, " --time=%.9f", times[i]);
	FILE *csv = popen(cmd, "r");
	assert_non_null(csv);
	char row[512];
	assert_non_null(fgets(row, sizeof row, csv));
	assert_string_equal(row, "time,bone,x,y,z,qw,qx,qy,qz\n");
	double worst = 0;
	*rot_err = 0;
	for (int i = 0; i < nt; i++) {
		rpose p;
		pose_at(&s, &c, times[i], 120.0, &p);
		for (int b = 0; b < s.n; b++) {
			double tt, x, y, z, q[4];
			char bone[64];
			assert_non_null(fgets(row, sizeof row, csv));
			assert_int_equal(sscanf(row, "%lf,%63[^,],%lf,%lf,%lf,%lf,%lf,%lf,%lf", &tt, bone, &x, &y, &z, &q[0],
						&q[1], &q[2], &q[3]), 9);
			assert_true(fabs(tt - times[i]) < 1e-12 + 1e-15 * times[i]);
			assert_string_equal(bone, s.b[b].name);
			worst = fmax(worst, fmax(fabs(x - p.tip[b][0]), fmax(fabs(y - p.tip[b][1]), fabs(z - p.tip[b][2]))));
			mat g = quat_mat(q);
			for (int r = 0; r < 3; r++)
				for (int k = 0; k < 3; k++)
					*rot_err = fmax(*rot_err, fabs(g.m[r][k] - p.g[b].m[r][k]));
		}
	}
	assert_null(fgets(row, sizeof row, csv));
	assert_int_equal(pclose(csv), 0);
	free(c.v);
	return worst;
}

/* The clip with 360 degrees added to every rotation of every other frame,
 * and angles past 180 written the other way round (179 -> -181): the
 * same rotations, Euler values that wrap between neighbouring frames. */
static void write_wrapped(const char *src, const char *dst, const rskel *s)
{
	FILE *in = fopen(src, "rb"), *out = fopen(dst, "wb");
	assert_non_null(in);
	assert_non_null(out);
	char line[4096], copy[4096], name[64];
	long frame = 0;
	while (fgets(line, sizeof line, in)) {
		snprintf(copy, sizeof copy, "%s", line);
		clean(copy);
		int off = 0;
		char *end;
		if (sscanf(copy, "%63s%n", name, &off) != 1 || name[0] == ':' || name[0] == '#' ||
		    (strtol(name, &end, 10), *end == '\0')) {
			if (sscanf(copy, "%63s", name) == 1 && (strtol(name, &end, 10), *end == '\0'))
				frame++;
			fputs(line, out);
			continue;
		}
		int b = find(s, name);
		char *p = copy + off;
		fprintf(out, "%s", name);
		for (int k = 0; k < s->b[b].nch; k++) {
			double v = strtod(p, &p);
			if (s->b[b].ch[k] < 3) {
				if (frame % 2)
					v += 360.0;
				else if (v > 90.0)
					v -= 360.0;
			}
			fprintf(out, " %.9g", v);
		}
		fputc('\n', out);
	}
	fclose(in);
	fclose(out);
}

static void test_time_matches_slerp_reference(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	static const char *const picks[] = { "mocap/cmu/02_01.amc", "mocap/cmu/kick.amc", "mocap/cmu/backflip.amc",
					     "mocap/cmu/lambada.amc" };
	double times[40];
	srand(20261128);
	for (size_t i = 0; i < (size_t)test_clip_count; i++) {
		int pick = 0;
		for (int k = 0; k < 4; k++)
			pick |= !strcmp(test_clips[i].amc, picks[k]);
		if (!pick)
			continue;
		static rskel s;
		char asf[1024], amc[1024], wrapped[1100];
		snprintf(asf, sizeof asf, "%s", test_data_path(test_clips[i].asf));
		snprintf(amc, sizeof amc, "%s", test_data_path(test_clips[i].amc));
		load_asf(asf, &s);
		double height = skeleton_height(&s), d = (double)test_clips[i].frames / 120.0;
		for (int k = 0; k < 40; k++)
			times[k] = round((k == 39 ? d + 1.0 : d * rand() / (double)RAND_MAX) * 1e9) * 1e-9; /* and one past the end */
		for (int w = 0; w < 2; w++) {
			if (w) {
				snprintf(wrapped, sizeof wrapped, "%s/skp_wrapped_%d.amc", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp",
					 (int)getpid());
				write_wrapped(amc, wrapped, &s);
			}
			double rot, pos = compare_times(asf, w ? wrapped : amc, times, 40, &rot);
			print_message("%-28s %s: 40 times, max position error %.3g (%.2g of the extent), rotation %.3g\n",
				      test_clips[i].amc, w ? "wrapped by 360" : "as captured   ", pos, pos / height, rot);
			assert_true(pos <= 1e-5 * height);
			assert_true(rot <= 1e-5);
			if (w)
				unlink(wrapped);
		}
	}
}

/* At a captured frame's time --time prints what --frame prints. */
static void test_time_at_a_frame_is_the_frame(void **state)
{
	(void)state;
	if (!test_data_path("mocap"))
		skip();
	char a[4096], b[4096], cmd[2048];
	const char *asf = test_data_path("mocap/cmu/02.asf");
	char amc[1024];
	snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/02_01.amc"));
	snprintf(cmd, sizeof cmd, "%s fk '%s' '%s' --frame 201 | tail -n +2 | cut -d, -f2-", test_tool_path("skintool"),
		 asf, amc);
	FILE *f = popen(cmd, "r");
	size_t na = fread(a, 1, sizeof a - 1, f);
	pclose(f);
	snprintf(cmd, sizeof cmd, "%s fk '%s' '%s' --time=%.17g | tail -n +2 | cut -d, -f2-",
		 test_tool_path("skintool"), asf, amc, 200.0 / 120.0);
	f = popen(cmd, "r");
	size_t nb = fread(b, 1, sizeof b - 1, f);
	pclose(f);
	assert_true(na > 100);
	assert_int_equal(na, nb);
	assert_memory_equal(a, b, na);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_all_clips_match_reference),
		cmocka_unit_test(test_single_frame_option),
		cmocka_unit_test(test_time_matches_slerp_reference),
		cmocka_unit_test(test_time_at_a_frame_is_the_frame),
	};
	return cmocka_run_group_tests_name("fk_reference", tests, NULL, NULL);
}
