/* An AMC or BVH file as the playback engine's source (app/play): its
 * frames streamed from the file, counted by a first pass, at the BVH's
 * Frame Time or, for AMC (which does not say), the rate given (--fps,
 * default 120: the CMU rate). Going back reopens the file and reads
 * forward: a text stream has no index. */
#ifndef CLI_CLIP_SOURCE_H
#define CLI_CLIP_SOURCE_H

#include "cli_common.h"
#include "play_source.h"

#define CLI_DEFAULT_FPS 120.0

typedef struct cli_clip_source {
	cli_motion m;
	const char *path;
	const skel *s;
	long next;               /* index of the frame next() returns */
	int open;
} cli_clip_source;

/* Opens path against s. Returns 0 with *out ready, or -1 after reporting
 * (a file that cannot be read, no frames, a BVH Frame Time out of range). */
int cli_clip_source_open(cli_clip_source *c, const char *path, const skel *s, double amc_fps, play_source *out);
void cli_clip_source_close(cli_clip_source *c);

#endif
