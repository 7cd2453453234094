/* Button debouncing as a pure function of (state, timestamp, level), in the
 * style of Zephyr's gpio_keys: a const per-button config and a mutable data
 * struct the caller owns. A level must stay unchanged for debounce_ms
 * before it counts; a press held for long_press_ms also gives a long-press
 * event (once per press). Backends feed the raw level at every edge and
 * call again without a level ("tick") so that timers can fire. */
#ifndef DEBOUNCE_H
#define DEBOUNCE_H

#include <stdint.h>

typedef struct debounce_config {
	uint32_t debounce_ms;     /* quiet time before a level counts (0: none) */
	uint32_t long_press_ms;   /* hold time for DEBOUNCE_LONG (0: never) */
} debounce_config;

typedef struct debounce_data {
	uint64_t last_ms;         /* latest timestamp seen: time never goes back */
	uint64_t raw_since_ms;    /* when the raw level last changed */
	uint64_t press_ms;        /* when the current press began (raw edge) */
	uint8_t raw;              /* level of the latest edge, 1 = pressed */
	uint8_t stable;           /* debounced level */
	uint8_t long_sent;        /* this press already gave DEBOUNCE_LONG */
} debounce_data;

/* Event bits returned by debounce_update. When several are set they
 * happened in the order PRESS, LONG, RELEASE. */
enum {
	DEBOUNCE_PRESS = 1,
	DEBOUNCE_LONG = 2,
	DEBOUNCE_RELEASE = 4
};

#define DEBOUNCE_TICK (-1)   /* level argument: no edge, just time passing */

/* Starts at level (a button held at boot gives no press) at time now_ms. */
void debounce_init(debounce_data *d, int level, uint64_t now_ms);

/* Advances to now_ms and applies level (0, 1 or DEBOUNCE_TICK). A timestamp
 * older than one already seen is taken as that newer time, so samples
 * arriving out of order cannot shorten a debounce or fire early. Returns
 * the DEBOUNCE_* bits of what happened. */
unsigned debounce_update(const debounce_config *cfg, debounce_data *d, uint64_t now_ms, int level);

/* 1 and the time of the next timer (debounce or long press) in *at_ms, or
 * 0 when nothing is pending: how long the caller may sleep. */
int debounce_next_deadline(const debounce_config *cfg, const debounce_data *d, uint64_t *at_ms);

#endif
