/* Command lines the GNU way, for both programs: getopt_long underneath, so
 * --opt=value and --opt value both work, options and files mix in any
 * order, `--` ends the options; every command answers --help (its usage,
 * what it does and each option, on stdout, exit 0) and --version. A
 * command is a table: its options (with a one-line help each), a handler
 * for an option's value and one for the files, its exit statuses and
 * examples. help2man turns the same text into the man pages
 * (platform/debian/man_pages.sh), so the layout below is the one help2man
 * reads: "Options:", "Exit status:" and "Examples:" headings. */
#ifndef CLI_OPTS_H
#define CLI_OPTS_H

#include <stdio.h>

#include "cli_program.h"

typedef struct cli_opt {
	const char *name;       /* long name without the dashes; NULL ends a table */
	char short_name;        /* 0: none */
	const char *arg;        /* the value's name in the help ("FILE"), NULL: a flag */
	int id;                 /* handed to take() */
	const char *help;       /* one line */
} cli_opt;

#define CLI_MAX_TABLES 8

/* One example of --help (help2man puts them in the man page's EXAMPLES). */
typedef struct cli_example {
	const char *what;       /* "the demo on the screen"; NULL ends a list */
	const char *line;       /* the command line */
} cli_example;

typedef struct cli_command {
	const char *prog;       /* "skintool bind": in messages and the help */
	const char *usage;      /* after "usage: PROG " (several lines may follow "\n") */
	const char *about;      /* what the command does, a paragraph */
	const cli_opt *opts[CLI_MAX_TABLES]; /* tables; unused ones NULL */
	/* an option with its value (NULL for a flag): 0, or -1 after reporting */
	int (*take)(void *ctx, int id, const char *value);
	/* a file or other word that is not an option: 0, or -1 after reporting */
	int (*positional)(void *ctx, const char *arg);
	const char *more;       /* a paragraph after the options, or NULL */
	const char *exit2;      /* what exit status 2 means, or NULL: the command has none */
	const cli_example *examples; /* ended by a NULL what; NULL: none */
} cli_command;

/* Parses argv[first..argc). Returns 0, 1 when --help or --version was
 * answered (exit 0), or -1 after reporting a usage error on stderr with a
 * hint to --help (exit 1). */
int cli_parse(const cli_command *c, void *ctx, int argc, char **argv, int first);

/* The --help text. */
void cli_help(const cli_command *c, FILE *f);

/* "PROG: give WHAT" and the hint to --help, on stderr: -1 (a command's
 * files or required options missing). */
int cli_missing(const char *prog, const char *what);

/* "PROG: unknown value 'V' for --OPT; one of: a, b, c": -1. */
int cli_bad_choice(const char *prog, const char *opt, const char *value, const char *const *choices, int n);

/* Index of value among choices, or cli_bad_choice's -1. */
int cli_choice(const char *prog, const char *opt, const char *value, const char *const *choices, int n);

/* The "Exit status:" list of --help: 0 and 1 as every command has them,
 * then 2 when exit2 says what it means (help2man: the EXIT STATUS section). */
void cli_help_exit(const char *exit2, FILE *f);

#endif
