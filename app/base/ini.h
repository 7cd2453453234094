/* A small INI reader over text_lines: `[section]` headers, `key = value`
 * lines, `#` or `;` comments (whole lines, or after white space), blank
 * lines. No allocation: entries point into the line buffer and live until
 * the next call. */
#ifndef INI_H
#define INI_H

#include "text_lines.h"

typedef struct ini_reader {
	text_lines lines;
	char section[SKP_MAX_NAME];
	int stuck;               /* a line error the reader cannot go past */
} ini_reader;

typedef struct ini_entry {
	const char *section;     /* "" before the first header */
	const char *key, *value; /* trimmed; value may be "" */
	long line;
} ini_entry;

void ini_init(ini_reader *r, skp_reader rd);

/* 1 and the next key in *e, 0 at the end, or a negative skp_status with
 * err naming the line (a line that is neither header nor key = value). A
 * UTF-8 byte order mark before the first line is skipped. After a bad
 * line the next call goes on with the line after it (a bad header leaves
 * no section: its keys come in section "?") unless ini_can_go_on says no
 * (a line too long, a NUL byte, a read error). */
int ini_next(ini_reader *r, ini_entry *e, skp_error *err);

int ini_can_go_on(const ini_reader *r);

#endif
