/* ISO 8601 UTC times by hand: the calendar's arithmetic is a few lines,
 * and timegm() and strptime() are neither C11 nor on a microcontroller. */
#include "utc_time.h"

#include <stddef.h>

/* n digits at s as a number; -1 when one is not a digit. */
static long digits(const char *s, int n)
{
	long v = 0;
	for (int i = 0; i < n; i++) {
		if (s[i] < '0' || s[i] > '9')
			return -1;
		v = v * 10 + (s[i] - '0');
	}
	return v;
}

/* Days from 1970-01-01 to y-m-d (the proleptic Gregorian calendar). */
static int64_t days_from_civil(long y, long m, long d)
{
	y -= m <= 2;
	long era = (y >= 0 ? y : y - 399) / 400, yoe = y - era * 400;
	long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1, doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
	return (int64_t)era * 146097 + doe - 719468;
}

static int leap(long y)
{
	return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

/* The fraction of a second after the point, in ns; *end past it. */
static long fraction_ns(const char **p)
{
	long ns = 0, scale = 100000000;
	if (**p != '.')
		return 0;
	for ((*p)++; **p >= '0' && **p <= '9'; (*p)++, scale /= 10)
		ns += (**p - '0') * scale;
	return ns;
}

int utc_time_parse(const char *text, int64_t *ns)
{
	static const int mdays[] = { 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31 };
	const char *s = text;
	/* YYYY-MM-DDTHH:MM:SS and a zone at least: nothing read past the end */
	size_t n = 0;
	while (s && n < 20 && s[n])
		n++;
	if (n < 20)
		return -1;
	long y = digits(s, 4), mo = digits(s + 5, 2), d = digits(s + 8, 2);
	if (y < 1900 || y > 2200 || s[4] != '-' || mo < 1 || mo > 12 || s[7] != '-' || d < 1 ||
	    d > mdays[mo - 1] + (mo == 2 && leap(y)) || (s[10] != 'T' && s[10] != 't' && s[10] != ' '))
		return -1;
	long h = digits(s + 11, 2), mi = digits(s + 14, 2), se = digits(s + 17, 2);
	if (h < 0 || h > 23 || s[13] != ':' || mi < 0 || mi > 59 || s[16] != ':' || se < 0 || se > 59)
		return -1;
	const char *p = s + 19;
	long frac = fraction_ns(&p);
	if (!((p[0] == 'Z' || p[0] == 'z') && p[1] == '\0') && !(p[0] == '+' && p[1] == '0' && p[2] == '0' &&
								     p[3] == ':' && p[4] == '0' && p[5] == '0' && p[6] == '\0'))
		return -1;
	int64_t secs = days_from_civil(y, mo, d) * 86400 + h * 3600 + mi * 60 + se;
	*ns = secs * 1000000000 + frac;
	return 0;
}
