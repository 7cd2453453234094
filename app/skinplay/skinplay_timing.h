/* skinplay --report-timing: where a frame's time goes on this board, per
 * stage, as mean and worst over the run, printed at the end, so a kiosk
 * builder sees which stage to shrink (a smaller mesh, GPU skinning, a
 * smaller screen). */
#ifndef SKINPLAY_TIMING_H
#define SKINPLAY_TIMING_H

#include <stdint.h>

typedef enum stage {
	STAGE_DECODE,   /* the frame read (stream or image block) */
	STAGE_FK,       /* forward kinematics */
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
	uint64_t this_frame[STAGE_COUNT];
} stage_times;

/* Adds ns to stage s of the frame being made. */
void stage_add(stage_times *t, stage s, uint64_t ns);
/* Closes frame number `frame`: its stages count toward mean and worst. */
void stage_frame_done(stage_times *t, long frame);
/* The table on stderr. */
void stage_report(const stage_times *t);

#endif
