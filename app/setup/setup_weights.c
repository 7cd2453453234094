#include "setup_weights.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "cli_error.h"
#include "cli_text_out.h"
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

int setup_write_weights(const char *path, const skel *s, const skin_weights *w)
{
	static cli_text_out out;
	if (strcmp(path, "-") == 0) {
		int rc = write_rows(stdout, s, w) < 0 || fflush(stdout) != 0 ? -1 : 0;
		if (rc < 0)
			fprintf(stderr, "-: write failed: %s\n", strerror(errno));
		return rc;
	}
	if (cli_text_out_open(&out, path) < 0)
		return -1;
	write_rows(out.f, s, w);
	return cli_text_out_commit(&out);
}

int setup_load_weights(const char *path, const skel *s, int vert_count, skin_weights *out)
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
