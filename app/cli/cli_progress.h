/* Progress of a step that can take more than a second (metrics, compare,
 * pack, bench): on a terminal a line redrawn at most five times a second
 * with a bar, the count, the rate and the time left; nothing while it runs
 * when stderr is not a terminal; with --quiet (cli_quiet.h) nothing at all.
 * The end prints one summary line (not with --quiet). */
#ifndef CLI_PROGRESS_H
#define CLI_PROGRESS_H

#include <stdint.h>

typedef struct cli_progress {
	const char *what;       /* "compare 135_06" */
	const char *unit;       /* "frames" */
	long total;             /* 0 or less: not known (no bar, no time left) */
	long done;
	uint64_t t0, last;
	int tty;
} cli_progress;

void cli_progress_start(cli_progress *p, const char *what, const char *unit, long total);
void cli_progress_step(cli_progress *p, long done);
/* Clears the line and prints "WHAT: N UNIT in S s (R UNIT/s)EXTRA". */
void cli_progress_end(cli_progress *p, const char *extra);
double cli_progress_seconds(const cli_progress *p);
/* Clears the line only: the command prints its own summary. */
void cli_progress_clear(cli_progress *p);

#endif
