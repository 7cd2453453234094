/* systemd's readiness and watchdog protocol, written directly (no
 * libsystemd): one datagram per message to the AF_UNIX socket named by
 * $NOTIFY_SOCKET (a path, or '@' for the abstract namespace). Without
 * $NOTIFY_SOCKET (not run by systemd) every call is a no-op. */
#ifndef SD_NOTIFY_H
#define SD_NOTIFY_H

#include <stdint.h>

typedef struct sdnotify {
	int fd;                  /* -1: not under systemd */
	uint64_t interval_ns;    /* WATCHDOG=1 period (half of $WATCHDOG_USEC), 0: none */
	uint64_t last_ns;        /* when WATCHDOG=1 was last sent */
} sdnotify;

/* Reads $NOTIFY_SOCKET, $WATCHDOG_USEC and $WATCHDOG_PID (the watchdog is
 * ours only when the pid matches or is absent). Returns 0, or -errno when
 * the variable is set but the socket cannot be made. */
int sdnotify_init(sdnotify *n);

/* Sends state ("READY=1", "STOPPING=1", "RELOADING=1", "STATUS=...").
 * Returns 0 (also when not under systemd) or -errno. */
int sdnotify_send(sdnotify *n, const char *state);

/* Sends WATCHDOG=1 when half the watchdog period has passed since the
 * last one; call once per frame. Returns 1 when sent, 0, or -errno. */
int sdnotify_watchdog(sdnotify *n, uint64_t now_ns);

void sdnotify_close(sdnotify *n);

#endif
