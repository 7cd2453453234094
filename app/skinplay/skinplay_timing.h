/* Where a frame's time goes, per stage: the one record of skinplay's
 * timings. The status line reads the last second's means (stage_window_*),
 * the summary line the run's, and --report-timing prints every stage's
 * mean and worst over the run at the end, so a kiosk builder sees which
 * stage to shrink (a smaller mesh, GPU skinning, a smaller screen). */
#ifndef SKINPLAY_TIMING_H
#define SKINPLAY_TIMING_H

#include <stdint.h>

typedef enum stage {
	STAGE_POSE,     /* the pose at the frame's time: frames read (stream or
	                 * image block), interpolated, forward kinematics */
	STAGE_BONES,    /* bone transforms for the kernels */
	STAGE_SKIN,     /* the skinning kernels (CPU) */
	STAGE_UPLOAD,   /* vertices to the GPU */
	STAGE_DRAW,     /* draw calls until the GPU is done */
	STAGE_SWAP,     /* present (page flip, swap, PNG read-back) */
	STAGE_COUNT
} stage;

typedef struct stage_times {
	uint64_t sum[STAGE_COUNT], worst[STAGE_COUNT];
	long worst_frame[STAGE_COUNT];
	long frames;
	long ran[STAGE_COUNT];             /* frames in which the stage ran */
	uint64_t start_ns;                 /* the run's start */
	uint64_t window[STAGE_COUNT];      /* since window_ns */
	long window_frames, window_ran[STAGE_COUNT];
	uint64_t window_ns;
	uint64_t this_frame[STAGE_COUNT];
	unsigned char this_ran[STAGE_COUNT];
} stage_times;

/* A new run (and window) starting at now_ns. */
void stage_start(stage_times *t, uint64_t now_ns);
/* Adds ns to stage s of the frame being made. */
void stage_add(stage_times *t, stage s, uint64_t ns);
/* Closes frame number `frame`: its stages count toward the run's mean and
 * worst and the window's mean. */
void stage_frame_done(stage_times *t, long frame);
/* Mean ms a frame of stages first..last (inclusive), over the window or
 * over the run; 0 without frames. Each stage's mean is over the frames in
 * which it ran: a headless run draws only the frames it writes, and their
 * draw time is not spread over the frames it did not draw. */
double stage_window_ms(const stage_times *t, stage first, stage last);
double stage_run_ms(const stage_times *t, stage first, stage last);
/* Frames a second over the window ending at now_ns; then a new window. */
double stage_window_fps(const stage_times *t, uint64_t now_ns);
void stage_window_reset(stage_times *t, uint64_t now_ns);
/* The table on stderr. */
void stage_report(const stage_times *t);

#endif
