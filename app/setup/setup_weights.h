/* Skin weights files for both programs: the CSV of weights_csv.h read
 * through the core parser, errors reported as FILE:LINE: message
 * (skintool writes it: tool_body_out.h). */
#ifndef SETUP_WEIGHTS_H
#define SETUP_WEIGHTS_H

#include "skel.h"
#include "skin_weights.h"

/* Reads and validates the weights of vert_count vertices (weights_csv_read).
 * Returns 0, or -1 after reporting the error. */
int setup_load_weights(const char *path, const skel *s, int vert_count, skin_weights *out);

#endif
