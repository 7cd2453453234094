#include "skinplay_timing.h"

#include <stdio.h>
#include <string.h>

static const char *const stage_name[STAGE_COUNT] = {
	"decode and pose", "bone transforms", "skinning (CPU)", "upload", "draw", "swap / present",
};

void stage_start(stage_times *t, uint64_t now_ns)
{
	memset(t, 0, sizeof *t);
	t->start_ns = t->window_ns = now_ns;
}

void stage_add(stage_times *t, stage s, uint64_t ns)
{
	t->this_frame[s] += ns;
	t->this_ran[s] = 1;
}

void stage_frame_done(stage_times *t, long frame)
{
	for (int s = 0; s < STAGE_COUNT; s++) {
		uint64_t ns = t->this_frame[s];
		if (!t->this_ran[s])
			continue;
		t->sum[s] += ns;
		t->window[s] += ns;
		if (ns > t->worst[s] || !t->ran[s]) {
			t->worst[s] = ns;
			t->worst_frame[s] = frame;
		}
		t->ran[s]++;
		t->window_ran[s]++;
		t->this_frame[s] = 0;
		t->this_ran[s] = 0;
	}
	t->frames++;
	t->window_frames++;
}

static double mean_ms(const uint64_t *sum, const long *ran, stage first, stage last)
{
	double ms = 0;
	for (int s = first; s <= (int)last; s++)
		ms += ran[s] > 0 ? (double)sum[s] * 1e-6 / (double)ran[s] : 0.0;
	return ms;
}

double stage_window_ms(const stage_times *t, stage first, stage last)
{
	return mean_ms(t->window, t->window_ran, first, last);
}

double stage_run_ms(const stage_times *t, stage first, stage last)
{
	return mean_ms(t->sum, t->ran, first, last);
}

double stage_window_fps(const stage_times *t, uint64_t now_ns)
{
	return now_ns > t->window_ns ? (double)t->window_frames / ((double)(now_ns - t->window_ns) * 1e-9) : 0.0;
}

void stage_window_reset(stage_times *t, uint64_t now_ns)
{
	memset(t->window, 0, sizeof t->window);
	memset(t->window_ran, 0, sizeof t->window_ran);
	t->window_frames = 0;
	t->window_ns = now_ns;
}

void stage_report(const stage_times *t)
{
	if (!t->frames)
		return;
	double total = 0;
	for (int s = 0; s < STAGE_COUNT; s++)
		total += (double)t->sum[s];
	fprintf(stderr, "timing over %ld frames (mean and worst per stage; the worst frame's number):\n", t->frames);
	fprintf(stderr, "  %-20s %10s %10s %8s %7s\n", "stage", "mean ms", "worst ms", "frame", "share");
	for (int s = 0; s < STAGE_COUNT; s++)
		fprintf(stderr, "  %-20s %10.3f %10.3f %8ld %6.1f%%\n", stage_name[s],
			stage_run_ms(t, (stage)s, (stage)s), (double)t->worst[s] * 1e-6, t->worst_frame[s],
			total > 0 ? 100.0 * (double)t->sum[s] / total : 0.0);
	fprintf(stderr, "  %-20s %10.3f\n", "frame", total * 1e-6 / (double)t->frames);
	if (t->ran[STAGE_DRAW] < t->frames)
		fprintf(stderr, "  (%ld of the %ld frames drawn, the ones written: upload, draw and swap are their means)\n",
			t->ran[STAGE_DRAW], t->frames);
}
