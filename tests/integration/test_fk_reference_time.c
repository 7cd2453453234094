/* Acceptance: `skintool fk --time` agrees with an independent
 * double-precision reference interpolated by slerp (each bone's local
 * rotation, between the frames around the time) within 1e-5 of the
 * skeleton's extent, also on clips whose Euler values wrap by 360 degrees
 * between frames; at a captured frame's time it prints what --frame
 * prints. The reference (tests/support/test_fkref.c and the slerp below)
 * shares no code with app/: its own (simple, trusting) parser, 3x3
 * matrices and quaternions in double. `skintool fk` by frame:
 * test_fk_reference.c. */
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

typedef dmat3 mat;

/* ---- time: the reference interpolated ---- */

typedef struct {
	long n;
	double (*v)[FKREF_MAX][7];    /* every frame's values */
} rclip;

static void load_amc(const char *path, const fkref_skel *s, rclip *c)
{
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	char line[4096], name[64];
	long cap = 8192;
	c->v = calloc((size_t)cap, sizeof *c->v);
	c->n = 0;
	while (fgets(line, sizeof line, f)) {
		fkref_clean(line);
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
		int b = fkref_find(s, name);
		assert_true(b >= 0 && c->n > 0);
		char *p = line + off;
		for (int k = 0; k < s->b[b].nch; k++)
			c->v[c->n - 1][b][k] = strtod(p, &p);
	}
	fclose(f);
}

/* Bone i's local rotation C M C^T and translation from its values. */
static mat local_of(const fkref_skel *s, const double v[7], int i, double t[3])
{
	const fkref_bone *b = &s->b[i];
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
	return fkref_quat_mat(q);
}

/* The reference pose at clip time t (frame k at k / rate): slerp of each
 * local rotation, translations linear, then FK. */
static void pose_at(const fkref_skel *s, const rclip *c, double t, double rate, fkref_pose *p)
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
		const fkref_bone *b = &s->b[k];
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
	static fkref_skel s;
	static rclip c;
	static char cmd[16384];
	fkref_load_asf(asf, &s);
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
		fkref_pose p;
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
			mat g = fkref_quat_mat(q);
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
static void write_wrapped(const char *src, const char *dst, const fkref_skel *s)
{
	FILE *in = fopen(src, "rb"), *out = fopen(dst, "wb");
	assert_non_null(in);
	assert_non_null(out);
	char line[4096], copy[4096], name[64];
	long frame = 0;
	while (fgets(line, sizeof line, in)) {
		snprintf(copy, sizeof copy, "%s", line);
		fkref_clean(copy);
		int off = 0;
		char *end;
		if (sscanf(copy, "%63s%n", name, &off) != 1 || name[0] == ':' || name[0] == '#' ||
		    (strtol(name, &end, 10), *end == '\0')) {
			if (sscanf(copy, "%63s", name) == 1 && (strtol(name, &end, 10), *end == '\0'))
				frame++;
			fputs(line, out);
			continue;
		}
		int b = fkref_find(s, name);
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
		static fkref_skel s;
		char asf[1024], amc[1024], wrapped[1100];
		snprintf(asf, sizeof asf, "%s", test_data_path(test_clips[i].asf));
		snprintf(amc, sizeof amc, "%s", test_data_path(test_clips[i].amc));
		fkref_load_asf(asf, &s);
		double height = fkref_skeleton_height(&s), d = (double)test_clips[i].frames / 120.0;
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
		cmocka_unit_test(test_time_matches_slerp_reference),
		cmocka_unit_test(test_time_at_a_frame_is_the_frame),
	};
	return cmocka_run_group_tests_name("fk_reference_time", tests, NULL, NULL);
}
