#include "skinplay_timing.h"

#include <stdio.h>

static const char *const stage_name[STAGE_COUNT] = {
	"decode", "forward kinematics", "bone transforms", "skinning (CPU)", "upload", "draw", "swap / present",
};

void stage_add(stage_times *t, stage s, uint64_t ns)
{
	t->this_frame[s] += ns;
}

void stage_frame_done(stage_times *t, long frame)
{
	for (int s = 0; s < STAGE_COUNT; s++) {
		uint64_t ns = t->this_frame[s];
		t->sum[s] += ns;
		if (ns > t->worst[s] || !t->frames) {
			t->worst[s] = ns;
			t->worst_frame[s] = frame;
		}
		t->this_frame[s] = 0;
	}
	t->frames++;
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
