#include "cli_common.h"

#include <stdio.h>
#include <string.h>

#include "asf.h"
#include "text_tokens.h"

void cli_error(const char *path, const skp_error *err)
{
	if (err->line > 0)
		fprintf(stderr, "%s:%ld: %s\n", path, err->line, err->msg);
	else if (err->block >= 0)
		fprintf(stderr, "%s: block %ld: %s\n", path, err->block, err->msg);
	else
		fprintf(stderr, "%s: %s\n", path, err->msg);
}

static int open_lines(const char *path, file_reader *fr, text_lines *tl)
{
	int rc = file_reader_open(fr, path);
	if (rc < 0) {
		fprintf(stderr, "%s: cannot open: %s\n", path, strerror(-rc));
		return -1;
	}
	text_lines_init(tl, file_reader_as_reader(fr));
	return 0;
}

int cli_load_skel(const char *path, skel *out)
{
	static file_reader fr;
	static text_lines tl;
	skp_error err;

	if (open_lines(path, &fr, &tl) < 0)
		return -1;
	skp_status rc = asf_parse(out, &tl, &err);
	file_reader_close(&fr);
	if (rc != SKP_OK) {
		cli_error(path, &err);
		return -1;
	}
	return 0;
}

int cli_motion_open(cli_motion *m, const char *path, const skel *s)
{
	/* a loop reopens the same file: its cut frame is reported once */
	if (m->path != path)
		m->warned_cut = 0;
	m->path = path;
	if (open_lines(path, &m->file, &m->lines) < 0)
		return -1;
	amc_open(&m->stream, s, &m->lines);
	return 0;
}

int cli_motion_next(cli_motion *m, amc_frame *f)
{
	skp_error err;
	int r = amc_next(&m->stream, f, &err);
	if (r < 0) {
		cli_error(m->path, &err);
		return -1;
	}
	if (r == 0 && m->stream.cut_frame >= 0 && !m->warned_cut) {
		fprintf(stderr, "%s:%ld: warning: frame %ld is cut short (the file ends inside it): dropped\n",
			m->path, m->stream.cut_line, m->stream.cut_frame);
		m->warned_cut = 1;
	}
	return r;
}

void cli_motion_close(cli_motion *m)
{
	file_reader_close(&m->file);
}

int cli_parse_long(const char *opt, const char *text, long *out)
{
	if (!text || tok_parse_long(text, out) != 0) {
		fprintf(stderr, "skintool: %s expects an integer, got '%s'\n", opt, text ? text : "");
		return -1;
	}
	return 0;
}

static void no_frame(const char *path, long number, long first, long last)
{
	if (first < 0)
		fprintf(stderr, "%s: no frames\n", path);
	else
		fprintf(stderr, "%s: no frame %ld (the file has frames %ld..%ld)\n", path, number,
			first, last);
}

int cli_read_frame(const char *path, const skel *s, long number, amc_frame *f)
{
	static cli_motion m;
	if (cli_motion_open(&m, path, s) < 0)
		return -1;
	int r;
	long first = -1, last = -1;
	while ((r = cli_motion_next(&m, f)) > 0) {
		if (first < 0)
			first = f->number;
		last = f->number;
		if (number < 0 || f->number == number)
			break;
	}
	cli_motion_close(&m);
	if (r < 0)
		return -1;
	if (r == 0) {
		no_frame(path, number, first, last);
		return -1;
	}
	return 0;
}

const char *cli_option_value(const char *cmd, const char *opt, int argc, char **argv, int *i)
{
	if (*i + 1 >= argc) {
		fprintf(stderr, "%s: %s needs a value\n", cmd, opt);
		return NULL;
	}
	return argv[++*i];
}

int cli_take_positional(const char *cmd, const char **const *slots, int n, const char *arg)
{
	for (int k = 0; k < n; k++)
		if (!*slots[k]) {
			*slots[k] = arg;
			return 0;
		}
	fprintf(stderr, "%s: unexpected argument '%s'\n", cmd, arg);
	return -1;
}

const char *cli_basename(const char *path)
{
	const char *s = strrchr(path, '/');
	return s ? s + 1 : path;
}
