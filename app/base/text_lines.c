#include "text_lines.h"

void text_lines_init(text_lines *tl, skp_reader rd)
{
	tl->rd = rd;
	tl->pos = tl->end = 0;
	tl->eof = 0;
	tl->after_cr = 0;
	tl->line_no = 0;
	tl->line[0] = '\0';
}

/* 1 when bytes are available, 0 at the end, negative on error */
static int fill(text_lines *tl, skp_error *err)
{
	if (tl->pos < tl->end)
		return 1;
	if (tl->eof)
		return 0;
	long n = tl->rd.read(tl->rd.ctx, tl->chunk, sizeof tl->chunk);
	if (n < 0)
		return -(int)skp_fail(err, SKP_ERR_IO, tl->line_no + 1, "read error");
	if (n == 0) {
		tl->eof = 1;
		return 0;
	}
	tl->pos = 0;
	tl->end = (size_t)n;
	return 1;
}

int text_lines_next(text_lines *tl, char **line, size_t *len, skp_error *err)
{
	size_t n = 0;
	int got_any = 0;

	for (;;) {
		int r = fill(tl, err);
		if (r < 0)
			return r;
		if (r == 0)
			break;
		char c = tl->chunk[tl->pos++];
		if (tl->after_cr) {
			tl->after_cr = 0;
			if (c == '\n')
				continue;
		}
		got_any = 1;
		if (c == '\n' || c == '\r') {
			tl->after_cr = (c == '\r');
			break;
		}
		if (c == '\0')
			return -(int)skp_fail(err, SKP_ERR_SYNTAX, tl->line_no + 1,
					      "unexpected NUL byte: not a text file");
		if (n + 1 >= sizeof tl->line)
			return -(int)skp_fail(err, SKP_ERR_LIMIT, tl->line_no + 1,
					      "line longer than %d bytes (board limit SKP_MAX_LINE)",
					      SKP_MAX_LINE - 1);
		tl->line[n++] = c;
	}
	if (!got_any)
		return 0;
	tl->line[n] = '\0';
	tl->line_no++;
	*line = tl->line;
	if (len)
		*len = n;
	return 1;
}
