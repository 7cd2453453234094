/* A small, allocation-free formatter so that app/ needs no stdio. */
#ifndef SKP_FORMAT_H
#define SKP_FORMAT_H

#include <stdarg.h>
#include <stddef.h>

/* Writes at most cap-1 characters plus NUL; returns the length written.
 * Conversions: %s %d %ld %u %lu %c %% %g (6 significant digits). */
size_t skp_vformat(char *buf, size_t cap, const char *fmt, va_list ap);
/* The same with control characters of %s arguments written as \xNN: error
 * messages quote input bytes, which must not reach a terminal or the
 * journal raw. */
size_t skp_vformat_escaped(char *buf, size_t cap, const char *fmt, va_list ap);
size_t skp_format(char *buf, size_t cap, const char *fmt, ...);

/* A name from a file, kept with its control characters as \xNN (cut to
 * cap-1 bytes): names are printed on terminals, in logs and on screen. */
size_t skp_escape_name(char *buf, size_t cap, const char *name);

#endif
