/* An AMC or BVH file as the playback engine's source (app/play): its
 * frames streamed from the file, counted by a first pass, at the BVH's
 * Frame Time or, for AMC (which does not say), the rate given (--fps,
 * default 120: the CMU rate). Going back reopens the file and reads
 * forward: a text stream has no index. */
#ifndef CLIP_FILE_H
#define CLIP_FILE_H

#include "motion_file.h"
#include "play_source.h"

#define CLI_DEFAULT_FPS 120.0

typedef struct clip_file {
	motion_file m;
	const char *path;
	const skel *s;
	long next;               /* index of the frame next() returns */
	int open;
} clip_file;

/* Opens path against s. Returns 0 with *out ready, or -1 after reporting
 * (a file that cannot be read, no frames, a BVH Frame Time out of range). */
int clip_file_open(clip_file *c, const char *path, const skel *s, double amc_fps, play_source *out);
void clip_file_close(clip_file *c);

#endif
