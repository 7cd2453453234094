#include "cli_progress.h"

#include <stdio.h>
#include <unistd.h>

#include "cli_quiet.h"
#include "clock.h"

#define REDRAW_NS 200000000u
#define BAR 30

void cli_progress_start(cli_progress *p, const char *what, const char *unit, long total)
{
	p->what = what;
	p->unit = unit;
	p->total = total;
	p->done = 0;
	p->t0 = clock_now_ns();
	p->last = 0;
	p->tty = !cli_quiet() && isatty(2);
}

double cli_progress_seconds(const cli_progress *p)
{
	return (double)(clock_now_ns() - p->t0) * 1e-9;
}

static void draw(const cli_progress *p, double secs)
{
	double rate = secs > 0.0 ? (double)p->done / secs : 0.0;
	if (p->total > 0) {
		char bar[BAR + 1];
		int fill = (int)(BAR * (p->done > p->total ? p->total : p->done) / p->total);
		for (int i = 0; i < BAR; i++)
			bar[i] = i < fill ? '#' : '.';
		bar[BAR] = '\0';
		double left = rate > 0.0 ? (double)(p->total - p->done) / rate : 0.0;
		fprintf(stderr, "\r%s [%s] %3ld%% %ld/%ld %s, %.0f/s, %.0f s left  ", p->what, bar,
			100 * p->done / p->total, p->done, p->total, p->unit, rate, left);
	} else {
		fprintf(stderr, "\r%s: %ld %s, %.0f/s, %.1f s  ", p->what, p->done, p->unit, rate, secs);
	}
}

void cli_progress_step(cli_progress *p, long done)
{
	p->done = done;
	if (!p->tty)
		return;
	uint64_t now = clock_now_ns();
	/* nothing for steps that end within the first second */
	if (now - p->t0 < 1000000000u || now - p->last < REDRAW_NS)
		return;
	p->last = now;
	draw(p, (double)(now - p->t0) * 1e-9);
}

void cli_progress_clear(cli_progress *p)
{
	if (p->tty && p->last)
		fprintf(stderr, "\r%*s\r", 110, "");
	p->last = 0;
}

void cli_progress_end(cli_progress *p, const char *extra)
{
	double secs = cli_progress_seconds(p);
	cli_progress_clear(p);
	fprintf(cli_note(), "%s: %ld %s in %.2f s (%.0f %s/s)%s\n", p->what, p->done, p->unit, secs,
		secs > 0.0 ? (double)p->done / secs : 0.0, p->unit, extra ? extra : "");
}
