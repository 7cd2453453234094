#include "skp_error.h"

#include <stdarg.h>

#include "skp_format.h"

skp_status skp_vfail(skp_error *err, skp_status code, long line,
		     const char *fmt, va_list ap)
{
	if (!err)
		return code;
	err->code = code;
	err->line = line;
	err->block = -1;
	skp_vformat_escaped(err->msg, sizeof err->msg, fmt, ap);
	return code;
}

skp_status skp_fail(skp_error *err, skp_status code, long line,
		    const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	skp_vfail(err, code, line, fmt, ap);
	va_end(ap);
	return code;
}

skp_status skp_syntax(skp_error *err, long line, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	skp_status rc = skp_vfail(err, SKP_ERR_SYNTAX, line, fmt, ap);
	va_end(ap);
	return rc;
}

void skp_error_clear(skp_error *err)
{
	if (!err)
		return;
	err->code = SKP_OK;
	err->line = 0;
	err->block = -1;
	err->msg[0] = '\0';
}
