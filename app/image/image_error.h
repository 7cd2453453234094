/* The error every file of app/image that reports a block (reader, writer,
 * parity, copies, clip stream) fails through. Private to app/image. */
#ifndef IMAGE_ERROR_H
#define IMAGE_ERROR_H

#include <stdint.h>

#include "skp_error.h"

/* skp_fail with code, naming block in err->block. */
skp_status image_block_fail(skp_error *err, skp_status code, uint32_t block, const char *fmt, ...);

#endif
