/* An ISO 8601 UTC time as ns since the Unix epoch (utc_time.c): the
 * synchronised show's epoch (app/play/play_sync.h), from board.ini and the
 * command line. */
#ifndef UTC_TIME_H
#define UTC_TIME_H

#include <stdint.h>

/* "2026-01-01T00:00:00Z" (a fraction of a second allowed, "Z" or
 * "+00:00"; years 1900 to 2200) into *ns. 0, or -1 when text is not one. */
int utc_time_parse(const char *text, int64_t *ns);

#endif
