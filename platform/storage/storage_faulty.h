/* A fault-injecting wrapper around any skp_blockdev, for tests: what worn,
 * torn or half-written flash does to reads. Faults are set per block or at
 * a seeded random rate, and every one is counted. */
#ifndef STORAGE_FAULTY_H
#define STORAGE_FAULTY_H

#include <stdint.h>

#include "blockdev.h"

#define STORAGE_FAULTY_MAX 32  /* blocks each kind of per-block fault can name */

typedef struct storage_fault_list {
	int count;
	uint32_t block[STORAGE_FAULTY_MAX];
	uint32_t arg[STORAGE_FAULTY_MAX];  /* flip: bit index in the block; short: bytes */
} storage_fault_list;

typedef struct storage_faulty {
	const skp_blockdev *lower;
	skp_blockdev bd;
	storage_fault_list flip, shortr, eio;
	double flip_rate;          /* probability a read gets one random bit flipped */
	uint64_t rng;
	unsigned delay_us;         /* added to every read */
	unsigned long reads, flips, shorts, eios;
} storage_faulty;

void storage_faulty_init(storage_faulty *f, const skp_blockdev *lower);

/* Every read of block returns bit (0..8*block_size-1) inverted. */
int storage_faulty_flip(storage_faulty *f, uint32_t block, uint32_t bit);
/* Each read has probability rate of one bit flipped at random (seeded). */
void storage_faulty_flip_rate(storage_faulty *f, double rate, uint64_t seed);
/* Reads of block return only bytes bytes. */
int storage_faulty_short(storage_faulty *f, uint32_t block, uint32_t bytes);
/* Reads of block fail with SKP_BD_EIO. */
int storage_faulty_eio(storage_faulty *f, uint32_t block);
/* Every read takes at least us microseconds longer. */
void storage_faulty_delay(storage_faulty *f, unsigned us);

#endif
