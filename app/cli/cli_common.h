/* Shared by both programs (skinplay, skintool): reporting errors as
 * FILE:LINE: message on stderr, and the positional arguments' helpers.
 * (Skeletons and motion files: app/runtime/motion_file.h.) */
#ifndef CLI_COMMON_H
#define CLI_COMMON_H

#include "skp_error.h"

/* Prints "FILE:LINE: message" (or "FILE: message" without a line), the
 * path's control characters as \xNN. */
void cli_error(const char *path, const skp_error *err);

/* text (a path or name from the command line or a file) with its control
 * characters as \xNN, for messages: in one of 4 rotating buffers, cut to
 * 1023 bytes. */
const char *cli_shown(const char *text);

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
