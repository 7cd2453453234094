#include "storage_faulty.h"

#include <string.h>
#include <time.h>

static int find(const storage_fault_list *l, uint32_t block)
{
	for (int i = 0; i < l->count; i++)
		if (l->block[i] == block)
			return i;
	return -1;
}

static int add(storage_fault_list *l, uint32_t block, uint32_t arg)
{
	if (l->count >= STORAGE_FAULTY_MAX)
		return -1;
	l->block[l->count] = block;
	l->arg[l->count++] = arg;
	return 0;
}

/* splitmix64: a seed gives the same faults on every run. */
static uint64_t next_rand(storage_faulty *f)
{
	uint64_t z = (f->rng += 0x9e3779b97f4a7c15ull);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
	return z ^ (z >> 31);
}

static void flip_bit(uint8_t *buf, uint32_t bit)
{
	buf[bit / 8] ^= (uint8_t)(1u << (bit % 8));
}

static void sleep_us(unsigned us)
{
	struct timespec ts = { us / 1000000u, (long)(us % 1000000u) * 1000 };
	while (nanosleep(&ts, &ts) != 0)
		;
}

static int faulty_read(void *ctx, uint32_t block, void *buf)
{
	storage_faulty *f = ctx;
	int i;
	f->reads++;
	if (f->delay_us)
		sleep_us(f->delay_us);
	if (find(&f->eio, block) >= 0) {
		f->eios++;
		return SKP_BD_EIO;
	}
	int n = f->lower->read(f->lower->ctx, block, buf);
	if (n <= 0)
		return n;
	if ((i = find(&f->flip, block)) >= 0) {
		flip_bit(buf, f->flip.arg[i] % (8u * (uint32_t)n));
		f->flips++;
	}
	if (f->flip_rate > 0 && (double)(next_rand(f) >> 11) * 0x1.0p-53 < f->flip_rate) {
		flip_bit(buf, (uint32_t)(next_rand(f) % (8u * (uint64_t)n)));
		f->flips++;
	}
	if ((i = find(&f->shortr, block)) >= 0 && f->shortr.arg[i] < (uint32_t)n) {
		f->shorts++;
		return (int)f->shortr.arg[i];
	}
	return n;
}

static int faulty_write(void *ctx, uint32_t block, const void *buf)
{
	storage_faulty *f = ctx;
	return f->lower->write ? f->lower->write(f->lower->ctx, block, buf) : SKP_BD_EIO;
}

void storage_faulty_init(storage_faulty *f, const skp_blockdev *lower)
{
	memset(f, 0, sizeof *f);
	f->lower = lower;
	f->bd = *lower;
	f->bd.read = faulty_read;
	f->bd.write = lower->write ? faulty_write : NULL;
	f->bd.ctx = f;
}

int storage_faulty_flip(storage_faulty *f, uint32_t block, uint32_t bit)
{
	return add(&f->flip, block, bit);
}

void storage_faulty_flip_rate(storage_faulty *f, double rate, uint64_t seed)
{
	f->flip_rate = rate;
	f->rng = seed;
}

int storage_faulty_short(storage_faulty *f, uint32_t block, uint32_t bytes)
{
	return add(&f->shortr, block, bytes);
}

int storage_faulty_eio(storage_faulty *f, uint32_t block)
{
	return add(&f->eio, block, 0);
}

void storage_faulty_delay(storage_faulty *f, unsigned us)
{
	f->delay_us = us;
}
