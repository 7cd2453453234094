/* Mesh files for both programs: OBJ in, through the core parser, errors
 * reported as FILE:LINE: message (skintool writes OBJ: tool_body_out.h). */
#ifndef SETUP_MESH_IO_H
#define SETUP_MESH_IO_H

#include "mesh.h"
#include "obj.h"

/* Loads an OBJ, keeping only the faces of group when it is not NULL.
 * Returns the parser's work area (vertex mapping in ->source, counts,
 * groups), or NULL after reporting the error (*group_missing, when not
 * NULL, then says whether it was that the group has no faces). The work area is the start-up scratch
 * (setup_scratch.h): valid until the next call or the next binding step. */
const obj_work *setup_load_obj(const char *path, const char *group, mesh *out, int *group_missing);

/* What the first comment of `skintool mannequin`'s OBJ says: a mesh that
 * starts with it is bound like the generated body (balanced by default). */
#define TOOL_GENERATED_BODY "skintool mannequin, the generated body"

/* 1 when path starts with that comment. */
int setup_obj_is_generated(const char *path);

#endif
