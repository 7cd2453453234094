#include "debounce.h"

#include <stddef.h>

void debounce_init(debounce_data *d, int level, uint64_t now_ms)
{
	d->last_ms = now_ms;
	d->raw_since_ms = now_ms;
	d->press_ms = now_ms;
	d->raw = d->stable = level ? 1 : 0;
	/* a button held at boot must not give a long press either */
	d->long_sent = 1;
}

/* The long-press timer counts while the press is held. A release edge
 * before the deadline that is still unconfirmed (maybe a bounce) defers
 * the decision until it is confirmed or undone. */
static int long_due(const debounce_config *cfg, const debounce_data *d, uint64_t now, uint64_t *at)
{
	if (!d->stable || d->long_sent || !cfg->long_press_ms)
		return 0;
	uint64_t t = d->press_ms + cfg->long_press_ms;
	if (at)
		*at = t;
	if (!d->raw && d->raw_since_ms < t)
		return 0;
	return now >= t;
}

static unsigned advance(const debounce_config *cfg, debounce_data *d, uint64_t now)
{
	unsigned ev = 0;
	if (long_due(cfg, d, now, NULL)) {
		d->long_sent = 1;
		ev |= DEBOUNCE_LONG;
	}
	if (d->raw != d->stable && now - d->raw_since_ms >= cfg->debounce_ms) {
		d->stable = d->raw;
		if (d->stable) {
			d->press_ms = d->raw_since_ms;
			d->long_sent = 0;
			ev |= DEBOUNCE_PRESS;
			if (long_due(cfg, d, now, NULL)) {
				d->long_sent = 1;
				ev |= DEBOUNCE_LONG;
			}
		} else {
			ev |= DEBOUNCE_RELEASE;
		}
	}
	return ev;
}

unsigned debounce_update(const debounce_config *cfg, debounce_data *d, uint64_t now_ms, int level)
{
	if (now_ms < d->last_ms)
		now_ms = d->last_ms;
	d->last_ms = now_ms;
	unsigned ev = advance(cfg, d, now_ms);
	if (level != DEBOUNCE_TICK && (level ? 1 : 0) != d->raw) {
		d->raw = level ? 1 : 0;
		d->raw_since_ms = now_ms;
		/* with no debounce time the new level counts at once */
		ev |= advance(cfg, d, now_ms);
	}
	return ev;
}

int debounce_next_deadline(const debounce_config *cfg, const debounce_data *d, uint64_t *at_ms)
{
	uint64_t best = UINT64_MAX, t;
	if (d->raw != d->stable)
		best = d->raw_since_ms + cfg->debounce_ms;
	if (d->stable && !d->long_sent && cfg->long_press_ms) {
		long_due(cfg, d, 0, &t);
		if (t < best)
			best = t;
	}
	if (best == UINT64_MAX)
		return 0;
	*at_ms = best;
	return 1;
}
