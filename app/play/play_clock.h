/* The engine's sense of time. Time comes in as nanoseconds from the
 * caller (the monotonic clock on a screen, display frame n at n / rate
 * seconds headless, any sequence in a test); the clock subtracts the time
 * spent paused, so a pause freezes the clip and any crossfade alike. */
#ifndef PLAY_CLOCK_H
#define PLAY_CLOCK_H

#include <stdint.h>

typedef struct play_clock {
	uint64_t paused_total;   /* ns spent paused before the current pause */
	uint64_t paused_at;      /* when the current pause began */
	int paused;
	int started;
	uint64_t origin;         /* the first time seen: active time counts from it */
} play_clock;

void play_clock_init(play_clock *c);

/* Time not spent paused, in ns since the first call, at now (which must
 * not go backwards). */
uint64_t play_clock_active(play_clock *c, uint64_t now);

void play_clock_pause(play_clock *c, int paused, uint64_t now);

/* Display frame n of a virtual clock at hz frames a second: n / hz
 * seconds, rounded to the ns (headless runs: the same bits every run). */
uint64_t play_display_time(long n, double hz);

#endif
