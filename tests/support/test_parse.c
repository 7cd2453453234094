#include "test_parse.h"

#include <stdlib.h>

#include "test_paths.h"

skp_status test_parse_asf(const char *text, size_t len, skel *out, skp_error *err)
{
	static text_lines tl;
	skp_mem_source src;
	text_lines_init(&tl, skp_mem_reader(&src, text, len));
	return asf_parse(out, &tl, err);
}

skp_status test_parse_asf_file(const char *path, skel *out, skp_error *err)
{
	size_t n;
	char *data = test_read_file(path, &n);
	if (!data)
		return SKP_ERR_IO;
	skp_status rc = test_parse_asf(data, n, out, err);
	free(data);
	return rc;
}

long test_stream_amc(const char *text, size_t len, const skel *s, skp_error *err,
		     void (*fn)(const amc_frame *f, void *ctx), void *ctx)
{
	static text_lines tl;
	static amc_stream a;
	static amc_frame f;
	skp_mem_source src;
	text_lines_init(&tl, skp_mem_reader(&src, text, len));
	amc_open(&a, s, &tl);
	long n = 0;
	int r;
	while ((r = amc_next(&a, &f, err)) > 0) {
		if (fn)
			fn(&f, ctx);
		n++;
	}
	return r < 0 ? r : n;
}

long test_stream_bvh(const char *text, size_t len, skel *s, skp_error *err,
		     void (*fn)(const amc_frame *f, void *ctx), void *ctx)
{
	static text_lines tl;
	static bvh_layout lay;
	static bvh_stream b;
	static amc_frame f;
	skp_mem_source src;
	text_lines_init(&tl, skp_mem_reader(&src, text, len));
	skp_status rc = bvh_parse(s, &lay, &tl, err);
	if (rc)
		return -(long)rc;
	bvh_open(&b, s, &lay, &tl);
	long n = 0;
	int r;
	while ((r = bvh_next(&b, &f, err)) > 0) {
		if (fn)
			fn(&f, ctx);
		n++;
	}
	return r < 0 ? r : n;
}
