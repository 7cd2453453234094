/* A message that may repeat for months (a pass over a clip with a bad
 * block, a visitor pressing NEXT onto a damaged clip): said the first
 * time, then counted and said again at most once per interval, with how
 * many were held back in between, so a log never grows with the number of
 * passes or presses. Time is passed in (ns): the frame loop's clock, the
 * virtual one in headless runs, a fake one in tests. */
#ifndef SKP_RATELIMIT_H
#define SKP_RATELIMIT_H

#include <stdint.h>

#define SKP_RATELIMIT_HOUR 3600000000000ull

typedef struct skp_ratelimit {
	uint64_t interval;       /* ns between two lines said */
	uint64_t said_at;        /* when the last one was said */
	unsigned long held;      /* occurrences counted, not said, since then */
	int said;                /* one has been said */
} skp_ratelimit;

void skp_ratelimit_init(skp_ratelimit *r, uint64_t interval_ns);

/* An occurrence at now: 1 when it is to be said, with *held_back the
 * occurrences counted since the last one said (0 the first time); 0 when
 * it is only counted. */
int skp_ratelimit_take(skp_ratelimit *r, uint64_t now, unsigned long *held_back);

#endif
