/* Skin weights files for both programs: the CSV of weights_csv.h written
 * with stdio, and read through the core parser with errors reported as
 * FILE:LINE: message. */
#ifndef SETUP_WEIGHTS_H
#define SETUP_WEIGHTS_H

#include "skel.h"
#include "skin_weights.h"

/* Writes `vertex,bone,weight` then one row per influence (weights with 9
 * significant digits, enough to round-trip a float). path "-" is stdout.
 * Returns 0, or -1 after reporting the error. */
int setup_write_weights(const char *path, const skel *s, const skin_weights *w);

/* Reads and validates the weights of vert_count vertices (weights_csv_read).
 * Returns 0, or -1 after reporting the error. */
int setup_load_weights(const char *path, const skel *s, int vert_count, skin_weights *out);

#endif
