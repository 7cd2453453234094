/* A MakeHuman rig over its base mesh: the skeleton file (.mhskel: bones
 * with their parents, each bone's head a joint placed at the mean of a
 * list of base-mesh vertices) and the weights file it names (.mhw: per
 * bone, [vertex, weight] pairs). Both are JSON (rig_json.h) and index the
 * OBJ's `v` lines from 0, so they fit the mesh they were made for (the
 * base mesh, or an export that kept its vertices): a vertex beyond the
 * file's is an error. Weights of vertices the mesh left out (the helper
 * geometry beside MakeHuman's body group) are skipped. */
#ifndef RIG_MAKEHUMAN_H
#define RIG_MAKEHUMAN_H

#include "obj.h"
#include "rig_json.h"
#include "rig_scene.h"

/* Fills out's joints from the skeleton (root: the parsed .mhskel) in the
 * file's order, each at its joint's place among obj's file vertices; out
 * keeps its mesh (the OBJ obj parsed) and loses any weights. *weights_file
 * is the weights file it names (owned by root), or NULL. Errors name the
 * bone or joint and what was expected. */
skp_status rig_mh_skeleton(json_object *root, const obj_work *obj, rig_scene *out, const char **weights_file,
			   skp_error *err);

/* Adds the weights (root: the parsed .mhw) to out's mesh vertices, which
 * obj maps to the file's (obj->source). Errors name the bone and entry. */
skp_status rig_mh_weights(json_object *root, const obj_work *obj, rig_scene *out, skp_error *err);

#endif
