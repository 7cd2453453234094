#include "cli_weights.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "file_reader.h"
#include "weights_csv.h"

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

int cli_write_weights(const char *path, const skel *s, const skin_weights *w)
{
	int to_stdout = strcmp(path, "-") == 0;
	FILE *f = to_stdout ? stdout : fopen(path, "w");
	if (!f) {
		fprintf(stderr, "%s: cannot create: %s\n", path, strerror(errno));
		return -1;
	}
	int rc = write_rows(f, s, w);
	if (fflush(f) != 0)
		rc = -1;
	int saved = errno;
	if (!to_stdout && fclose(f) != 0)
		rc = -1;
	if (rc < 0)
		fprintf(stderr, "%s: write failed: %s\n", path, strerror(saved ? saved : errno));
	return rc;
}

int cli_load_weights(const char *path, const skel *s, int vert_count, skin_weights *out)
{
	static file_reader fr;
	static text_lines tl;
	skp_error err;

	int rc = file_reader_open(&fr, path);
	if (rc < 0) {
		fprintf(stderr, "%s: cannot open: %s\n", path, strerror(-rc));
		return -1;
	}
	text_lines_init(&tl, file_reader_as_reader(&fr));
	skp_status st = weights_csv_read(&tl, s, vert_count, out, &err);
	file_reader_close(&fr);
	if (st != SKP_OK) {
		cli_error(path, &err);
		return -1;
	}
	return 0;
}
