/* The joints of a skeleton named for people ("LEFT ELBOW", "NECK"), for
 * the screen and the report: the joint at bone b's head, where b meets its
 * parent. Names come from the bones' roles (skel_roles.h) and their place
 * in the limb, not from the bones' names, so CMU's lradius, a BVH's
 * LeftForeArm and Mixamo's mixamorig:LeftForeArm all give LEFT ELBOW; the
 * side is read from the name (l/L, left, _L, .L) and, failing that, from
 * where the joint lies (a body facing +z has its left at +x). */
#ifndef SKEL_JOINTS_H
#define SKEL_JOINTS_H

#include <stddef.h>
#include <stdint.h>

#include "skel_roles.h"

typedef enum skel_joint_kind {
	JOINT_OTHER, JOINT_HIPS, JOINT_BACK, JOINT_CHEST, JOINT_NECK, JOINT_HEAD,
	JOINT_COLLAR, JOINT_SHOULDER, JOINT_ELBOW, JOINT_WRIST, JOINT_HAND, JOINT_FINGERS, JOINT_THUMB,
	JOINT_PELVIS, JOINT_HIP, JOINT_KNEE, JOINT_ANKLE, JOINT_TOES,
	JOINT_UPPER_ARM, JOINT_FOREARM, JOINT_THIGH, JOINT_SHIN, /* twist bones: mid-limb */
	JOINT_KIND_COUNT
} skel_joint_kind;

typedef enum skel_side { SIDE_NONE, SIDE_LEFT, SIDE_RIGHT } skel_side;

typedef struct skel_joints {
	int count;
	int biped;                     /* 0: not a human's: joints go by their bones' names */
	const skel *skel;
	uint8_t kind[SKP_MAX_BONES];   /* skel_joint_kind of the joint at the bone's head */
	uint8_t side[SKP_MAX_BONES];   /* skel_side */
} skel_joints;

/* Names every joint of s as bound in pose p (a standing body). */
void skel_joints_find(const skel *s, const skel_pose *p, skel_joints *out);

/* "LEFT ELBOW", "NECK", ... into buf (at most cap bytes); on a skeleton
 * that is not a human's the bone's name in capitals; "JOINT" for a bone
 * out of range. Returns buf. */
const char *skel_joint_name(const skel_joints *j, int bone, char *buf, size_t cap);

/* How far the joint at bone b's head has turned, as a visitor would
 * check it with a protractor, in degrees (0..180). The twist: about the
 * bone's axis since the bind pose, against the nearest ancestor that is
 * another joint (the neck's bones count as one). The bend of a person's
 * elbow or knee: the angle between its two bones now (0 straight, 150 a
 * tight curl), whatever the bind pose's; of a shoulder or hip: the limb's
 * angle from hanging down the torso (0 at the side); of any other joint,
 * and on a skeleton that is not a human's, the swing of the bone's axis
 * since the bind pose against that ancestor's. The swing as well, for
 * every joint: whether it moved. */
typedef struct skel_joint_turn {
	float bend, twist;
	float swing;
} skel_joint_turn;

skel_joint_turn skel_joint_turned(const skel *s, const skel_joints *j, const skel_pose *bind, const skel_pose *pose,
				  int bone);

/* The joint to tell of where the skin at bone's joint changed: that
 * joint, or its parent joint when that one moved (swing or twist since
 * the bind pose) 30 degrees or more and it did not (the skin between
 * CMU's wrist and hand is nearest the hand's joint, the twist is the
 * wrist's). Its turn into *t. */
int skel_joint_turning(const skel *s, const skel_joints *j, const skel_pose *bind, const skel_pose *pose, int bone,
		       skel_joint_turn *t);

/* What a turn shows: a twist of 30 degrees or more and no less than the
 * bend, else a bend of 30 or more, else nothing to say. */
typedef enum skel_turn_kind { SKEL_TURN_SLIGHT, SKEL_TURN_TWIST, SKEL_TURN_BEND } skel_turn_kind;

/* Its kind, and "TWISTED 178 DEG", "BENT 150 DEG" or "" into buf (at most
 * cap bytes); *degrees the angle said (0 when slight). */
skel_turn_kind skel_joint_turn_say(skel_joint_turn t, char *buf, size_t cap, int *degrees);

#endif
