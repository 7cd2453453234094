/* Shared by both programs (skinplay, skintool): loading skeletons and
 * motion, and reporting errors as FILE:LINE: message on stderr. */
#ifndef CLI_COMMON_H
#define CLI_COMMON_H

#include "amc.h"
#include "bvh.h"
#include "file_reader.h"
#include "skel.h"
#include "skp_error.h"
#include "text_lines.h"

/* Prints "FILE:LINE: message" (or "FILE: message" without a line). */
void cli_error(const char *path, const skp_error *err);

/* Loads a skeleton: an ASF, or the HIERARCHY of a BVH (by the name's
 * .bvh); on failure reports and returns -1 (cli_motion.c). */
int cli_load_skel(const char *path, skel *out);

/* Motion opened for streaming against s: an AMC, or a BVH whose
 * HIERARCHY must be s's. */
typedef struct cli_motion {
	const char *path;
	file_reader file;
	text_lines lines;
	int is_bvh;
	amc_stream stream;
	bvh_stream bvh;
	bvh_layout layout;
	skel bvh_skel;          /* the BVH's own, checked against s */
	int warned_cut;         /* the cut-short end was reported */
} cli_motion;

int cli_motion_open(cli_motion *m, const char *path, const skel *s);
/* 1 frame, 0 end, -1 error (already reported). */
int cli_motion_next(cli_motion *m, amc_frame *f);
/* The same with the error in err, not reported (warnings about a file cut
 * short are printed, once). */
int cli_motion_read(cli_motion *m, amc_frame *f, skp_error *err);
void cli_motion_close(cli_motion *m);

/* Streams the whole file: its frame count, or -1 (reported). */
long cli_motion_count(const char *path, const skel *s);

/* Reads frame number (as written in the file; < 0: the first frame) of the
 * AMC at path into f. Returns 0, or -1 after reporting the error (naming
 * the frames the file has when number is not one of them). */
int cli_read_frame(const char *path, const skel *s, long number, amc_frame *f);

/* Puts arg into the first of the n slots still NULL; -1 after reporting
 * "CMD: unexpected argument" when every slot is taken. */
int cli_take_positional(const char *cmd, const char **const *slots, int n, const char *arg);

/* A BVH carries its skeleton: "MOTION.bvh" stands for "SKELETON.asf
 * MOTION.amc". Given the positional slots as a command filled them, in
 * order (skeleton, motion, and the slot after the motion or NULL), puts
 * the BVH in both the skeleton's and the motion's place and moves what the
 * user gave next into the slot after. */
void cli_bvh_slots(const char **skeleton, const char **motion, const char **next);

/* The file name of path without its folders. */
const char *cli_basename(const char *path);

/* Parses a whole decimal integer argument; -1 (reported) when it is not. */
int cli_parse_long(const char *opt, const char *text, long *out);

#endif
