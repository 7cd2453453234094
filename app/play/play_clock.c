#include "play_clock.h"

#include <math.h>

void play_clock_init(play_clock *c)
{
	c->paused_total = c->paused_at = c->origin = 0;
	c->paused = c->started = 0;
}

static uint64_t since_origin(play_clock *c, uint64_t now)
{
	if (!c->started) {
		c->origin = now;
		c->started = 1;
	}
	return now >= c->origin ? now - c->origin : 0;
}

uint64_t play_clock_active(play_clock *c, uint64_t now)
{
	uint64_t t = since_origin(c, now), off = c->paused_total;
	if (c->paused && t > c->paused_at)
		off += t - c->paused_at;
	return t > off ? t - off : 0;
}

void play_clock_pause(play_clock *c, int paused, uint64_t now)
{
	uint64_t t = since_origin(c, now);
	if (paused && !c->paused)
		c->paused_at = t;
	else if (!paused && c->paused && t > c->paused_at)
		c->paused_total += t - c->paused_at;
	c->paused = paused != 0;
}

uint64_t play_display_time(long n, double hz)
{
	return (uint64_t)llround((double)n * 1e9 / hz);
}
