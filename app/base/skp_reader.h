/* Byte-stream input through a callback, so parsers work the same on a file,
 * a flash partition or a test buffer, without stdio. */
#ifndef SKP_READER_H
#define SKP_READER_H

#include <stddef.h>

/* Reads up to len bytes into buf. Returns the count read (> 0), 0 at the end
 * of the stream, or a negative value on an I/O error. */
typedef long (*skp_read_fn)(void *ctx, void *buf, size_t len);

typedef struct skp_reader {
	skp_read_fn read;
	void *ctx;
} skp_reader;

/* A reader over a memory buffer (tests, embedded assets). */
typedef struct skp_mem_source {
	const char *data;
	size_t size, pos;
} skp_mem_source;

skp_reader skp_mem_reader(skp_mem_source *src, const void *data, size_t size);

#endif
