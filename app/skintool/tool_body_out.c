#include "tool_body_out.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cli_error.h"
#include "cli_text_out.h"

static void write_body(FILE *f, const mesh *m, const char *what)
{
	fprintf(f, "# %s: %d vertices, %d triangles\n", what, m->vert_count, m->tri_count);
	for (int i = 0; i < m->vert_count; i++)
		fprintf(f, "v %.9g %.9g %.9g\n", m->pos[i].x, m->pos[i].y, m->pos[i].z);
	for (int i = 0; i < m->vert_count; i++)
		fprintf(f, "vn %.6g %.6g %.6g\n", m->normal[i].x, m->normal[i].y, m->normal[i].z);
	for (int t = 0; t < m->tri_count; t++) {
		unsigned long a = m->tri[t][0] + 1UL, b = m->tri[t][1] + 1UL, c = m->tri[t][2] + 1UL;
		fprintf(f, "f %lu//%lu %lu//%lu %lu//%lu\n", a, a, b, b, c, c);
	}
}

int tool_write_obj(const char *path, const mesh *m, const char *what)
{
	static cli_text_out out;
	if (cli_text_out_open(&out, path) < 0)
		return -1;
	write_body(out.f, m, what ? what : "skinplay mesh");
	return cli_text_out_commit(&out);
}

static int write_rows(FILE *f, const skel *s, const skin_weights *w)
{
	if (fprintf(f, "vertex,bone,weight\n") < 0)
		return -1;
	for (int v = 0; v < w->vert_count; v++)
		for (int k = 0; k < w->count[v]; k++)
			if (fprintf(f, "%d,%s,%.9g\n", v, s->bone[w->bone[v][k]].name,
				    (double)w->weight[v][k]) < 0)
				return -1;
	return 0;
}

int tool_write_weights(const char *path, const skel *s, const skin_weights *w)
{
	static cli_text_out out;
	if (strcmp(path, "-") == 0) {
		if (write_rows(stdout, s, w) == 0 && fflush(stdout) == 0)
			return 0;
		cli_error_errno("standard output", "write", -(errno ? errno : EIO));
		return -1;
	}
	if (cli_text_out_open(&out, path) < 0)
		return -1;
	write_rows(out.f, s, w);
	return cli_text_out_commit(&out);
}
