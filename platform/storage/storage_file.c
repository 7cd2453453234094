#include "storage_file.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>


/* pread until the block is complete: a short count is only the end of the
 * file, never a signal or a partial transfer. */
static int sf_read(void *ctx, uint32_t block, void *buf)
{
	storage_file *sf = ctx;
	uint32_t bs = sf->bd.block_size, got = 0;
	off_t at = (off_t)block * bs;
	if ((uint64_t)at >= sf->size)
		return SKP_BD_ERANGE;
	while (got < bs) {
		ssize_t n = pread(sf->fd, (char *)buf + got, bs - got, at + got);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0)
			return SKP_BD_EIO;
		if (n == 0)
			break;
		got += (uint32_t)n;
	}
	return (int)got;
}

static int sf_write(void *ctx, uint32_t block, const void *buf)
{
	storage_file *sf = ctx;
	uint32_t bs = sf->bd.block_size, put = 0;
	off_t at = (off_t)block * bs;
	while (put < bs) {
		ssize_t n = pwrite(sf->fd, (const char *)buf + put, bs - put, at + put);
		if (n < 0 && errno == EINTR)
			continue;
		if (n <= 0)
			return SKP_BD_EIO;
		put += (uint32_t)n;
	}
	if ((uint64_t)at + bs > sf->size)
		sf->size = (uint64_t)at + bs;
	sf->bd.block_count = (uint32_t)((sf->size + bs - 1) / bs);
	return 0;
}

void storage_file_set_block_size(storage_file *sf, uint32_t block_size)
{
	sf->bd.block_size = block_size;
	/* a zero size means "not known yet": no blocks rather than a division by zero */
	sf->bd.block_count = block_size ? (uint32_t)((sf->size + block_size - 1) / block_size) : 0;
}

/* Storage is a regular file or a block device (a raw partition, whose
 * size is where it ends); a FIFO, a socket, a terminal or a directory
 * would block a reader or make no sense: -EINVAL (storage_file_kind says
 * which). */
static int sf_size(int fd, const struct stat *st, uint64_t *size)
{
	if (S_ISREG(st->st_mode)) {
		*size = (uint64_t)st->st_size;
		return 0;
	}
	if (!S_ISBLK(st->st_mode))
		return -EINVAL;
	off_t end = lseek(fd, 0, SEEK_END);
	if (end < 0)
		return -errno;
	*size = (uint64_t)end;
	return 0;
}

static int sf_init(storage_file *sf, int fd, uint32_t block_size, int writable)
{
	struct stat st;
	sf->fd = fd;
	if (fd < 0)
		return -errno;
	int rc = fstat(fd, &st) != 0 ? -errno : sf_size(fd, &st, &sf->size);
	if (rc < 0) {
		close(fd);
		sf->fd = -1;
		return rc;
	}
	sf->pos = 0;
	sf->bd.read = sf_read;
	sf->bd.write = writable ? sf_write : NULL;
	sf->bd.ctx = sf;
	storage_file_set_block_size(sf, block_size);
	return 0;
}

int storage_file_use_fd(storage_file *sf, int fd, uint32_t block_size)
{
	return sf_init(sf, fd, block_size, 1);
}

int storage_file_open(storage_file *sf, const char *path, uint32_t block_size)
{
	/* O_NONBLOCK: a FIFO put where a slot was must not hang start-up in
	 * open() (sf_init then refuses it); reads of files and block devices
	 * do not block either way */
	return sf_init(sf, open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK), block_size, 0);
}

const char *storage_file_kind(const char *path)
{
	struct stat st;
	if (stat(path, &st) != 0)
		return "missing";
	return S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISSOCK(st.st_mode) ? "a socket" : S_ISCHR(st.st_mode) ? "a character device"
	       : S_ISDIR(st.st_mode) ? "a directory" : "not a regular file or a block device";
}

int storage_file_create(storage_file *sf, const char *path, uint32_t block_size)
{
	return sf_init(sf, open(path, O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644), block_size, 1);
}

int storage_file_sync(storage_file *sf)
{
	return fsync(sf->fd) == 0 ? 0 : -errno;
}

static long sf_stream(void *ctx, void *buf, size_t len)
{
	storage_file *sf = ctx;
	for (;;) {
		ssize_t n = pread(sf->fd, buf, len, (off_t)sf->pos);
		if (n >= 0) {
			sf->pos += (uint64_t)n;
			return (long)n;
		}
		if (errno != EINTR)
			return -1;
	}
}

skp_reader storage_file_reader(storage_file *sf)
{
	sf->pos = 0;
	skp_reader rd = { sf_stream, sf };
	return rd;
}

void storage_file_close(storage_file *sf)
{
	if (sf->fd >= 0)
		close(sf->fd);
	sf->fd = -1;
}
