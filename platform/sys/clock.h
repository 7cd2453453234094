/* Monotonic time for pacing and timing. */
#ifndef CLOCK_H
#define CLOCK_H

#include <stdint.h>

uint64_t clock_now_ns(void);
void clock_sleep_until_ns(uint64_t deadline);

#endif
