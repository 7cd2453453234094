/* Skin weights as CSV, the exchange format of `skintool bind`:
 *   vertex,bone,weight
 *   0,lfemur,0.75
 *   0,ltibia,0.25
 * vertex: 0-based index in the mesh's kept vertex order; bone: the ASF
 * name, or `root`; at most SKP_MAX_INFLUENCES rows per vertex, in any
 * order. Blank lines and `#` comments are skipped. The writer lives in the
 * front end (setup_weights.h): the core has no stdio. */
#ifndef WEIGHTS_CSV_H
#define WEIGHTS_CSV_H

#include "skel.h"
#include "skin_weights.h"
#include "skp_error.h"
#include "text_lines.h"

/* How far a vertex's weights may sum from 1 and still be re-normalised. */
#define WEIGHTS_CSV_SUM_TOLERANCE 1e-3

/* Reads the weights of vert_count vertices into out. Errors name the line
 * (unknown bone, bad number, negative weight, vertex out of range, more
 * than SKP_MAX_INFLUENCES rows or the same bone twice for a vertex, bad
 * header) or the vertex (no rows; weights not summing to 1 within the
 * tolerance). Each vertex's weights are re-normalised to sum 1. */
skp_status weights_csv_read(text_lines *tl, const skel *s, int vert_count,
			    skin_weights *out, skp_error *err);

#endif
