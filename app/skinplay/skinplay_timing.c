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
}

void stage_frame_done(stage_times *t, long frame)
{
	for (int s = 0; s < STAGE_COUNT; s++) {
		uint64_t ns = t->this_frame[s];
		t->sum[s] += ns;
		t->window[s] += ns;
		if (ns > t->worst[s] || !t->frames) {
			t->worst[s] = ns;
			t->worst_frame[s] = frame;
		}
		t->this_frame[s] = 0;
	}
	t->frames++;
	t->window_frames++;
}

static double mean_ms(const uint64_t *sum, long frames, stage first, stage last)
{
	uint64_t ns = 0;
	for (int s = first; s <= (int)last; s++)
		ns += sum[s];
	return frames > 0 ? (double)ns * 1e-6 / (double)frames : 0.0;
}

double stage_window_ms(const stage_times *t, stage first, stage last)
{
	return mean_ms(t->window, t->window_frames, first, last);
}

double stage_run_ms(const stage_times *t, stage first, stage last)
{
	return mean_ms(t->sum, t->frames, first, last);
}

double stage_window_fps(const stage_times *t, uint64_t now_ns)
{
	return now_ns > t->window_ns ? (double)t->window_frames / ((double)(now_ns - t->window_ns) * 1e-9) : 0.0;
}

void stage_window_reset(stage_times *t, uint64_t now_ns)
{
	memset(t->window, 0, sizeof t->window);
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
			(double)t->sum[s] * 1e-6 / (double)t->frames, (double)t->worst[s] * 1e-6, t->worst_frame[s],
			total > 0 ? 100.0 * (double)t->sum[s] / total : 0.0);
	fprintf(stderr, "  %-20s %10.3f\n", "frame", total * 1e-6 / (double)t->frames);
}
