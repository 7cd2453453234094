#include "setup_mesh_io.h"

#include <stdio.h>
#include <string.h>

#include "cli_error.h"
#include "setup_scratch.h"
#include "cli_text_out.h"
#include "file_reader.h"

const obj_work *setup_load_obj(const char *path, const char *group, mesh *out, int *group_missing)
{
	obj_work *work = &setup_scratch_area()->obj;
	static file_reader fr;
	static text_lines tl;
	obj_options opt = { group, 0, 0 };
	skp_error err;

	if (group_missing)
		*group_missing = 0;
	int rc = file_reader_open(&fr, path);
	if (rc < 0) {
		fprintf(stderr, "%s: cannot open: %s\n", path, strerror(-rc));
		return NULL;
	}
	text_lines_init(&tl, file_reader_as_reader(&fr));
	skp_status st = obj_parse(out, work, &tl, &opt, &err);
	file_reader_close(&fr);
	if (st != SKP_OK) {
		cli_error(path, &err);
		if (group_missing)
			*group_missing = group && st == SKP_ERR_RANGE && work->kept_faces == 0 && err.line == 0;
		return NULL;
	}
	return work;
}

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

int mesh_write_obj(const char *path, const mesh *m, const char *what)
{
	static cli_text_out out;
	if (cli_text_out_open(&out, path) < 0)
		return -1;
	write_body(out.f, m, what ? what : "skinplay mesh");
	return cli_text_out_commit(&out);
}

int setup_obj_is_generated(const char *path)
{
	char line[128];
	FILE *f = fopen(path, "r");
	if (!f)
		return 0;
	size_t n = strlen(TOOL_GENERATED_BODY);
	int yes = fgets(line, sizeof line, f) && line[0] == '#' && line[1] == ' ' &&
		  strncmp(line + 2, TOOL_GENERATED_BODY, n) == 0 && line[2 + n] == ':';
	fclose(f);
	return yes;
}
