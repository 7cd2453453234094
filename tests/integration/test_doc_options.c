/* The option reference is --help, and everything else agrees with it:
 *  - each man page (build/man, made by help2man from --help) lists exactly
 *    the options of its command's --help, has an EXIT STATUS section, and
 *    each example of --help on a line of its own;
 *  - every option the documentation (README.md and the folder docs, *.md)
 *    gives a command (`skintool CMD ... --opt`, `skinplay ... --opt`) is one
 *    that command's --help lists; a flag is never given a value, an option
 *    that takes one is never shown without it, and a placeholder written
 *    in capitals (--weights W.csv) is the one --help shows (W.csv|mesh).
 * Skips where build/skintool does not run (a cross build). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test_paths.h"
#include "test_run.h"

#define MAX_CMDS 24
#define MAX_OPTS 96

typedef struct opt {
	char name[32];
	char meta[32];          /* "" for a flag */
	char short_name;
} opt;

typedef struct command {
	char name[32];          /* "skinplay", "skintool pack" */
	char page[40];          /* "skinplay", "skintool-pack" */
	opt opts[MAX_OPTS];
	int count;
	char *help;
} command;

static command cmds[MAX_CMDS];
static int cmd_count;
static int problems;

static void problem(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vprint_message(fmt, ap);
	va_end(ap);
	print_message("\n");
	problems++;
}

static char *help_of(const char *tool, const char *cmd)
{
	const char *out = test_scratch("help.txt");
	assert_int_equal(test_run("%s %s --help > %s", test_tool_path(tool), cmd, out), 0);
	char *text = test_read_file(out, NULL);
	assert_non_null(text);
	return text;
}

/* "  -o, --output=DIR   ..." and "      --fit   ...": the Options list. */
static void parse_options(command *c)
{
	for (const char *p = c->help; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL) {
		char s = 0;
		const char *q = p;
		if (!strncmp(q, "  -", 3) && q[3] != '-' && q[4] == ',') {
			s = q[3];
			q += 6;
		} else if (!strncmp(q, "      --", 8)) {
			q += 6;
		} else {
			continue;
		}
		if (strncmp(q, "--", 2) != 0 || c->count == MAX_OPTS)
			continue;
		opt *o = &c->opts[c->count++];
		memset(o, 0, sizeof *o);
		o->short_name = s;
		q += 2;
		size_t n = strcspn(q, "= \n");
		snprintf(o->name, sizeof o->name, "%.*s", (int)n, q);
		if (q[n] == '=')
			snprintf(o->meta, sizeof o->meta, "%.*s", (int)strcspn(q + n + 1, " \n"), q + n + 1);
	}
}

static void add_command(const char *tool, const char *cmd)
{
	command *c = &cmds[cmd_count++];
	snprintf(c->name, sizeof c->name, "%s%s%s", tool, cmd[0] ? " " : "", cmd);
	snprintf(c->page, sizeof c->page, "%s%s%s", tool, cmd[0] ? "-" : "", cmd);
	c->help = help_of(tool, cmd);
	parse_options(c);
	assert_true(c->count >= 3); /* --help, --quiet, --version at least */
}

static const opt *find_opt(const command *c, const char *name)
{
	for (int i = 0; i < c->count; i++)
		if (!strcmp(c->opts[i].name, name))
			return &c->opts[i];
	return NULL;
}

static const opt *find_short(const command *c, char s)
{
	for (int i = 0; i < c->count; i++)
		if (c->opts[i].short_name == s)
			return &c->opts[i];
	return NULL;
}

static int load_commands(void)
{
	if (access(test_tool_path("skintool"), X_OK) != 0 || test_run("%s --version > /dev/null 2>&1",
								       test_tool_path("skintool")) != 0)
		return 0;
	cmd_count = 0;
	add_command("skinplay", "");
	char *list = help_of("skintool", "");
	for (char *line = strtok(list, "\n"); line; line = strtok(NULL, "\n")) {
		char name[32];
		if (line[0] == ' ' && line[1] == ' ' && islower((unsigned char)line[2]) && sscanf(line, " %31s", name) == 1)
			add_command("skintool", name);
	}
	free(list);
	assert_int_equal(cmd_count, 15);
	return 1;
}

/* The man page's source with help2man's escapes undone: "\-" to "-",
 * font changes and "\," "\/" dropped. */
static char *plain_man(const char *page)
{
	char path[512];
	snprintf(path, sizeof path, "%s/man/%s.1", getenv("SKP_BUILD") ? getenv("SKP_BUILD") : "build", page);
	char *text = test_read_file(path, NULL);
	if (!text)
		return NULL;
	char *w = text;
	for (const char *r = text; *r; r++) {
		if (r[0] == '\\' && r[1] == '-') {
			*w++ = '-';
			r++;
		} else if (r[0] == '\\' && r[1] == 'f' && r[2]) {
			r += 2;
		} else if (r[0] == '\\' && (r[1] == ',' || r[1] == '/')) {
			r++;
		} else {
			*w++ = *r;
		}
	}
	*w = '\0';
	return text;
}

static void check_man_page(const command *c)
{
	char *man = plain_man(c->page);
	if (!man) {
		problem("%s.1: not made (make builds the man pages)", c->page);
		return;
	}
	int listed[MAX_OPTS] = { 0 };
	/* each option's tag line follows a .TP */
	for (const char *p = strstr(man, "\n.TP\n"); p; p = strstr(p + 1, "\n.TP\n")) {
		const char *tag = p + 5, *end = strchr(tag, '\n');
		for (const char *d = strstr(tag, "--"); d && d < end; d = strstr(d + 2, "--")) {
			char name[32];
			snprintf(name, sizeof name, "%.*s", (int)strspn(d + 2, "abcdefghijklmnopqrstuvwxyz0123456789-"), d + 2);
			const opt *o = find_opt(c, name);
			if (!o)
				problem("%s.1: lists --%s, which '%s --help' does not", c->page, name, c->name);
			else
				listed[o - c->opts] = 1;
		}
	}
	for (int i = 0; i < c->count; i++)
		if (!listed[i])
			problem("%s.1: does not list --%s of '%s --help'", c->page, c->opts[i].name, c->name);
	if (!strstr(man, "\n.SH \"EXIT STATUS\"\n"))
		problem("%s.1: no EXIT STATUS section", c->page);
	/* examples: each command line a paragraph of its own */
	const char *ex = strstr(c->help, "\nExamples:\n");
	int examples = 0;
	for (const char *p = ex ? strchr(ex + 1, '\n') + 1 : NULL; p && !strncmp(p, "  ", 2);
	     p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL) {
		if (strncmp(p, "      ", 6) != 0)
			continue;
		char want[512];
		snprintf(want, sizeof want, "\n.IP\n%.*s\n", (int)strcspn(p + 6, "\n"), p + 6);
		examples++;
		if (!strstr(man, want))
			problem("%s.1: the example '%.*s' is not a line of its own", c->page, (int)strcspn(p + 6, "\n"),
				p + 6);
	}
	if (!examples)
		problem("'%s --help' has no examples", c->name);
	else if (!strstr(man, "\n.SH EXAMPLES\n"))
		problem("%s.1: no EXAMPLES section", c->page);
	free(man);
}

static void test_man_pages_list_the_help(void **state)
{
	(void)state;
	if (!load_commands()) {
		print_message("build/skintool does not run here: skipped\n");
		skip();
	}
	problems = 0;
	for (int i = 0; i < cmd_count; i++)
		check_man_page(&cmds[i]);
	/* skintool's own page */
	char *man = plain_man("skintool");
	assert_non_null(man);
	for (int i = 1; i < cmd_count; i++) {
		char see[64];
		snprintf(see, sizeof see, ".BR %s (1)", cmds[i].page);
		if (!strstr(man, see))
			problem("skintool.1: SEE ALSO does not name %s(1)", cmds[i].page);
	}
	free(man);
	for (int i = 0; i < cmd_count; i++)
		free(cmds[i].help);
	if (problems)
		fail_msg("%d disagreements between the man pages and --help", problems);
}

/* A placeholder as --help writes one: capitals first (N, W.csv,
 * P.amc[:F], SECONDS...), no '$' or '/'. */
static int is_placeholder(const char *v)
{
	return isupper((unsigned char)v[0]) && !strpbrk(v, "$/") && (strlen(v) == 1 || !islower((unsigned char)v[1]) ||
								       strchr(v, '.'));
}

/* The doc's placeholder is --help's, maybe with a file name's extension
 * (OUT.bvh for OUT) or "..." for a repeat; FILE and DIR are any name; of
 * alternatives (DIR|F.mp4|F.webm) any one. */
static int same_placeholder(const char *doc, const char *help)
{
	const char *bar = strchr(help, '|');
	if (bar) {
		char first[32];
		snprintf(first, sizeof first, "%.*s", (int)(bar - help), help);
		if (same_placeholder(doc, first) || same_placeholder(doc, bar + 1))
			return 1;
	}
	size_t n = strlen(help), d = strlen(doc);
	if (!strcmp(help, "FILE") || !strcmp(help, "DIR"))
		return 1;
	if (d >= 3 && !strcmp(doc + d - 3, "..."))
		d -= 3;
	return !strncmp(doc, help, n) && (d == n || (d > n && doc[n] == '.' && !strchr(help, '.')));
}

/* One mention: the words after "skintool CMD" or "skinplay" on a line, up to
 * the end of the command (a backtick, a pipe into another program, ';',
 * "&&", a closing parenthesis). */
static const command *command_named(const char *text, size_t *len);

static void check_words(const char *file, int line, const command *c, const char *words)
{
	char buf[2048];
	snprintf(buf, sizeof buf, "%s", words);
	buf[strcspn(buf, "`;)")] = '\0';
	char *amp = strstr(buf, "&&");
	if (amp)
		*amp = '\0';
	char *tok[128], *save;
	int n = 0;
	for (char *t = strtok_r(buf, " \t", &save); t && n < 128; t = strtok_r(NULL, " \t", &save))
		tok[n++] = t;
	for (int i = 0; i < n; i++) {
		char *t = tok[i];
		while (*t == '[' || *t == '(')
			t++;
		if (!strcmp(t, "|") || !strcmp(t, ">") || !strcmp(t, "2>"))
			break; /* the output goes on to another program */
		if (!strcmp(t, "--") && !strcmp(c->name, "skintool view")) {
			/* what follows is skinplay's (skintool view plays with it) */
			size_t k;
			const command *play = command_named("skinplay", &k);
			if (!play)
				break;
			c = play;
			continue;
		}
		if (t[0] != '-' || t[1] == '\0' || isdigit((unsigned char)t[1]))
			continue;
		char name[64], value[256] = "";
		int has_eq = 0;
		const opt *o;
		if (t[1] == '-') {
			size_t k = strspn(t + 2, "abcdefghijklmnopqrstuvwxyz0123456789-");
			snprintf(name, sizeof name, "%.*s", (int)k, t + 2);
			if (!name[0])
				continue;
			has_eq = t[2 + k] == '=';
			if (has_eq)
				snprintf(value, sizeof value, "%s", t + 3 + k);
			o = find_opt(c, name);
		} else {
			if (strlen(t) != 2 || !isalpha((unsigned char)t[1]))
				continue;
			snprintf(name, sizeof name, "-%c", t[1]);
			o = find_short(c, t[1]);
		}
		if (!o) {
			problem("%s:%d: '%s' gets %s%s, which '%s --help' does not list", file, line, c->name,
				t[1] == '-' ? "--" : "", name, c->name);
			continue;
		}
		if (!has_eq && o->meta[0] && i + 1 < n)
			snprintf(value, sizeof value, "%s", tok[i + 1]);
		/* trailing ']' '|' ')' ',' '.' of the prose or synopsis */
		size_t vl = strlen(value);
		while (vl && strchr("],|).", value[vl - 1]) && !(vl >= 3 && !strcmp(value + vl - 3, "...")))
			value[--vl] = '\0';
		if (!o->meta[0] && has_eq)
			problem("%s:%d: '%s' gives --%s a value; it is a flag", file, line, c->name, o->name);
		else if (o->meta[0] && !value[0] && i + 1 >= n && !has_eq)
			; /* the option named alone in prose ("skinplay --image") */
		else if (o->meta[0] && is_placeholder(value) && !same_placeholder(value, o->meta))
			problem("%s:%d: '%s' shows --%s %s; --help says --%s=%s", file, line, c->name, o->name, value,
				o->name, o->meta);
	}
}

static const command *command_named(const char *text, size_t *len)
{
	const command *best = NULL;
	for (int i = 0; i < cmd_count; i++) {
		size_t n = strlen(cmds[i].name);
		if (!strncmp(text, cmds[i].name, n) && (text[n] == ' ' || text[n] == '\0') && (!best || n > *len)) {
			best = &cmds[i];
			*len = n;
		}
	}
	return best;
}

/* "journalctl -u skinplay", "systemctl enable --now skinplay": the name of
 * a unit, user or package, not the program run. */
static int another_programs(const char *line, const char *at)
{
	const char *e = at;
	while (e > line && e[-1] == ' ')
		e--;
	const char *b = e;
	while (b > line && b[-1] != ' ' && b[-1] != '`' && b[-1] != '(')
		b--;
	if (b == e)
		return 0;
	static const char *const verbs[] = { "enable", "disable", "reload", "restart", "start", "stop", "status",
					     "purge", "remove", "install", "user" };
	if (*b == '-')
		return 1;
	for (size_t i = 0; i < sizeof verbs / sizeof verbs[0]; i++)
		if ((size_t)(e - b) == strlen(verbs[i]) && !strncmp(b, verbs[i], (size_t)(e - b)))
			return 1;
	return 0;
}

static int check_doc(const char *path)
{
	char *text = test_read_file(path, NULL);
	assert_non_null(text);
	int mentions = 0, line = 0;
	char joined[4096];
	for (char *p = text; p && *p;) {
		/* a code line ending in a backslash goes on */
		size_t used = 0;
		int first = ++line;
		for (;;) {
			char *e = strchr(p, '\n');
			size_t len = e ? (size_t)(e - p) : strlen(p);
			if (used + len + 1 >= sizeof joined)
				len = sizeof joined - used - 2;
			memcpy(joined + used, p, len);
			used += len;
			joined[used] = '\0';
			p = e ? e + 1 : NULL;
			if (used && joined[used - 1] == '\\' && p) {
				joined[--used] = ' ';
				line++;
				continue;
			}
			break;
		}
		for (const char *q = joined; (q = strstr(q, "skin")); q++) {
			if (q > joined && (isalnum((unsigned char)q[-1]) || q[-1] == '_' || q[-1] == '/' || q[-1] == '-' ||
					   q[-1] == '.'))
				continue;
			size_t n = 0;
			const command *c = command_named(q, &n);
			/* "skintool --help" lists commands; "skintool COMMAND": a placeholder */
			if (!c || (!strcmp(c->name, "skintool") && q[n] == ' ' && isupper((unsigned char)q[n + 1])))
				continue;
			if (!strcmp(c->name, "skintool") || another_programs(joined, q))
				continue;
			mentions++;
			check_words(path, first, c, q + n);
		}
	}
	free(text);
	return mentions;
}

static void test_docs_give_commands_their_options(void **state)
{
	(void)state;
	if (!load_commands()) {
		print_message("build/skintool does not run here: skipped\n");
		skip();
	}
	const char *list = test_scratch("docs.txt");
	assert_int_equal(test_run("{ ls *.md; find app board platform tests assets -name '*.md'; } | sort > %s", list), 0);
	char *files = test_read_file(list, NULL);
	assert_non_null(files);
	problems = 0;
	int docs = 0, mentions = 0;
	char *save;
	for (char *f = strtok_r(files, "\n", &save); f; f = strtok_r(NULL, "\n", &save)) {
		mentions += check_doc(f);
		docs++;
	}
	free(files);
	for (int i = 0; i < cmd_count; i++)
		free(cmds[i].help);
	printf("docs: %d files, %d command lines checked against --help\n", docs, mentions);
	assert_true(docs >= 2 && mentions >= 20);
	if (problems)
		fail_msg("%d options in the docs disagree with --help", problems);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_man_pages_list_the_help),
		cmocka_unit_test(test_docs_give_commands_their_options),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
