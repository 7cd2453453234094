/* SIGTERM / SIGINT (quit) and SIGHUP (reload the show) as a pollable fd:
 * a self-pipe written from the handler, so it works whatever threads Mesa
 * or the worker pool started and whatever their signal masks. */
#ifndef SIGNALS_H
#define SIGNALS_H

enum {
	SIGNALS_QUIT = 1,        /* SIGTERM or SIGINT */
	SIGNALS_RELOAD = 2       /* SIGHUP */
};

/* Installs the handlers, then lets the three signals through (one held
 * by signals_hold before an exec arrives now). Returns the fd to poll for
 * POLLIN, or -errno. */
int signals_init(void);

/* Blocks SIGTERM, SIGINT and SIGHUP: one that arrives from now on waits,
 * through signals_shutdown and an exec, until signals_init takes it. A
 * re-exec for SIGHUP holds them first: a second SIGHUP in between (two
 * `systemctl reload`s) would otherwise meet the default action and kill
 * the kiosk. */
void signals_hold(void);

/* The SIGNALS_* bits of what arrived since the last call (never blocks). */
unsigned signals_take(void);

/* Restores the default handlers and closes the pipe. */
void signals_shutdown(void);

#endif
