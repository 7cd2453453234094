/* When a rig's joint names mean nothing (CesiumMan's torso_joint_1 and
 * arm_joint_L__3_, a Bone.NNN chain), its parts come from the skeleton's
 * shape: a biped's topology and geometry.
 *   - Limbs are mirror pairs: two joints with one parent whose subtrees
 *     have as many joints (within one) and reach as far (within a third),
 *     reaching a quarter of the skeleton's size or more (fingers do not).
 *   - The legs are the pair nearest the root, the arms the pair whose
 *     parent lies below the legs' common parent (or beside it, in a
 *     pelvis-and-spine split); the chest is the arms' parent.
 *   - The head ends the chain that goes on from the chest with one child
 *     a joint, where it branches (a face) or ends.
 *   - Up is hips to chest; front the way the feet point (ankle to toe);
 *     left is up x front.
 *   - Along a leg: the thigh is the first joint whose bone (to the next
 *     joint) is 0.6 of the leg's longest or more, then shin, foot, toe;
 *     along an arm the upper arm is the first such (0.3) bone starting out
 *     to the side of the spine by 0.3 of its length or more, the clavicle
 *     the joint before it, then forearm and hand.
 * A quadruped has the same topology: rig_biped.h tells it by its
 * geometry. */
#ifndef RIG_TOPOLOGY_H
#define RIG_TOPOLOGY_H

#include "rig_names.h"
#include "rig_scene.h"

/* The joints a biped's shape is judged by: the hips (the legs' parent),
 * the chest (the arms'), the head, and the last joint of each leg and
 * arm (by the chain reaching furthest). */
typedef struct rig_shape_parts {
	int hips, chest, head;
	int leg_end[2], arm_end[2];
} rig_shape_parts;

/* 1 when the joints have a biped's topology (two limb pairs and a neck),
 * with out filled; 0 when not. */
int rig_topology_parts(const rig_scene *r, rig_shape_parts *out);

/* Fills names[j] (slot, side, rig RIG_FAMILY_SHAPE) for the joints the
 * shape says are parts; the others get RIG_NONE. Returns the limbs found
 * (0 to 4), 0 when the shape is not a biped's. */
int rig_topology_names(const rig_scene *r, rig_name *names);

#endif
