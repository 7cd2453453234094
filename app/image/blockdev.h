/* Block storage through callbacks, in the spirit of littlefs's lfs_config:
 * the core reads and writes whole fixed-size blocks and never sees a file,
 * so the same image reader runs on a file (platform/storage/storage_file.c), a raw
 * flash partition, memory-mapped flash or a fault-injecting test wrapper
 * (platform/storage/storage_faulty.c). */
#ifndef BLOCKDEV_H
#define BLOCKDEV_H

#include <stddef.h>
#include <stdint.h>

#include "skp_reader.h"

/* What a block read returns besides a whole block (block_size). */
#define SKP_BD_EIO   (-1)   /* the medium reported an error */
#define SKP_BD_ERANGE (-2)  /* block beyond block_count */

typedef struct skp_blockdev {
	/* Reads block (0-based) into buf (block_size bytes). Returns block_size
	 * on success, 0..block_size-1 for a short read (the bytes that came,
	 * e.g. a truncated file; the rest of buf is undefined), or a negative
	 * SKP_BD_* error. */
	int (*read)(void *ctx, uint32_t block, void *buf);
	/* Writes one whole block; NULL on read-only storage. Returns 0 or < 0. */
	int (*write)(void *ctx, uint32_t block, const void *buf);
	uint32_t block_size;
	uint32_t block_count;   /* blocks present (a partial last block counts) */
	void *ctx;
} skp_blockdev;

/* Storage in memory: a RAM buffer or memory-mapped flash. A write past the
 * end fails; size need not be a multiple of block_size (the last block then
 * reads short). */
typedef struct skp_mem_blockdev {
	uint8_t *data;          /* NULL for read-only data: see skp_mem_blockdev_ro */
	const uint8_t *rodata;
	size_t size, capacity;  /* bytes written so far (or held) / buffer size */
	uint32_t block_size;
} skp_mem_blockdev;

/* Writable: block_count is what fits in capacity; reads see what was
 * written (size grows with the highest block written). */
skp_blockdev skp_mem_blockdev_init(skp_mem_blockdev *m, void *buf, size_t capacity,
				   uint32_t block_size);
skp_blockdev skp_mem_blockdev_ro(skp_mem_blockdev *m, const void *data, size_t size,
				 uint32_t block_size);

/* A sequential byte stream stored on a block device from byte offset for
 * len bytes (raw ASF/AMC text kept in flash), as an skp_reader, so the text
 * parsers stream it exactly as they stream a file. buf holds one block
 * (dev->block_size bytes, caller-owned). A failed or short block read is an
 * I/O error of the reader. */
typedef struct skp_blockdev_stream {
	const skp_blockdev *dev;
	uint8_t *buf;
	uint64_t pos, end;       /* byte positions on the device */
	uint32_t cached;         /* block in buf, UINT32_MAX for none */
} skp_blockdev_stream;

skp_reader skp_blockdev_reader(skp_blockdev_stream *st, const skp_blockdev *dev, void *buf,
			       uint64_t offset, uint64_t len);

#endif
