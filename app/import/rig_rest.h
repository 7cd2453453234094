/* A rigged file's rest pose, as the file's own node hierarchy puts it:
 * every skinned vertex posed by its bones' nodes (node transform x offset
 * matrix, weighted), and every joint at its node. The importer takes it
 * when the skin's bind pose is no pose of the skeleton (a part bound
 * elsewhere: BCN_Epileptic.X's head, half a body away from its neck),
 * which brings the part to its place as any viewer of the file shows it.
 * Parts without a skin follow the nearest joint above them (a helmet, a
 * prop in a hand). Private to the importer: it speaks the asset library's
 * types. */
#ifndef RIG_REST_H
#define RIG_REST_H

#include <assimp/scene.h>

#include "rig_scene.h"

/* A node's or bone's name as joints are named: control characters as \xNN
 * (names are printed), at most RIG_NAME - 1 bytes. */
void rig_rest_name(char *dst, const struct aiString *s);

/* The joint node named name (the first without meshes, else the first),
 * or NULL. */
const struct aiNode *rig_rest_node(const struct aiScene *scene, const char *name);

/* The node's transform in the scene's space (its ancestors' applied). */
struct aiMatrix4x4 rig_rest_global(const struct aiNode *node);

/* The n = am->mNumVertices vertices of a skinned mesh in the rest pose
 * into out; vertices without a weight take node_m, the mesh node's
 * transform. scratch holds n floats. */
void rig_rest_skin(const struct aiScene *scene, const struct aiMesh *am, const struct aiMatrix4x4 *node_m,
		   vec3 *out, float *scratch);

/* 1 when node is the node of one of r's joints. */
int rig_rest_is_joint(const struct aiScene *scene, const rig_scene *r, const struct aiNode *node);

/* The joint a part under node follows: the nearest node at or above it
 * that is one of r's joints, or -1. */
int rig_rest_joint_above(const struct aiScene *scene, const rig_scene *r, const struct aiNode *node);

#endif
