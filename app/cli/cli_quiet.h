/* What a program says besides its product and its errors: notes on
 * stderr (each choice made for the user's files, the display opened, a
 * line a second), progress, and summary lines after a file is written.
 * -q/--quiet (cli_opts.h; skintool also before the command) silences them
 * all; errors and warnings (damaged blocks, a file cut short, a fallback
 * the user did not ask for) and output a command was asked for (fk's
 * rows, info, --report) still print. */
#ifndef CLI_QUIET_H
#define CLI_QUIET_H

#include <stdio.h>

void cli_set_quiet(int quiet);
int cli_quiet(void);

/* stderr, or with --quiet a stream that discards what is written. */
FILE *cli_note(void);

/* stdout for the line a command prints after writing its file (pack,
 * convert, mannequin, repair), or with --quiet the discarding stream. */
FILE *cli_summary(void);

#endif
