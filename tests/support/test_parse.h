/* Parse ASF/AMC text held in memory (tests). */
#ifndef TEST_PARSE_H
#define TEST_PARSE_H

#include <stddef.h>

#include "amc.h"
#include "bvh.h"
#include "asf.h"

skp_status test_parse_asf(const char *text, size_t len, skel *out, skp_error *err);
skp_status test_parse_asf_file(const char *path, skel *out, skp_error *err);

/* Streams all frames of an AMC text; calls fn for each (may be NULL).
 * Returns the frame count, or a negative status. */
long test_stream_amc(const char *text, size_t len, const skel *s, skp_error *err,
		     void (*fn)(const amc_frame *f, void *ctx), void *ctx);

/* Parses a BVH text into s and streams its frames like test_stream_amc;
 * a HIERARCHY error returns the negative status. */
long test_stream_bvh(const char *text, size_t len, skel *s, skp_error *err,
		     void (*fn)(const amc_frame *f, void *ctx), void *ctx);

#endif
