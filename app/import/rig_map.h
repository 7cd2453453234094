/* Which bone of the skeleton (ASF or BVH) each joint of a rigged mesh
 * moves with.
 *
 * On the mesh, joint names say what limbs are (rig_names.h); the hips are
 * the joint both thighs hang from, the head the joint named head or else
 * the end of the unsided chain above the clavicles (Rigify's spine.005).
 * On the skeleton, whose names differ between exporters, the parts come
 * from its shape (skel_roles.h): in each limb branch the upper bone is the
 * first at least 0.6 times as long as the branch's longest, the next
 * non-zero bones the forearm or shin, then the hand (the first bone that
 * branches into fingers) and the fingers (the bone on from it) or the foot
 * and toes, and a bone before the upper arm the clavicle; left is up x
 * front, front the way the feet point.
 * Limb joints map to the skeleton bone of the same part and side; the
 * spine chain between hips and head maps by where each joint sits along
 * it onto the skeleton's chain from the root to its head bone, the chest
 * (where the arms hang from) matched to the chest: the hips-chest and
 * chest-head stretches each scaled to the skeleton's. A map file (rig_map_file.h) overrides any of it.
 *
 * A joint left unmapped (the thumb, the fingers' and toes' further
 * joints, twist bones, face, helpers) moves with
 * its nearest mapped ancestor, or with the root. */
#ifndef RIG_MAP_H
#define RIG_MAP_H

#include <stdint.h>

#include "fk.h"
#include "rig_names.h"
#include "rig_scene.h"

typedef struct rig_skel_parts {
	int bone[3][RIG_SLOT_COUNT];    /* [rig_side][rig_slot], -1 when none */
	int spine[SKP_MAX_BONES];       /* root ... head bone */
	int spine_count;
	int chest;                      /* the spine bone the arms hang from, or -1 */
	vec3 up, front, left;
} rig_skel_parts;

typedef struct rig_map_entry {
	char joint[RIG_NAME];
	char bone[SKP_MAX_NAME];        /* "-": leave the joint unmapped */
	long line;
} rig_map_entry;

#define RIG_MAP_MAX_ENTRIES RIG_MAX_JOINTS

typedef struct rig_map_file {
	int count;
	rig_map_entry entry[RIG_MAP_MAX_ENTRIES];
} rig_map_file;

typedef struct rig_map {
	int bone[RIG_MAX_JOINTS];       /* the skeleton bone it maps to, or -1 */
	int follow[RIG_MAX_JOINTS];     /* the bone it moves with */
	int via[RIG_MAX_JOINTS];        /* the mapped ancestor it follows, -1: itself or the root */
	uint8_t beside[RIG_MAX_JOINTS]; /* 1: via is no ancestor but the mapped joint nearest it */
	rig_name name[RIG_MAX_JOINTS];
	int by_file[RIG_MAX_JOINTS];
	int mapped;                     /* joints with a bone */
	int hips, chest, head;          /* mesh joints, -1 when not found */
	int family;                     /* the spelling most names matched (rig_family_name) */
	int limbs;                      /* of the 4 limbs, those whose upper and lower parts mapped */
	rig_skel_parts parts;
} rig_map;

/* The skeleton's parts in pose p. */
void rig_find_skel_parts(const skel *s, const skel_pose *p, rig_skel_parts *out);

/* Maps the joints of r onto s posed as p; file (may be NULL) overrides.
 * Fails when the file names a joint or bone that is not there. */
skp_status rig_map_joints(const rig_scene *r, const skel *s, const skel_pose *p,
			  const rig_map_file *file, rig_map *out, skp_error *err);

/* The mesh joint mapped to the skeleton part (side, slot), or -1. */
int rig_map_part_joint(const rig_map *m, const rig_scene *r, rig_side side, rig_slot slot);

/* Where the part starts on the mesh: the mean head of its shallowest
 * mapped joints (the knuckles of a hand's four fingers, the bases of
 * MakeHuman's five toes). 0 when it is not mapped. */
int rig_map_part_head(const rig_map *m, const rig_scene *r, rig_side side, rig_slot slot, vec3 *head);

#endif
