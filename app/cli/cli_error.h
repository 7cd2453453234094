/* Messages of both programs (skintool, skinplay): an error as FILE:LINE:
 * message (or FILE: block N: message) on stderr, and text from the
 * command line or a file shown with its control bytes escaped. */
#ifndef CLI_ERROR_H
#define CLI_ERROR_H

#include "skp_error.h"

/* Prints "FILE:LINE: message" (or "FILE: message" without a line), the
 * path's control characters as \xNN. */
void cli_error(const char *path, const skp_error *err);

/* Prints "PATH: cannot DOING: why" for a call that returned rc, a
 * negative errno ("open", "create", "write"). */
void cli_error_errno(const char *path, const char *doing, int rc);

/* text (a path or name from the command line or a file) with its control
 * characters as \xNN, for messages: in one of 4 rotating buffers, cut to
 * 1023 bytes. */
const char *cli_shown(const char *text);

/* The file name of path without its folders. */
const char *cli_basename(const char *path);

#endif
