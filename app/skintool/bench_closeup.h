/* skintool bench's measure of the close-up's and difference view's CPU
 * work per frame (bench_closeup.c). */
#ifndef BENCH_CLOSEUP_H
#define BENCH_CLOSEUP_H

#include "skin.h"

/* Times it over soa (skinned with bones by LBS and DQBS) best of rounds,
 * and prints it next to kernels_ns, the two kernels' ns a vertex. 0, or
 * -1 out of memory (reported). */
int bench_closeup(const skin_soa *soa, const skin_bones *bones, double kernels_ns, int rounds);

#endif
