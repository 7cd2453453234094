/* Many screens, one performance: where a show is at a wall-clock time,
 * so that every device playing the same image on a synchronised clock
 * (NTP through chrony, PTP through linuxptp) shows the same pose at the
 * same instant, whenever it started. The show's position is (wall clock -
 * epoch) modulo the show's length, its clips in their order. Arithmetic on
 * the clock only: no allocation, no I/O (the MCU core builds it). */
#ifndef PLAY_SYNC_H
#define PLAY_SYNC_H

#include <stdint.h>

/* Where the show is. */
typedef struct play_sync_at {
	int clip;                /* index into the lengths given (a length of 0 is never chosen) */
	uint64_t into_ns;        /* time into that clip, in display time */
	uint64_t pass;           /* whole shows played since the epoch */
} play_sync_at;

/* The show at wall time wall_ns (ns since the Unix epoch; before the
 * epoch counts backwards round the show): clips' lengths in display time
 * (a clip's frames over its rate, over the speed; 0 for one that does not
 * play). 0, or -1 when no clip has a length. */
int play_sync_locate(int64_t wall_ns, int64_t epoch_ns, const uint64_t *length_ns, int clips, play_sync_at *at);

/* How far a device's clip time lies from the clock's (seconds, either
 * sign), and whether that is a join: the device is off the clock by more
 * than tolerance_s (a late start, a pause, a stall), so it crossfades to
 * the clock's pose rather than jump. */
int play_sync_off(double shown_s, double clock_s, double tolerance_s);

#endif
