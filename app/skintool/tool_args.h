/* What skintool's commands share on their command lines (cli_opts.h): the
 * same spelling for the same file everywhere (--skeleton, --motion,
 * --mesh, -o/--output, besides the files named in order) and the binding
 * options (cli_bind_args.h). A command's own arguments struct starts with
 * a tool_common. */
#ifndef TOOL_ARGS_H
#define TOOL_ARGS_H

#include "cli_bind_args.h"
#include "cli_opts.h"

enum { TOOL_OPT_SKELETON = 400, TOOL_OPT_MOTION, TOOL_OPT_MESH, TOOL_OPT_OUTPUT };

typedef struct tool_common {
	const char *prog;               /* "skintool bind" */
	const char *asf, *amc, *mesh, *out;
	bind_args bind;
} tool_common;

extern const cli_opt tool_opt_skeleton[], tool_opt_motion[], tool_opt_mesh[], tool_opt_output[];

void tool_common_init(tool_common *c, const char *prog);

/* Takes one of the shared options: 0, -1 after reporting, 1 when id is
 * not one of them (the command's own). */
int tool_common_take(tool_common *c, int id, const char *value);

/* cli_command.positional for commands whose arguments struct starts with
 * a tool_common: the files in the order SKELETON MESH, or SKELETON MOTION
 * MESH. */
int tool_files_skel_mesh(void *ctx, const char *arg);
int tool_files_skel_motion_mesh(void *ctx, const char *arg);

/* A command whose only argument is one file (info, repair): parses argv
 * with c (no options of its own, take and positional unused) into *path.
 * 0, 1 (--help/--version answered) or -1 (reported). */
int tool_one_file(const cli_command *c, int argc, char **argv, const char **path);

/* "PROG: give ...; Try 'PROG --help'": 1, the exit status. */
int tool_missing(const tool_common *c, const char *what);

#endif
