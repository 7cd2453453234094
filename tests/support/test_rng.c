#include "test_rng.h"

static uint32_t state = 1;

void test_rng_seed(uint32_t seed)
{
	state = seed ? seed : 1;
}

uint32_t test_rng_u32(void)
{
	uint32_t x = state;
	x ^= x << 13;
	x ^= x >> 17;
	x ^= x << 5;
	return state = x;
}

uint64_t test_rng_u64(void)
{
	uint64_t hi = test_rng_u32();
	return hi << 32 | test_rng_u32();
}

double test_rng_range(double lo, double hi)
{
	return lo + (hi - lo) * (test_rng_u32() / 4294967296.0);
}
