#include "blockdev.h"

#include <string.h>

static int mem_read(void *ctx, uint32_t block, void *buf)
{
	skp_mem_blockdev *m = ctx;
	const uint8_t *src = m->data ? m->data : m->rodata;
	uint64_t bs = m->block_size, at = (uint64_t)block * bs;
	if (at >= m->size)
		return SKP_BD_ERANGE;
	uint64_t n = m->size - at < bs ? m->size - at : bs;
	memcpy(buf, src + at, (size_t)n);
	return (int)n;
}

static int mem_write(void *ctx, uint32_t block, const void *buf)
{
	skp_mem_blockdev *m = ctx;
	uint64_t bs = m->block_size, at = (uint64_t)block * bs;
	if (!m->data || at + bs > m->capacity)
		return SKP_BD_ERANGE;
	memcpy(m->data + at, buf, (size_t)bs);
	if (at + bs > m->size)
		m->size = (size_t)(at + bs);
	return 0;
}

skp_blockdev skp_mem_blockdev_init(skp_mem_blockdev *m, void *buf, size_t capacity,
				   uint32_t block_size)
{
	memset(m, 0, sizeof *m);
	m->data = buf;
	m->capacity = capacity;
	m->block_size = block_size;
	skp_blockdev bd = { mem_read, mem_write, block_size,
			    (uint32_t)(capacity / block_size), m };
	return bd;
}

skp_blockdev skp_mem_blockdev_ro(skp_mem_blockdev *m, const void *data, size_t size,
				 uint32_t block_size)
{
	memset(m, 0, sizeof *m);
	m->rodata = data;
	m->size = m->capacity = size;
	m->block_size = block_size;
	skp_blockdev bd = { mem_read, NULL, block_size,
			    (uint32_t)((size + block_size - 1) / block_size), m };
	return bd;
}

/* Copies from the cached block, reading the next one when the position
 * leaves it: one block read per block_size bytes streamed. */
static long stream_read(void *ctx, void *buf, size_t len)
{
	skp_blockdev_stream *st = ctx;
	const skp_blockdev *dev = st->dev;
	if (st->pos >= st->end || len == 0)
		return 0;
	uint32_t block = (uint32_t)(st->pos / dev->block_size);
	uint32_t off = (uint32_t)(st->pos % dev->block_size);
	if (st->cached != block) {
		int n = dev->read(dev->ctx, block, st->buf);
		uint64_t need = st->end - (uint64_t)block * dev->block_size;
		if (n < 0 || (uint64_t)n < (need < dev->block_size ? need : dev->block_size))
			return -1;
		st->cached = block;
	}
	uint64_t avail = dev->block_size - off;
	if (avail > st->end - st->pos)
		avail = st->end - st->pos;
	size_t n = len < avail ? len : (size_t)avail;
	memcpy(buf, st->buf + off, n);
	st->pos += n;
	return (long)n;
}

skp_reader skp_blockdev_reader(skp_blockdev_stream *st, const skp_blockdev *dev, void *buf,
			       uint64_t offset, uint64_t len)
{
	st->dev = dev;
	st->buf = buf;
	st->pos = offset;
	st->end = offset + len;
	st->cached = UINT32_MAX;
	skp_reader rd = { stream_read, st };
	return rd;
}
