/* A file as block storage (open/pread/pwrite, no stdio buffering): the
 * skp_blockdev the image reader and writer use, and a sequential skp_reader
 * over the same file for raw ASF/AMC text. */
#ifndef STORAGE_FILE_H
#define STORAGE_FILE_H

#include <stdint.h>

#include "blockdev.h"

typedef struct storage_file {
	int fd;
	uint64_t size;         /* bytes in the file */
	uint64_t pos;          /* the sequential reader's position */
	skp_blockdev bd;
} storage_file;

/* Opens read-only with that block size, never blocking: a regular file or
 * a block device (a raw partition). Returns 0 or -errno: -EINVAL for
 * anything else (a FIFO, a socket, a directory: storage_file_kind). */
int storage_file_open(storage_file *sf, const char *path, uint32_t block_size);

/* What path is when storage_file_open refused it with -EINVAL: "a FIFO",
 * "a socket", "a character device", "a directory", ... */
const char *storage_file_kind(const char *path);

/* Block storage over an open read-write fd (an atomic_file's): closing the
 * storage closes it. Returns 0 or -errno. */
int storage_file_use_fd(storage_file *sf, int fd, uint32_t block_size);

/* Creates (truncates) a file to write blocks into. Returns 0 or -errno. */
int storage_file_create(storage_file *sf, const char *path, uint32_t block_size);

/* Changes the block size (block_count follows). */
void storage_file_set_block_size(storage_file *sf, uint32_t block_size);

/* fsync. Returns 0 or -errno. */
int storage_file_sync(storage_file *sf);

/* Bytes from the start of the file, in order (pread from a kept offset). */
skp_reader storage_file_reader(storage_file *sf);

void storage_file_close(storage_file *sf);

#endif
