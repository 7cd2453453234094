/* Error reporting for app/: functions return a status and fill an skp_error;
 * only the front ends print it (as FILE:LINE: message). */
#ifndef SKP_ERROR_H
#define SKP_ERROR_H

#include <stdarg.h>

typedef enum skp_status {
	SKP_OK = 0,
	SKP_ERR_SYNTAX,   /* input does not follow the format */
	SKP_ERR_LIMIT,    /* input is larger than a board limit */
	SKP_ERR_IO,       /* the reader callback failed */
	SKP_ERR_RANGE,    /* a value or argument is out of range */
	SKP_ERR_CORRUPT   /* a checksum or structural check failed */
} skp_status;

typedef struct skp_error {
	skp_status code;
	long line;        /* 1-based line of a text input, 0 when not a line */
	long block;       /* block number of a block input, -1 when not a block */
	char msg[200];
} skp_error;

/* Fills err (when non-NULL) and returns code. The format understands %s %d
 * %ld %u %lu %c %% and %g (printed with 6 significant digits). */
skp_status skp_fail(skp_error *err, skp_status code, long line,
		    const char *fmt, ...);

skp_status skp_vfail(skp_error *err, skp_status code, long line,
		     const char *fmt, va_list ap);

/* skp_fail with SKP_ERR_SYNTAX: what the text parsers report. */
skp_status skp_syntax(skp_error *err, long line, const char *fmt, ...);

void skp_error_clear(skp_error *err);

#endif
