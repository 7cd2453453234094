/* Line splitting, tokens, numbers and the message formatter. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "skp_format.h"
#include "text_lines.h"
#include "text_tokens.h"

/* A reader handing out at most `step` bytes per call, to cross every
 * chunk boundary the real reader could meet. */
typedef struct slow_src {
	const char *data;
	size_t size, pos, step;
	int fail_at;          /* call number that fails, or -1 */
	int calls;
} slow_src;

static long slow_read(void *ctx, void *buf, size_t len)
{
	slow_src *s = ctx;
	if (s->calls++ == s->fail_at)
		return -1;
	size_t n = s->size - s->pos;
	if (n > s->step) n = s->step;
	if (n > len) n = len;
	memcpy(buf, s->data + s->pos, n);
	s->pos += n;
	return (long)n;
}

static int collect(const char *text, size_t step, char out[][64], int max, skp_error *err)
{
	static text_lines tl;
	slow_src src = { text, strlen(text), 0, step, -1, 0 };
	skp_reader rd = { slow_read, &src };
	text_lines_init(&tl, rd);
	char *line;
	int n = 0, r;
	while ((r = text_lines_next(&tl, &line, NULL, err)) > 0 && n < max)
		strcpy(out[n++], line);
	return r < 0 ? r : n;
}

static void test_line_ends_all_styles(void **state)
{
	(void)state;
	const char *text = "a\nb\r\nc\rd\r\r\ne";
	for (size_t step = 1; step <= 8; step++) {
		char lines[8][64];
		skp_error err;
		int n = collect(text, step, lines, 8, &err);
		assert_int_equal(n, 6);
		assert_string_equal(lines[0], "a");
		assert_string_equal(lines[1], "b");
		assert_string_equal(lines[2], "c");
		assert_string_equal(lines[3], "d");
		assert_string_equal(lines[4], "");
		assert_string_equal(lines[5], "e");
	}
}

static void test_latin1_bytes_pass_through(void **state)
{
	(void)state;
	char lines[2][64];
	skp_error err;
	assert_int_equal(collect("f\xfcr Bonn\n", 3, lines, 2, &err), 1);
	assert_string_equal(lines[0], "f\xfcr Bonn");
}

static void test_line_too_long_names_limit(void **state)
{
	(void)state;
	static char big[SKP_MAX_LINE + 64];
	memset(big, 'x', sizeof big - 1);
	big[0] = 'o'; big[1] = 'k'; big[2] = '\n';
	char lines[2][64];
	skp_error err;
	int r = collect(big, 4096, lines, 2, &err);
	assert_int_equal(r, -SKP_ERR_LIMIT);
	assert_int_equal(err.line, 2);
	assert_non_null(strstr(err.msg, "SKP_MAX_LINE"));
}

static void test_nul_byte_is_an_error(void **state)
{
	(void)state;
	static text_lines tl;
	skp_mem_source src;
	text_lines_init(&tl, skp_mem_reader(&src, "ok\nb\0d\n", 7));
	char *line;
	skp_error err;
	assert_int_equal(text_lines_next(&tl, &line, NULL, &err), 1);
	assert_int_equal(text_lines_next(&tl, &line, NULL, &err), -SKP_ERR_SYNTAX);
	assert_int_equal(err.line, 2);
}

static void test_read_error_reported(void **state)
{
	(void)state;
	static text_lines tl;
	slow_src src = { "abc\ndef\n", 8, 0, 4, 1, 0 };
	skp_reader rd = { slow_read, &src };
	text_lines_init(&tl, rd);
	char *line;
	skp_error err;
	assert_int_equal(text_lines_next(&tl, &line, NULL, &err), 1);
	assert_int_equal(text_lines_next(&tl, &line, NULL, &err), -SKP_ERR_IO);
}

static void test_tokens_separators_and_comments(void **state)
{
	(void)state;
	char line[] = "  limits (-inf, 12.5)\t(1e-011 inf) # comment (x)";
	char *t[8];
	int n = tok_split(line, t, 8);
	assert_int_equal(n, 5);
	assert_string_equal(t[0], "limits");
	assert_string_equal(t[1], "-inf");
	assert_string_equal(t[2], "12.5");
	assert_string_equal(t[3], "1e-011");
	assert_string_equal(t[4], "inf");
	char many[] = "a b c d";
	assert_int_equal(tok_split(many, t, 3), -1);
	char empty[] = "   # all comment";
	assert_int_equal(tok_split(empty, t, 3), 0);
}

static void test_numbers(void **state)
{
	(void)state;
	static const struct { const char *s; double v; } ok[] = {
		{ "0", 0 }, { "-4.4891e-011", -4.4891e-11 }, { "1.43544e-026", 1.43544e-26 },
		{ "987.25", 987.25 }, { "+.5", 0.5 }, { "5.", 5.0 }, { "-1251.0", -1251.0 },
		{ "1E3", 1000 }, { "123456789012345678901234", 1.2345678901234568e23 },
		{ "0.000000000000000000000000000001", 1e-30 }, { "2.5e+2", 250 },
	};
	for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++) {
		double v;
		assert_int_equal(tok_parse_double(ok[i].s, &v), 0);
		assert_true(fabs(v - ok[i].v) <= 1e-15 * fabs(ok[i].v));
	}
	double v;
	assert_int_equal(tok_parse_double("inf", &v), 0);
	assert_true(isinf(v) && v > 0);
	assert_int_equal(tok_parse_double("-INF", &v), 0);
	assert_true(isinf(v) && v < 0);
	assert_int_equal(tok_parse_double("1e999", &v), 0);
	assert_true(isinf(v));
	static const char *bad[] = { "", "-", ".", "e5", "1e", "1e+", "1.2.3", "12a", "0x10", "nan", "--1" };
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
		assert_int_equal(tok_parse_double(bad[i], &v), -1);
	long l;
	assert_int_equal(tok_parse_long("-42", &l), 0);
	assert_int_equal(l, -42);
	assert_int_equal(tok_parse_long("4.2", &l), -1);
	assert_int_equal(tok_parse_long("99999999999999999999999", &l), -1);
	assert_true(tok_ieq("ORDER", "order"));
	assert_false(tok_ieq("orde", "order"));
}

static void test_format(void **state)
{
	(void)state;
	char buf[64];
	skp_format(buf, sizeof buf, "%s:%d:%ld:%u:%c:%%", "a", -5, 1234567890L, 7u, 'z');
	assert_string_equal(buf, "a:-5:1234567890:7:z:%");
	skp_format(buf, sizeof buf, "%g %g %g %g", 0.5, -12.25, 1e-7, 3.0);
	assert_string_equal(buf, "0.5 -12.25 1.00000e-7 3");
	char tiny[5];
	assert_int_equal(skp_format(tiny, sizeof tiny, "%s", "abcdefgh"), 4);
	assert_string_equal(tiny, "abcd");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_line_ends_all_styles),
		cmocka_unit_test(test_latin1_bytes_pass_through),
		cmocka_unit_test(test_line_too_long_names_limit),
		cmocka_unit_test(test_nul_byte_is_an_error),
		cmocka_unit_test(test_read_error_reported),
		cmocka_unit_test(test_tokens_separators_and_comments),
		cmocka_unit_test(test_numbers),
		cmocka_unit_test(test_format),
	};
	return cmocka_run_group_tests_name("text", tests, NULL, NULL);
}
