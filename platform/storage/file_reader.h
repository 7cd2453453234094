/* A sequential skp_reader over a file descriptor (open/read, no stdio
 * buffering: the text parsers keep their own fixed chunk). */
#ifndef FILE_READER_H
#define FILE_READER_H

#include "skp_reader.h"

typedef struct file_reader {
	int fd;
} file_reader;

/* Returns 0, or -errno when the file cannot be opened. */
int file_reader_open(file_reader *fr, const char *path);
skp_reader file_reader_as_reader(file_reader *fr);
void file_reader_close(file_reader *fr);

/* Reads the first len bytes of the file at path (fewer when it is
 * shorter; len 0: whether it opens): what a format sniffer or a first-line
 * check needs. Returns the count, or -errno when the file cannot be opened
 * or read. */
long file_reader_head(const char *path, void *buf, size_t len);

#endif
