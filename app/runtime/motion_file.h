/* Motion for the programs: a skeleton and its frames from ASF/AMC or from
 * one BVH file (bvh.h), streamed the same way whatever the format; errors
 * reported as FILE:LINE: message on stderr (cli_error). */
#ifndef MOTION_FILE_H
#define MOTION_FILE_H

#include "amc.h"
#include "bvh.h"
#include "file_reader.h"
#include "skel.h"
#include "skp_error.h"
#include "text_lines.h"

/* Loads a skeleton: an ASF, or the HIERARCHY of a BVH (by the name's
 * .bvh); on failure reports and returns -1 (motion_file.c). */
int motion_load_skel(const char *path, skel *out);

/* Motion opened for streaming against s: an AMC, or a BVH whose
 * HIERARCHY must be s's. */
typedef struct motion_file {
	const char *path;
	file_reader file;
	text_lines lines;
	int is_bvh;
	amc_stream stream;
	bvh_stream bvh;
	bvh_layout layout;
	skel bvh_skel;          /* the BVH's own, checked against s */
	int warned_cut;         /* the cut-short end was reported */
} motion_file;

int motion_file_open(motion_file *m, const char *path, const skel *s);
/* 1 frame, 0 end, -1 error (already reported). */
int motion_file_next(motion_file *m, amc_frame *f);
/* The same with the error in err, not reported (warnings about a file cut
 * short are printed, once). */
int motion_file_read(motion_file *m, amc_frame *f, skp_error *err);
void motion_file_close(motion_file *m);

/* Streams the whole file: its frame count, or -1 (reported). */
long motion_file_count(const char *path, const skel *s);

/* Reads frame number (as written in the file; < 0: the first frame) of the
 * AMC at path into f. Returns 0, or -1 after reporting the error (naming
 * the frames the file has when number is not one of them). */
int motion_read_frame(const char *path, const skel *s, long number, amc_frame *f);

/* A BVH carries its skeleton: "MOTION.bvh" stands for "SKELETON.asf
 * MOTION.amc". Given the positional slots as a command filled them, in
 * order (skeleton, motion, and the slot after the motion or NULL), puts
 * the BVH in both the skeleton's and the motion's place and moves what the
 * user gave next into the slot after. */
void motion_bvh_slots(const char **skeleton, const char **motion, const char **next);

#endif
