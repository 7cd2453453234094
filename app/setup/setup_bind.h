/* Binding at start-up: the skeleton, the mesh (picked, placed, posed),
 * the weights (computed, read, or the rigged mesh's own) and the quality
 * gate, from the options a command parsed (cli_bind_args.h) into the bound
 * body the frame path plays (runtime_body.h). */
#ifndef SETUP_BIND_H
#define SETUP_BIND_H

#include "cli_bind_args.h"
#include "runtime_body.h"

/* Loads skeleton asf, mesh obj (group), the bind pose, fits the mesh when
 * asked, then computes the weights (default bind_params) or reads them,
 * and checks the result (setup_gate.h): a failing bind is refused.
 * obj NULL or BIND_MESH_GENERATED: the generated body (skintool mannequin)
 * in the rest pose with its arms out (skel_tpose.h), which is then the
 * bind pose (a file of that name is ./generated).
 * Returns 0, or -1 after reporting the error on stderr. */
#define BIND_MESH_GENERATED "generated"
int setup_bind_load(const bind_args *a, const char *asf, const char *obj, bound_body *body);

/* The steps setup_bind_load takes that a rigged mesh's importer (skintool's
 * app/import: rig_bind_load) takes too, around its own: the skeleton and
 * the pose asked for (0, or -1 after reporting), and 1 when obj is a mesh
 * for the importer (glTF, FBX, COLLADA, or an OBJ with --rig): this
 * program (skinplay) refuses it, saying to pack it with skintool. The
 * quality gate after is setup_gate.h's. */
int setup_bind_begin(const bind_args *a, const char *asf, bound_body *body);
int setup_bind_rigged(const bind_args *a, const char *obj);

/* 1 when path names a mesh the importer reads rather than an OBJ. */
int setup_bind_is_interchange(const char *path);

/* The paper's weights (balanced when asked, or by default for the
 * generated body) on body->mesh in body->pose. Returns 0, or -1 after
 * reporting the error. */
int setup_bind_auto_weights(const bind_args *a, int generated, const char *name, bound_body *body);

/* The weights file's (--weights W.csv) when given, else as
 * setup_bind_auto_weights. Returns 0, or -1 after reporting the error. */
int setup_bind_weights(const bind_args *a, int generated, const char *name, bound_body *body);

#endif
