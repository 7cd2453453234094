/* The show's position from the wall clock: integers in ns throughout, so
 * that two devices compute the same clip and time to the nanosecond. */
#include "play_sync.h"

#include <math.h>

int play_sync_locate(int64_t wall_ns, int64_t epoch_ns, const uint64_t *length_ns, int clips, play_sync_at *at)
{
	uint64_t show = 0;
	for (int i = 0; i < clips; i++)
		show += length_ns[i];
	if (show == 0)
		return -1;
	/* before the epoch: round the show backwards, still in [0, show) */
	int64_t since = wall_ns - epoch_ns;
	uint64_t mag = since < 0 ? (uint64_t)-(since + 1) + 1 : (uint64_t)since;
	uint64_t in = mag % show, passes = mag / show;
	if (since < 0 && in) {
		in = show - in;
		passes++;
	}
	at->pass = passes;
	for (int i = 0; i < clips; i++) {
		if (in < length_ns[i]) {
			at->clip = i;
			at->into_ns = in;
			return 0;
		}
		in -= length_ns[i];
	}
	return -1; /* not reached: in < show */
}

int play_sync_off(double shown_s, double clock_s, double tolerance_s)
{
	return !(fabs(shown_s - clock_s) <= tolerance_s);
}
