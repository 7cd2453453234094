/* A small deterministic PRNG (xorshift32) shared by the randomised tests,
 * so every run draws the same inputs. */
#ifndef TEST_RNG_H
#define TEST_RNG_H

#include <stdint.h>

void test_rng_seed(uint32_t seed);
uint32_t test_rng_u32(void);
uint64_t test_rng_u64(void);
/* uniform in [lo, hi) */
double test_rng_range(double lo, double hi);

#endif
