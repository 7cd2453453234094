/* A rigged character read from an interchange file (glTF 2.0, FBX,
 * COLLADA, ...: rig_import.c), before it meets a skeleton: its triangles,
 * its joints with their bind-pose places and hierarchy, and the artist's
 * per-vertex joint weights. Host code: the device reads packed images. */
#ifndef RIG_SCENE_H
#define RIG_SCENE_H

#include <stdint.h>

#include "mesh.h"
#include "skp_error.h"

#define RIG_MAX_JOINTS 256
#define RIG_MAX_INFLUENCES 8    /* per vertex as read; skinning keeps 4 */
#define RIG_MAX_PARTS 64
#define RIG_NAME 64

typedef struct rig_joint {
	char name[RIG_NAME];
	int parent;             /* nearest ancestor that is a joint, or -1 */
	vec3 head;              /* bind-pose origin, scene space */
	int weighted;           /* vertices it has a weight on */
} rig_joint;

typedef struct rig_scene {
	mesh *mesh;             /* the caller's: positions in scene space */
	int joint_count;
	rig_joint joint[RIG_MAX_JOINTS];
	uint8_t infl_count[SKP_MAX_VERTS];
	uint8_t held[SKP_MAX_VERTS];    /* 1: of a part with no joint above it, held by the joint nearest it */
	uint16_t infl_joint[SKP_MAX_VERTS][RIG_MAX_INFLUENCES];
	float infl_weight[SKP_MAX_VERTS][RIG_MAX_INFLUENCES];
	int dropped_influences; /* vertices that had more than RIG_MAX_INFLUENCES */
	int part_count;         /* the file's meshes (primitives) */
	char part[RIG_MAX_PARTS][RIG_NAME];
	int part_used[RIG_MAX_PARTS];
	int part_skinned[RIG_MAX_PARTS];
	int part_joint[RIG_MAX_PARTS];  /* a part without a skin: the joint above it it follows, or -1 */
	int part_near[RIG_MAX_PARTS];   /* one with no joint above it: the deforming joint nearest it, or -1 */
	int welded;             /* vertices merged with an identical one */
	int textured;           /* meshes whose base colour texture was sampled (rig_colour.h) */
	int texture_problems;   /* textures that could not be read: the material's colour used */
	char texture_problem[320]; /* the first, naming texture and material */
	int rest_posed;         /* the skin's bind pose was no pose of its skeleton: the nodes' rest pose taken */
	/* with mesh->textured, the texture the GPU draws (rig_colour.h): RGBA8,
	 * top row first; allocated, freed by the next import or
	 * rig_scene_release */
	uint8_t *texture_rgba;
	int texture_w, texture_h;
	char texture_path[512];
	char texture_material[64];
	/* vertices kept apart from one at their place with the same weights
	 * only because their UVs differ (a seam of the GPU's texture): each
	 * vertex's first such twin, itself when it has none (rig_weld.h) */
	int seams;
	int seam_lead[SKP_MAX_VERTS];
} rig_scene;

/* Reads path: every triangle mesh (only those named group, when not NULL)
 * in the skin's bind pose, each moved by its node's transform (or, when
 * that bind pose is no pose of its skeleton, in the nodes' rest pose:
 * rig_rest.h), a part without a skin weighted wholly to the joint above
 * it, vertices at the same place with the same weights welded (unless
 * their UVs on the GPU's texture differ), and the joints of their skins. Fails with a message naming what went wrong: a file the library
 * cannot read, no triangles, a group that is not there (listing the
 * meshes), too many vertices, joints or triangles. */
skp_status rig_import(const char *path, const char *group, rig_scene *out, skp_error *err);

/* rig_import for a file whose name does not say its format: hint is the
 * extension of the format its content has ("zae" for a zip archive), so
 * the library reads it as that. hint NULL: rig_import. */
skp_status rig_import_as(const char *path, const char *hint, const char *group, rig_scene *out, skp_error *err);

/* Frees what an import allocated (the GPU's texture). */
void rig_scene_release(rig_scene *r);

/* Empties r for a reader to fill: its mesh pointer kept, the rest of its
 * header cleared, what it held released (the influences are the reader's
 * to clear, vertex by vertex). */
void rig_scene_reset(rig_scene *r);

/* Index of the joint named name, or -1. */
int rig_find_joint(const rig_scene *r, const char *name);

/* Adds weight to vertex v's influence of joint (summed when it has one
 * already); beyond RIG_MAX_INFLUENCES the influence is counted as
 * dropped. */
void rig_add_influence(rig_scene *r, int v, int joint, float weight);

#endif
