#include "skp_format.h"

#include <math.h>

typedef struct out {
	char *buf;
	size_t cap, len;
	int escape;          /* %s: control characters as \xNN */
} out;

static void put(out *o, char c)
{
	if (o->len + 1 < o->cap)
		o->buf[o->len] = c;
	o->len++;
}

static void put_str(out *o, const char *s)
{
	static const char hex[] = "0123456789abcdef";
	if (!s)
		s = "(null)";
	for (; *s; s++) {
		unsigned char c = (unsigned char)*s;
		if (o->escape && (c < 0x20 || c == 0x7f)) {
			put(o, '\\');
			put(o, 'x');
			put(o, hex[c >> 4]);
			put(o, hex[c & 15]);
		} else {
			put(o, *s);
		}
	}
}

static void put_unsigned(out *o, unsigned long v)
{
	char tmp[24];
	int n = 0;

	do {
		tmp[n++] = (char)('0' + v % 10);
		v /= 10;
	} while (v);
	while (n)
		put(o, tmp[--n]);
}

static void put_signed(out *o, long v)
{
	if (v < 0) {
		put(o, '-');
		put_unsigned(o, 0ul - (unsigned long)v);
	} else {
		put_unsigned(o, (unsigned long)v);
	}
}

/* Six significant digits, plain notation for moderate magnitudes and
 * scientific otherwise: enough for error messages, not for data output. */
static void put_double(out *o, double v)
{
	if (isnan(v)) {
		put_str(o, "nan");
		return;
	}
	if (v < 0) {
		put(o, '-');
		v = -v;
	}
	if (isinf(v)) {
		put_str(o, "inf");
		return;
	}
	int exp10 = 0;
	if (v != 0.0) {
		exp10 = (int)floor(log10(v));
		if (exp10 < -4 || exp10 > 9) {
			double m = v / pow(10.0, exp10);
			long digits = lround(m * 1e5);
			if (digits >= 1000000) {
				digits /= 10;
				exp10++;
			}
			put_unsigned(o, (unsigned long)(digits / 100000));
			put(o, '.');
			char frac[6];
			for (int i = 4; i >= 0; i--) {
				frac[i] = (char)('0' + digits % 10);
				digits /= 10;
			}
			for (int i = 0; i < 5; i++)
				put(o, frac[i]);
			put(o, 'e');
			put_signed(o, exp10);
			return;
		}
	}
	int decimals = 5 - exp10;
	if (decimals < 0)
		decimals = 0;
	double scale = pow(10.0, decimals);
	unsigned long whole = (unsigned long)floor(v);
	unsigned long frac = (unsigned long)llround((v - (double)whole) * scale);
	if ((double)frac >= scale) {
		whole++;
		frac = 0;
	}
	put_unsigned(o, whole);
	if (decimals == 0 || frac == 0)
		return;
	char digits[16];
	for (int i = decimals - 1; i >= 0; i--) {
		digits[i] = (char)('0' + frac % 10);
		frac /= 10;
	}
	int last = decimals - 1;
	while (last > 0 && digits[last] == '0')
		last--;
	put(o, '.');
	for (int i = 0; i <= last; i++)
		put(o, digits[i]);
}

static size_t format(char *buf, size_t cap, int escape, const char *fmt, va_list ap)
{
	out o = { buf, cap, 0, escape };

	for (const char *p = fmt; *p; p++) {
		if (*p != '%') {
			put(&o, *p);
			continue;
		}
		p++;
		int is_long = 0;
		if (*p == 'l') {
			is_long = 1;
			p++;
		}
		switch (*p) {
		case 's': put_str(&o, va_arg(ap, const char *)); break;
		case 'c': put(&o, (char)va_arg(ap, int)); break;
		case 'd': put_signed(&o, is_long ? va_arg(ap, long) : va_arg(ap, int)); break;
		case 'u': put_unsigned(&o, is_long ? va_arg(ap, unsigned long) : va_arg(ap, unsigned)); break;
		case 'g': put_double(&o, va_arg(ap, double)); break;
		case '%': put(&o, '%'); break;
		case '\0': p--; break;
		default: put(&o, '%'); put(&o, *p); break;
		}
	}
	if (cap)
		buf[o.len < cap ? o.len : cap - 1] = '\0';
	return o.len < cap ? o.len : (cap ? cap - 1 : 0);
}

size_t skp_vformat(char *buf, size_t cap, const char *fmt, va_list ap)
{
	return format(buf, cap, 0, fmt, ap);
}

size_t skp_vformat_escaped(char *buf, size_t cap, const char *fmt, va_list ap)
{
	return format(buf, cap, 1, fmt, ap);
}

size_t skp_format(char *buf, size_t cap, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	size_t n = skp_vformat(buf, cap, fmt, ap);
	va_end(ap);
	return n;
}

size_t skp_escape_name(char *buf, size_t cap, const char *name)
{
	out o = { buf, cap, 0, 1 };
	put_str(&o, name);
	if (cap)
		buf[o.len < cap ? o.len : cap - 1] = '\0';
	return o.len < cap ? o.len : cap - 1;
}
