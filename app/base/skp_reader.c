#include "skp_reader.h"

#include <string.h>

static long mem_read(void *ctx, void *buf, size_t len)
{
	skp_mem_source *src = ctx;
	size_t left = src->size - src->pos;
	size_t n = len < left ? len : left;

	memcpy(buf, src->data + src->pos, n);
	src->pos += n;
	return (long)n;
}

skp_reader skp_mem_reader(skp_mem_source *src, const void *data, size_t size)
{
	src->data = data;
	src->size = size;
	src->pos = 0;
	skp_reader rd = { mem_read, src };
	return rd;
}
