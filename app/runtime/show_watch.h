/* The image slots' files, watched while a show plays or waits for one: a
 * slot written in place, replaced or newly there is news once it has stood
 * still for SHOW_WATCH_SETTLE_NS (a copy in progress is not an image yet).
 * While a show plays, the settled slot must also hold a whole image (every
 * block as packed or rebuilt, the digest matching): a half-written or
 * damaged copy never stops a show that plays, and is said once. The show
 * is then opened again (skinplay starts over, as for SIGHUP). */
#ifndef SHOW_WATCH_H
#define SHOW_WATCH_H

#include <stdint.h>
#include <sys/types.h>
#include <time.h>

#include "show_source.h"

#define SHOW_WATCH_POLL_NS 250000000ull    /* a look at the slots four times a second */
#define SHOW_WATCH_SETTLE_NS 2000000000ull /* a changed slot must stand still this long */

/* What a slot file is now: enough to see that it changed. */
typedef struct show_slot_state {
	int exists;
	dev_t dev;
	ino_t ino;
	off_t size;
	struct timespec mtime;
} show_slot_state;

typedef struct show_watch {
	const char *const *paths;
	int count;
	show_slot_state seen[SHOW_MAX_SLOTS];  /* as the show was opened, or judged last */
	show_slot_state last[SHOW_MAX_SLOTS];  /* as last looked at */
	uint64_t changed_at;                   /* when a slot last changed; 0: none since */
	uint64_t next_look;
} show_watch;

/* Takes the slots as they are now (count at most SHOW_MAX_SLOTS). */
void show_watch_init(show_watch *w, const char *const *paths, int count);

/* At most every SHOW_WATCH_POLL_NS of now (ns, any monotonic clock): 1
 * when a slot changed since init and has stood still since; with
 * whole_only, only when that slot also holds a whole image (one that
 * does not is said on stderr and waited past until it changes again). */
int show_watch_poll(show_watch *w, uint64_t now, int whole_only);

#endif
