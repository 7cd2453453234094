#include "clock.h"

#include <errno.h>
#include <sys/timex.h>
#include <time.h>

uint64_t clock_now_ns(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

void clock_sleep_until_ns(uint64_t deadline)
{
	struct timespec ts = { (time_t)(deadline / 1000000000u), (long)(deadline % 1000000000u) };
	while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR)
		;
}

int64_t clock_wall_ns(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_REALTIME, &ts);
	return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

/* adjtimex(2) with no modes only reads: TIME_ERROR is the kernel's word
 * for a clock no daemon has synchronised (STA_UNSYNC). */
int clock_synchronised(void)
{
	struct timex tx = { 0 };
	int state = adjtimex(&tx);
	if (state < 0)
		return -1;
	return state != TIME_ERROR && !(tx.status & STA_UNSYNC);
}
