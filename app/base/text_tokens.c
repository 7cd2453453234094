#include "text_tokens.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>

static int is_sep(char c)
{
	return c == ' ' || c == '\t' || c == ',' || c == '(' || c == ')' ||
	       c == '\v' || c == '\f';
}

int tok_split(char *line, char **toks, int max)
{
	int n = 0;
	char *p = line;

	for (;;) {
		while (*p && is_sep(*p))
			p++;
		if (*p == '\0' || *p == '#')
			break;
		if (n == max)
			return -1;
		toks[n++] = p;
		while (*p && !is_sep(*p))
			p++;
		if (*p == '\0')
			break;
		*p++ = '\0';
	}
	return n;
}

static char lower(char c)
{
	return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c;
}

int tok_ieq(const char *a, const char *b)
{
	while (*a && lower(*a) == lower(*b)) {
		a++;
		b++;
	}
	return *a == '\0' && *b == '\0';
}

/* 10^e for 0 <= e <= 22 is exact in double; larger powers are built by
 * repeated multiplication (a rounding per step is fine for mocap data). */
static double pow10_exact(int e)
{
	static const double p[] = { 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8,
		1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19,
		1e20, 1e21, 1e22 };
	double r = 1.0;
	while (e > 22) {
		r *= 1e22;
		e -= 22;
	}
	return r * p[e];
}

static double scale10(uint64_t mant, int exp10)
{
	if (mant == 0)
		return 0.0;
	if (exp10 > 330)
		return INFINITY;
	if (exp10 < -350)
		return 0.0;
	if (exp10 >= 0)
		return (double)mant * pow10_exact(exp10);
	/* divide in two steps so that 1e-330 style values do not underflow
	 * the divisor to infinity */
	if (exp10 < -300)
		return ((double)mant / pow10_exact(300)) / pow10_exact(-exp10 - 300);
	return (double)mant / pow10_exact(-exp10);
}

int tok_parse_double(const char *s, double *out)
{
	int neg = 0;
	if (*s == '+' || *s == '-')
		neg = (*s++ == '-');
	if (tok_ieq(s, "inf") || tok_ieq(s, "infinity")) {
		*out = neg ? -INFINITY : INFINITY;
		return 0;
	}
	uint64_t mant = 0;
	int exp10 = 0, digits = 0;
	for (; *s >= '0' && *s <= '9'; s++, digits++) {
		if (mant < UINT64_C(1000000000000000000)) {
			mant = mant * 10 + (uint64_t)(*s - '0');
		} else {
			exp10++;
		}
	}
	if (*s == '.') {
		for (s++; *s >= '0' && *s <= '9'; s++, digits++) {
			if (mant < UINT64_C(1000000000000000000)) {
				mant = mant * 10 + (uint64_t)(*s - '0');
				exp10--;
			}
		}
	}
	if (digits == 0)
		return -1;
	if (*s == 'e' || *s == 'E') {
		s++;
		int eneg = 0;
		if (*s == '+' || *s == '-')
			eneg = (*s++ == '-');
		if (!(*s >= '0' && *s <= '9'))
			return -1;
		long e = 0;
		for (; *s >= '0' && *s <= '9'; s++)
			if (e < 100000)
				e = e * 10 + (*s - '0');
		exp10 += (int)(eneg ? -e : e);
	}
	if (*s != '\0')
		return -1;
	double v = scale10(mant, exp10);
	*out = neg ? -v : v;
	return 0;
}

int tok_parse_long(const char *s, long *out)
{
	int neg = 0;
	if (*s == '+' || *s == '-')
		neg = (*s++ == '-');
	if (!(*s >= '0' && *s <= '9'))
		return -1;
	long v = 0;
	for (; *s >= '0' && *s <= '9'; s++) {
		if (v > (LONG_MAX - 9) / 10)
			return -1;
		v = v * 10 + (*s - '0');
	}
	if (*s != '\0')
		return -1;
	*out = neg ? -v : v;
	return 0;
}
