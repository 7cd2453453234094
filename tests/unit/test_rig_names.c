/* Joint names of the common rigs read as body parts and sides
 * (app/import/rig_names.c), and names that are not parts. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "rig_names.h"

typedef struct case_ {
	const char *name;
	rig_slot slot;
	rig_side side;
} case_;

static void check(const case_ *c, size_t n)
{
	for (size_t i = 0; i < n; i++) {
		rig_name got;
		rig_name_parse(c[i].name, &got);
		if (got.slot != c[i].slot || (got.slot != RIG_NONE && got.side != c[i].side))
			fail_msg("'%s': got %s side %d, want %s side %d", c[i].name, rig_slot_name(got.slot),
				 (int)got.side, rig_slot_name(c[i].slot), (int)c[i].side);
	}
}

static void test_rigify(void **state)
{
	(void)state;
	static const case_ c[] = {
		{ "upper_arm.L", RIG_UPPER_ARM, RIG_LEFT }, { "forearm.R", RIG_FOREARM, RIG_RIGHT },
		{ "hand.L", RIG_HAND, RIG_LEFT }, { "shoulder.R", RIG_CLAVICLE, RIG_RIGHT },
		{ "thigh.L", RIG_THIGH, RIG_LEFT }, { "shin.R", RIG_SHIN, RIG_RIGHT },
		{ "foot.L", RIG_FOOT, RIG_LEFT }, { "toe.R", RIG_TOE, RIG_RIGHT },
		{ "DEF-upper_arm.L", RIG_UPPER_ARM, RIG_LEFT }, { "DEF-thigh.R", RIG_THIGH, RIG_RIGHT },
		/* a finger's first joint is the fingers; the thumb, the fingers'
		 * further joints, twist halves, the spine and helpers are not parts */
		{ "f_index.01.L", RIG_FINGERS, RIG_LEFT }, { "DEF-f_pinky.01.R", RIG_FINGERS, RIG_RIGHT },
		{ "f_index.02.L", RIG_NONE, RIG_CENTRE }, { "thumb.01.L", RIG_NONE, RIG_CENTRE },
		{ "palm.01.L", RIG_NONE, RIG_CENTRE },
		{ "DEF-upper_arm.L.001", RIG_NONE, RIG_CENTRE },
		{ "spine.003", RIG_NONE, RIG_CENTRE }, { "pelvis.L", RIG_NONE, RIG_CENTRE },
		{ "heel.02.L", RIG_NONE, RIG_CENTRE }, { "breast.R", RIG_NONE, RIG_CENTRE },
	};
	check(c, sizeof c / sizeof c[0]);
}

static void test_mixamo_makehuman_unreal_daz_cmu(void **state)
{
	(void)state;
	static const case_ c[] = {
		{ "mixamorig:LeftArm", RIG_UPPER_ARM, RIG_LEFT }, { "mixamorig:RightForeArm", RIG_FOREARM, RIG_RIGHT },
		{ "mixamorig:LeftUpLeg", RIG_THIGH, RIG_LEFT }, { "mixamorig:RightLeg", RIG_SHIN, RIG_RIGHT },
		{ "mixamorig:LeftToeBase", RIG_TOE, RIG_LEFT }, { "mixamorig:LeftShoulder", RIG_CLAVICLE, RIG_LEFT },
		{ "mixamorig:Head", RIG_HEAD, RIG_CENTRE }, { "Armature|mixamorig:LeftHand", RIG_HAND, RIG_LEFT },
		{ "upperarm01.L", RIG_UPPER_ARM, RIG_LEFT }, { "lowerarm01.R", RIG_FOREARM, RIG_RIGHT },
		{ "wrist.L", RIG_HAND, RIG_LEFT }, { "upperleg01.R", RIG_THIGH, RIG_RIGHT },
		{ "lowerleg01.L", RIG_SHIN, RIG_LEFT }, { "clavicle.R", RIG_CLAVICLE, RIG_RIGHT },
		{ "upperarm02.L", RIG_NONE, RIG_CENTRE }, { "metacarpal1.L", RIG_NONE, RIG_CENTRE },
		/* MakeHuman's five toes are the toes, its fingers but the thumb (finger1) the fingers */
		{ "toe1-1.L", RIG_TOE, RIG_LEFT }, { "toe5-1.R", RIG_TOE, RIG_RIGHT }, { "toe1-2.L", RIG_NONE, RIG_CENTRE },
		{ "finger2-1.L", RIG_FINGERS, RIG_LEFT }, { "finger5-1.R", RIG_FINGERS, RIG_RIGHT },
		{ "finger1-1.L", RIG_NONE, RIG_CENTRE }, { "finger2-2.L", RIG_NONE, RIG_CENTRE },
		{ "mixamorig:LeftHandIndex1", RIG_FINGERS, RIG_LEFT }, { "mixamorig:RightHandPinky1", RIG_FINGERS, RIG_RIGHT },
		{ "mixamorig:LeftHandThumb1", RIG_NONE, RIG_CENTRE }, { "mixamorig:LeftHandIndex2", RIG_NONE, RIG_CENTRE },
		{ "index_01_l", RIG_FINGERS, RIG_LEFT }, { "thumb_01_l", RIG_NONE, RIG_CENTRE },
		{ "lIndex1", RIG_FINGERS, RIG_LEFT }, { "rMid1", RIG_FINGERS, RIG_RIGHT }, { "lThumb1", RIG_NONE, RIG_CENTRE },
		{ "lfingers", RIG_FINGERS, RIG_LEFT }, { "LFingers", RIG_FINGERS, RIG_LEFT }, { "lthumb", RIG_NONE, RIG_CENTRE },
		{ "RightFingerBase", RIG_FINGERS, RIG_RIGHT },
		{ "upperarm_l", RIG_UPPER_ARM, RIG_LEFT }, { "calf_r", RIG_SHIN, RIG_RIGHT },
		{ "ball_l", RIG_TOE, RIG_LEFT }, { "clavicle_r", RIG_CLAVICLE, RIG_RIGHT },
		{ "lShldrBend", RIG_UPPER_ARM, RIG_LEFT }, { "rForearmBend", RIG_FOREARM, RIG_RIGHT },
		{ "lCollar", RIG_CLAVICLE, RIG_LEFT }, { "rShin", RIG_SHIN, RIG_RIGHT },
		{ "lhumerus", RIG_UPPER_ARM, RIG_LEFT }, { "rradius", RIG_FOREARM, RIG_RIGHT },
		{ "lfemur", RIG_THIGH, RIG_LEFT }, { "rtibia", RIG_SHIN, RIG_RIGHT }, { "ltoes", RIG_TOE, RIG_LEFT },
		{ "lhipjoint", RIG_NONE, RIG_CENTRE }, { "lowerback", RIG_NONE, RIG_CENTRE },
		{ "Left Arm", RIG_UPPER_ARM, RIG_LEFT }, { "hand-right", RIG_HAND, RIG_RIGHT },
	};
	check(c, sizeof c / sizeof c[0]);
}

static void test_unity_biped_and_joint_names(void **state)
{
	(void)state;
	static const case_ c[] = {
		/* Unity/Mecanim humanoid, in its spellings */
		{ "LeftUpperLeg", RIG_THIGH, RIG_LEFT }, { "RightLowerLeg", RIG_SHIN, RIG_RIGHT },
		{ "UpperLeg.L", RIG_THIGH, RIG_LEFT }, { "LowerLeg.R", RIG_SHIN, RIG_RIGHT },
		{ "UpperArm_l", RIG_UPPER_ARM, RIG_LEFT }, { "LowerArm_r", RIG_FOREARM, RIG_RIGHT },
		{ "LeftShoulder", RIG_CLAVICLE, RIG_LEFT }, { "RightToes", RIG_TOE, RIG_RIGHT },
		{ "Foot.L", RIG_FOOT, RIG_LEFT }, { "Hand.R", RIG_HAND, RIG_RIGHT },
		{ "Hips", RIG_NONE, RIG_CENTRE }, { "Chest", RIG_NONE, RIG_CENTRE }, { "UpperChest", RIG_NONE, RIG_CENTRE },
		/* 3ds Max Biped, Character Creator, joint-named rigs (BCN_Epileptic.X) */
		{ "Bip01 L UpperArm", RIG_UPPER_ARM, RIG_LEFT }, { "Bip01 R Calf", RIG_SHIN, RIG_RIGHT },
		{ "Bip01 L Toe0", RIG_TOE, RIG_LEFT }, { "CC_Base_R_Thigh", RIG_THIGH, RIG_RIGHT },
		{ "Bip01 L Finger1", RIG_FINGERS, RIG_LEFT }, { "Bip01 L Finger0", RIG_NONE, RIG_CENTRE },
		{ "Left Index Proximal", RIG_FINGERS, RIG_LEFT }, { "Right Little Proximal", RIG_FINGERS, RIG_RIGHT },
		{ "Left Thumb Proximal", RIG_NONE, RIG_CENTRE },
		{ "B_UpperArm_Left", RIG_UPPER_ARM, RIG_LEFT }, { "B_Hip_Right", RIG_THIGH, RIG_RIGHT },
		{ "B_Knee_Left", RIG_SHIN, RIG_LEFT }, { "B_Ankle_Right", RIG_FOOT, RIG_RIGHT },
		{ "elbow_l", RIG_FOREARM, RIG_LEFT }, { "B_Spine4", RIG_NONE, RIG_CENTRE },
	};
	check(c, sizeof c / sizeof c[0]);
	rig_name n;
	rig_name_parse("LeftUpperLeg", &n);
	assert_string_equal(rig_family_name(n.rig), "Unity/Mecanim humanoid");
	rig_name_parse("B_Knee_Left", &n);
	assert_string_equal(rig_family_name(n.rig), "joint names (hip, knee, ankle)");
	assert_string_equal(rig_family_name(RIG_FAMILY_SHAPE), "none: the skeleton's shape");
}

static void test_not_parts(void **state)
{
	(void)state;
	/* a limb without a side, a side without a part, empty and odd names */
	static const case_ c[] = {
		{ "arm", RIG_NONE, RIG_CENTRE }, { "leg", RIG_NONE, RIG_CENTRE }, { "Left", RIG_NONE, RIG_CENTRE },
		{ "L", RIG_NONE, RIG_CENTRE }, { "", RIG_NONE, RIG_CENTRE }, { ".L", RIG_NONE, RIG_CENTRE },
		{ "head.L", RIG_NONE, RIG_CENTRE }, { "Bone.001", RIG_NONE, RIG_CENTRE },
		{ "nodes[1]", RIG_NONE, RIG_CENTRE }, { ":::", RIG_NONE, RIG_CENTRE },
	};
	check(c, sizeof c / sizeof c[0]);
	char longname[400];
	memset(longname, 'x', sizeof longname - 1);
	longname[sizeof longname - 1] = '\0';
	rig_name got;
	assert_int_equal(rig_name_parse(longname, &got), RIG_NONE);
	assert_int_equal(rig_name_side("spine.L"), RIG_LEFT);
	assert_int_equal(rig_name_side("spine.005"), RIG_CENTRE);
}

static void test_families(void **state)
{
	(void)state;
	rig_name n;
	rig_name_parse("upper_arm.L", &n);
	assert_string_equal(rig_family_name(n.rig), "Rigify (Blender metarig)");
	rig_name_parse("mixamorig:LeftUpLeg", &n);
	assert_string_equal(rig_family_name(n.rig), "Mixamo");
	rig_name_parse("upperleg01.L", &n);
	assert_string_equal(rig_family_name(n.rig), "MakeHuman default");
	assert_string_equal(rig_family_name(0), "none");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_rigify),
		cmocka_unit_test(test_mixamo_makehuman_unreal_daz_cmu),
		cmocka_unit_test(test_unity_biped_and_joint_names),
		cmocka_unit_test(test_not_parts),
		cmocka_unit_test(test_families),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
