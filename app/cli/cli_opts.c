#include "cli_opts.h"

#include <getopt.h>
#include <string.h>

#include "cli_error.h"
#include "cli_inputs.h"
#include "cli_program.h"
#include "cli_quiet.h"
#include "cli_version.h"

#define MAX_OPTS 96
#define ID_HELP (-1000)
#define ID_VERSION (-1001)
#define ID_QUIET (-1002)

static const cli_opt common[] = {
	{ "help", 'h', NULL, ID_HELP, "show this help and exit" },
	{ "quiet", 'q', NULL, ID_QUIET, "only errors and warnings on stderr: no notes, progress or summary lines" },
	{ "version", 0, NULL, ID_VERSION, "show the version, revision, board and backends, and exit" },
	{ NULL, 0, NULL, 0, NULL },
};

typedef struct opt_index {
	struct option longopts[MAX_OPTS + 1];
	const cli_opt *by_index[MAX_OPTS];
	char shorts[2 * MAX_OPTS + 4];
	int count;
} opt_index;

static void add_table(opt_index *x, const cli_opt *t)
{
	for (; t && t->name && x->count < MAX_OPTS; t++) {
		struct option *o = &x->longopts[x->count];
		o->name = t->name;
		o->has_arg = t->arg ? required_argument : no_argument;
		o->flag = NULL;
		o->val = 0;
		x->by_index[x->count++] = t;
		if (t->short_name) {
			size_t n = strlen(x->shorts);
			x->shorts[n] = t->short_name;
			x->shorts[n + 1] = t->arg ? ':' : '\0';
			x->shorts[n + 2] = '\0';
		}
	}
}

static void build(const cli_command *c, opt_index *x)
{
	memset(x, 0, sizeof *x);
	/* leading ':' : a missing value is told apart from an unknown option */
	strcpy(x->shorts, ":");
	for (int k = 0; k < CLI_MAX_TABLES; k++)
		add_table(x, c->opts[k]);
	add_table(x, common);
}

static const cli_opt *by_short(const opt_index *x, int ch)
{
	for (int i = 0; i < x->count; i++)
		if (x->by_index[i]->short_name == ch)
			return x->by_index[i];
	return NULL;
}

static int usage_error(const cli_command *c, const char *what, const char *arg)
{
	fprintf(stderr, "%s: %s '%s'\nTry '%s --help' for more information.\n", c->prog, what, arg, c->prog);
	return -1;
}

/* getopt_long's '?' and ':' cases: which option, said plainly. */
static int bad_option(const cli_command *c, int ch, char **argv)
{
	const char *arg = argv[optind - 1];
	char shortopt[3] = { '-', (char)optopt, 0 };
	if (ch == ':')
		return usage_error(c, "option needs a value:", optopt ? shortopt : arg);
	return usage_error(c, "unknown option", optopt ? shortopt : arg);
}

static int answer(const cli_command *c, const cli_opt *o)
{
	char prog[32];
	size_t n = strcspn(c->prog, " ");
	snprintf(prog, sizeof prog, "%.*s", (int)n, c->prog);
	if (o->id == ID_HELP)
		cli_help(c, stdout);
	else
		cli_print_version(prog);
	return 1;
}

/* Options whose value names a file written: every other value and every
 * file is an input (cli_inputs.h). */
static int writes(const cli_opt *o)
{
	return !strcmp(o->name, "output") || !strcmp(o->name, "out") || !strcmp(o->name, "sheet");
}

int cli_parse(const cli_command *c, void *ctx, int argc, char **argv, int first)
{
	static opt_index x;
	static char *args[512];
	if (argc - first + 1 > (int)(sizeof args / sizeof args[0]))
		return usage_error(c, "too many arguments, from", argv[first + 510]);
	/* getopt sees argv[0] as the program: the command's own name */
	int n = 0;
	args[n++] = (char *)c->prog;
	for (int i = first; i < argc; i++)
		args[n++] = argv[i];
	args[n] = NULL;
	cli_set_program(c->prog);
	build(c, &x);
	cli_inputs_reset();
	optind = 0;     /* GNU: start afresh (a second parse in one process) */
	opterr = 0;
	int ch, li, out_count = 0;
	const char *outs[8];
	while ((ch = getopt_long(n, args, x.shorts, x.longopts, &li)) != -1) {
		const cli_opt *o = ch == 0 ? x.by_index[li] : by_short(&x, ch);
		if (ch == '?' || ch == ':' || !o)
			return bad_option(c, ch, args);
		if (o->id == ID_HELP || o->id == ID_VERSION)
			return answer(c, o);
		if (o->id == ID_QUIET) {
			cli_set_quiet(1);
			continue;
		}
		if (o->arg && !writes(o))
			cli_inputs_add(optarg);
		else if (o->arg && out_count < 8)
			outs[out_count++] = optarg;
		if (c->take(ctx, o->id, o->arg ? optarg : NULL) < 0)
			return -1;
	}
	for (int i = optind; i < n; i++) {
		if (!c->positional)
			return usage_error(c, "unexpected argument", args[i]);
		cli_inputs_add(args[i]);
		if (c->positional(ctx, args[i]) < 0)
			return -1;
	}
	/* before any work: an output named like an input is refused now (the
	 * writers check again, for the names they make and the inputs found
	 * on the way) */
	for (int i = 0; i < out_count; i++)
		if (cli_output_check(outs[i]) < 0)
			return -1;
	return 0;
}

/* GNU layout: "  -o, --output=FILE" or "      --frame=N", help from column 32. */
static void help_table(const cli_opt *t, FILE *f)
{
	for (; t && t->name; t++) {
		char head[96];
		int k;
		if (t->short_name)
			k = snprintf(head, sizeof head, "  -%c, --%s%s%s", t->short_name, t->name, t->arg ? "=" : "",
				     t->arg ? t->arg : "");
		else
			k = snprintf(head, sizeof head, "      --%s%s%s", t->name, t->arg ? "=" : "", t->arg ? t->arg : "");
		fprintf(f, "%s%*s%s\n", head, k < 31 ? 32 - k : 2, "", t->help);
	}
}

void cli_help_exit(const char *exit2, FILE *f)
{
	fprintf(f, "Exit status:\n  0  done\n"
		"  1  bad input, bad usage or a failure (the message names the file, line, block or option)\n");
	if (exit2)
		fprintf(f, "  2  %s\n", exit2);
}

/* Each example's line indented under what it does: help2man keeps them
 * as separate paragraphs. */
static void help_examples(const cli_example *e, FILE *f)
{
	if (!e || !e->what)
		return;
	fprintf(f, "\nExamples:\n");
	for (; e->what; e++)
		fprintf(f, "  %s:\n      %s\n", e->what, e->line);
}

void cli_help(const cli_command *c, FILE *f)
{
	fprintf(f, "Usage: %s %s\n", c->prog, c->usage);
	if (c->about)
		fprintf(f, "%s\n", c->about);
	fprintf(f, "\nOptions:\n");
	for (int k = 0; k < CLI_MAX_TABLES; k++)
		help_table(c->opts[k], f);
	help_table(common, f);
	if (c->more)
		fprintf(f, "\n%s", c->more);
	fprintf(f, "\n");
	cli_help_exit(c->exit2, f);
	help_examples(c->examples, f);
}

int cli_missing(const char *prog, const char *what)
{
	fprintf(stderr, "%s: give %s\nTry '%s --help' for more information.\n", prog, what, prog);
	return -1;
}

int cli_bad_choice(const char *prog, const char *opt, const char *value, const char *const *choices, int n)
{
	fprintf(stderr, "%s: unknown value '%s' for --%s; one of:", prog, cli_shown(value), opt);
	for (int i = 0; i < n; i++)
		fprintf(stderr, "%s %s", i ? "," : "", choices[i]);
	fprintf(stderr, "\n");
	return -1;
}

int cli_choice(const char *prog, const char *opt, const char *value, const char *const *choices, int n)
{
	for (int i = 0; value && i < n; i++)
		if (strcmp(value, choices[i]) == 0)
			return i;
	return cli_bad_choice(prog, opt, value, choices, n);
}
