/* The button input port: the interface a platform input backend implements
 * (platform/input/, kmscube style: one struct of function pointers per
 * backend, static state, one active at a time). Every backend delivers
 * debounced control_events (press, release, long press) with timestamps in
 * the caller's millisecond clock. The frame loop calls read() once a frame
 * and polls nothing: read never blocks, and the debounce and long-press
 * timers fire inside it. */
#ifndef INPUT_PORT_H
#define INPUT_PORT_H

#include <stdint.h>

#include "board_config.h"
#include "controls.h"
#include "skp_error.h"

#define INPUT_MAX_EVENTS 32   /* a good size for read()'s event array */

/* key()'s codes for keys that are not characters: a window's are the same
 * (platform/display/display.h), so one key map serves both. */
#define INPUT_KEY_LEFT 0x100
#define INPUT_KEY_RIGHT 0x101
#define INPUT_KEY_ESCAPE 27

typedef struct input_backend {
	const char *name;
	/* cfg: the board's buttons and chip; arg: the script file (else NULL);
	 * now_ms: the current time of the clock read() will be given. On
	 * failure nothing is left open. */
	int (*init)(const board_config *cfg, const char *arg, uint64_t now_ms, skp_error *err);
	/* Reads what is pending and fires timers due at now_ms. Returns the
	 * number of events written to ev (at most max; the rest waits for the
	 * next call), or -1 with err filled. */
	int (*read)(uint64_t now_ms, control_event *ev, int max, skp_error *err);
	/* Releases the lines, restores the terminal. */
	void (*shutdown)(void);
	/* NULL for buttons alone; else the next key typed since (a printable
	 * character, INPUT_KEY_*, 0 when none is waiting): a desktop's keys,
	 * mapped by the kiosk as a window's are. Never blocks. */
	int (*key)(void);
} input_backend;

#endif
