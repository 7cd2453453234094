/* The independent FK reference (test_fkref.h). */
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

#include "test_fkref.h"

/* first letter applied first: C = R3 * R2 * R1 */
static dmat3 axis_mat(const double a[3], const char *order, double unit)
{
	dmat3 r = dmat3_rot(0, 0);
	for (int k = 0; k < 3; k++) {
		int ax = (order[k] | 0x20) - 'x';
		r = dmat3_mul(dmat3_rot(ax, a[ax] * unit), r);
	}
	return r;
}

int fkref_find(const fkref_skel *s, const char *name)
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

void fkref_clean(char *line)
{
	for (char *p = line; *p; p++)
		if (*p == '(' || *p == ')' || *p == ',' || *p == '\r' || *p == '\n' || *p == '\t')
			*p = ' ';
}

void fkref_load_asf(const char *path, fkref_skel *s)
{
	FILE *f = fopen(path, "rb");
	assert_non_null(f);
	char line[4096], sec[64] = "", w[8][64];
	double orient[3] = { 0, 0, 0 };
	char root_axis[64] = "XYZ";
	fkref_bone *b = NULL;
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
		fkref_clean(line);
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
			int parent = fkref_find(s, tok);
			while ((tok = strtok_r(NULL, " ", &save)))
				s->b[fkref_find(s, tok)].parent = parent;
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

void fkref_pose_bone(const fkref_skel *s, const double v[FKREF_MAX][7], int i, fkref_pose *p)
{
	if (p->done[i])
		return;
	const fkref_bone *b = &s->b[i];
	double unit = s->deg ? M_PI / 180 : 1;
	dmat3 m = dmat3_rot(0, 0);
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
		fkref_pose_bone(s, v, b->parent, p);
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

dmat3 fkref_quat_mat(const double q[4])
{
	double w = q[0], x = q[1], y = q[2], z = q[3];
	dmat3 r = { { { 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y) },
		      { 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x) },
		      { 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y) } } };
	return r;
}

double fkref_skeleton_height(const fkref_skel *s)
{
	static double zero[FKREF_MAX][7];
	fkref_pose p;
	memset(&p, 0, sizeof p);
	double lo = 1e30, hi = -1e30;
	for (int i = 0; i < s->n; i++) {
		fkref_pose_bone(s, zero, i, &p);
		lo = fmin(lo, p.tip[i][1]);
		hi = fmax(hi, p.tip[i][1]);
	}
	return hi - lo;
}
