/* Monotonic time for pacing and timing; the wall clock and its health. */
#ifndef CLOCK_H
#define CLOCK_H

#include <stdint.h>

uint64_t clock_now_ns(void);

/* The wall clock (CLOCK_REALTIME), ns since the Unix epoch: what a
 * synchronised show's position is computed from (app/play/play_sync.h). */
int64_t clock_wall_ns(void);

/* Whether the kernel says the wall clock is synchronised (an NTP or PTP
 * daemon disciplines it: chrony, linuxptp's phc2sys): 1 yes, 0 no (its
 * status says unsynchronised), -1 unknown. */
int clock_synchronised(void);
void clock_sleep_until_ns(uint64_t deadline);

#endif
