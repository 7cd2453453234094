/* A text output (CSV, OBJ, BVH, ASF, AMC) written through stdio into an
 * atomic file (atomic_file.h): the old file stays whole until the new one
 * is complete, and a failed or interrupted write leaves nothing behind. */
#ifndef CLI_TEXT_OUT_H
#define CLI_TEXT_OUT_H

#include <stdio.h>

#include "atomic_file.h"

typedef struct cli_text_out {
	atomic_file af;
	FILE *f;                   /* write here */
} cli_text_out;

/* Returns 0, or -1 after reporting "PATH: cannot create: why" (or that
 * PATH is one of the command's inputs: cli_inputs.h). */
int cli_text_out_open(cli_text_out *o, const char *path);

/* Flushes, checks for write errors and replaces the target. Returns 0, or
 * -1 after reporting "PATH: cannot write: why" (nothing is left behind). */
int cli_text_out_commit(cli_text_out *o);

/* Drops the new contents; the target is untouched. */
void cli_text_out_abort(cli_text_out *o);

#endif
