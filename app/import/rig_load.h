/* skintool's mesh importer: a rigged glTF, FBX or
 * COLLADA body onto an ASF or BVH skeleton, each decision said on stderr:
 *   1. read it (rig_scene.h), the parts used named;
 *   2. map its joints (rig_map.h, --joint-map FILE), the unmapped listed;
 *   3. turn, scale and move it onto the skeleton by the mapped joints
 *      (rig_align.h; --no-fit keeps it as it is);
 *   4. pose the skeleton as the mesh stands (rig_pose.h), unless
 *      --bind-pose names a pose;
 *   5. weights: the mesh's own (--weights mesh, rig_weights.h) or computed.
 * A mesh without a skin, or whose joints do not map, is bound like an OBJ
 * of one's own (setup_mesh_place.h) with computed weights; --weights mesh
 * then fails with the report. */
#ifndef RIG_LOAD_H
#define RIG_LOAD_H

#include "cli_bind_args.h"
#include "runtime_body.h"

/* Returns 0, or -1 after reporting the error. */
int rig_load_mesh(const bind_args *a, const char *path, bound_body *body);

/* skintool's binding: setup_bind_load (app/setup) for an OBJ and the
 * generated body; a rigged mesh (glTF, FBX, COLLADA, an OBJ with --rig)
 * through rig_load_mesh between setup's first step and its quality gate.
 * The importer calls setup, never the other way. Returns 0, or -1 after
 * reporting the error. */
int rig_bind_load(const bind_args *a, const char *asf, const char *obj, bound_body *body);

/* After rig_bind_load, for an image or a render: the texture the GPU
 * draws (rig_colour.h) encoded into body->texture (rig_texture.h), said
 * on stderr; when that fails, a warning, and it is baked into the vertex
 * colours. Nothing to do for a body without one. */
void rig_load_texture(const char *path, bound_body *body);

#endif
