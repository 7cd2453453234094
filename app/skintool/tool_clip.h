/* A motion file held whole in memory (the host tool may allocate): what
 * the encoder takes and what decoded frames are measured against. */
#ifndef TOOL_CLIP_H
#define TOOL_CLIP_H

#include "skel.h"

typedef struct tool_clip {
	float *frames;          /* n x dof_count values, as amc_frame.value */
	long n;
	int dofs;
	long first_number;
	double rate;            /* a BVH's own frame rate, 0 for an AMC */
} tool_clip;

/* Reads every frame of path (AMC or BVH) against s; -1 after reporting. */
int tool_clip_load(const char *path, const skel *s, tool_clip *c);
void tool_clip_free(tool_clip *c);


#endif
