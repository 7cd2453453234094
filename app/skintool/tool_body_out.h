/* The bound body's text files skintool writes: the mesh as an OBJ
 * (skintool mannequin, skin --out) and the weights as the CSV of
 * weights_csv.h (skintool bind --out), each into an atomic file
 * (cli_text_out.h). */
#ifndef TOOL_BODY_OUT_H
#define TOOL_BODY_OUT_H

#include "mesh.h"
#include "skel.h"
#include "skin_weights.h"

/* Writes a first comment "# WHAT: N vertices, M triangles" (what NULL:
 * "skinplay mesh"), v (9 significant digits), vn and `f a//a b//b c//c`
 * lines. Returns 0, or -1 after reporting the error. */
int tool_write_obj(const char *path, const mesh *m, const char *what);

/* Writes `vertex,bone,weight` then one row per influence (weights with 9
 * significant digits, enough to round-trip a float). path "-" is stdout.
 * Returns 0, or -1 after reporting the error. */
int tool_write_weights(const char *path, const skel *s, const skin_weights *w);

#endif
