#include "file_reader.h"

#include <errno.h>
#include <fcntl.h>
#include <unistd.h>

int file_reader_open(file_reader *fr, const char *path)
{
	fr->fd = open(path, O_RDONLY | O_CLOEXEC);
	return fr->fd < 0 ? -errno : 0;
}

static long fd_read(void *ctx, void *buf, size_t len)
{
	file_reader *fr = ctx;
	for (;;) {
		ssize_t n = read(fr->fd, buf, len);
		if (n >= 0)
			return (long)n;
		if (errno != EINTR)
			return -1;
	}
}

skp_reader file_reader_as_reader(file_reader *fr)
{
	skp_reader rd = { fd_read, fr };
	return rd;
}

void file_reader_close(file_reader *fr)
{
	if (fr->fd >= 0)
		close(fr->fd);
	fr->fd = -1;
}

long file_reader_head(const char *path, void *buf, size_t len)
{
	file_reader fr;
	int rc = file_reader_open(&fr, path);
	if (rc < 0)
		return rc;
	size_t got = 0;
	long n = 1;
	while (got < len && (n = fd_read(&fr, (char *)buf + got, len - got)) > 0)
		got += (size_t)n;
	rc = n < 0 ? -errno : 0;
	file_reader_close(&fr);
	return rc < 0 ? rc : (long)got;
}
