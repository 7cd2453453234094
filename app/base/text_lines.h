/* Splits a byte stream into lines with a fixed buffer: LF, CRLF and CR all
 * end a line, bytes are passed through untouched (Latin-1 is fine). */
#ifndef TEXT_LINES_H
#define TEXT_LINES_H

#include <stddef.h>

#include "board_limits.h"
#include "skp_error.h"
#include "skp_reader.h"

typedef struct text_lines {
	skp_reader rd;
	size_t pos, end;          /* unread bytes are chunk[pos..end) */
	int eof;
	int after_cr;             /* previous line ended in CR: swallow one LF */
	long line_no;             /* 1-based number of the last line returned */
	char chunk[SKP_READ_CHUNK];
	char line[SKP_MAX_LINE];
} text_lines;

void text_lines_init(text_lines *tl, skp_reader rd);

/* Returns 1 and the NUL-terminated line (without its end) in *line,
 * 0 at the end of input, or a negative skp_status on error (line too long,
 * NUL byte, read failure; err names the line). */
int text_lines_next(text_lines *tl, char **line, size_t *len, skp_error *err);

#endif
