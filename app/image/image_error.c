#include "image_error.h"

#include <stdarg.h>

skp_status image_block_fail(skp_error *err, skp_status code, uint32_t block, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	skp_vfail(err, code, 0, fmt, ap);
	va_end(ap);
	if (err)
		err->block = (long)block;
	return code;
}
