/* What a joint's name says it is, across the rigs people export: Blender's
 * Rigify metarig (upper_arm.L, thigh.R, spine.003), Mixamo
 * (mixamorig:LeftForeArm, LeftUpLeg), MakeHuman's default skeleton
 * (upperarm01.L, lowerleg01.R), Unreal's (clavicle_l, calf_r), Daz
 * (lShldr, rShin), CMU's own (lhumerus, rtibia). Prefixes before ':' or
 * '|' (namespaces) and DEF-/ORG- go, case does not matter, the side is a
 * suffix (.L _l -left), a prefix (Left, l_, l) or absent. */
#ifndef RIG_NAMES_H
#define RIG_NAMES_H

typedef enum rig_slot {
	RIG_NONE = 0,
	RIG_HEAD,
	RIG_CLAVICLE, RIG_UPPER_ARM, RIG_FOREARM, RIG_HAND,
	RIG_THIGH, RIG_SHIN, RIG_FOOT, RIG_TOE,
	RIG_FINGERS,    /* the first joints of the four fingers, not the thumb's */
	RIG_SLOT_COUNT
} rig_slot;

typedef enum rig_side { RIG_CENTRE = 0, RIG_LEFT = 1, RIG_RIGHT = 2 } rig_side;

typedef struct rig_name {
	rig_slot slot;
	rig_side side;
	int rig;            /* which family's spelling matched (rig_family_name) */
} rig_name;

/* Fills out (slot RIG_NONE when the name is not one of them) and returns
 * its slot. Limbs need a side, the head none. */
rig_slot rig_name_parse(const char *name, rig_name *out);

/* The side the name carries, whatever its slot. */
rig_side rig_name_side(const char *name);

/* rig_name.rig of parts found from the skeleton's shape (rig_topology.h). */
#define RIG_FAMILY_SHAPE (1 << 9)

/* "Rigify", "Mixamo", ... for rig_name.rig. */
const char *rig_family_name(int rig);

/* "upper arm" for a slot, for reports. */
const char *rig_slot_name(rig_slot slot);

#endif
