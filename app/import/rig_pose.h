/* The bind pose a rigged mesh shows the skeleton: each limb bone of the
 * skeleton turned (by its own rotation channels, skel_aim) to point the way
 * the mesh's matching joint points to the next one: clavicle to shoulder,
 * upper arm to elbow, forearm to wrist, thigh to knee, shin to ankle, foot
 * to toe. The mesh must already be on the skeleton (rig_align.h). How well
 * the two then agree is measured joint by joint. */
#ifndef RIG_POSE_H
#define RIG_POSE_H

#include "rig_map.h"

#define RIG_POSE_MAX_AIMS 16

typedef struct rig_pose_aim {
	int bone;
	float turned_deg;       /* how far it was turned */
	float left_deg;         /* angle to the mesh's direction left after */
} rig_pose_aim;

typedef struct rig_pose_result {
	int aim_count;
	rig_pose_aim aim[RIG_POSE_MAX_AIMS];
	int pairs;              /* mapped joints measured */
	float mean_gap, worst_gap; /* distance skeleton joint - mesh joint, after */
	int worst_joint;
} rig_pose_result;

/* values (dof_count, as amc_frame.value) start as the pose to change and
 * end as the bind pose; pose gets its FK. */
void rig_pose_fit(const skel *s, const rig_scene *r, const rig_map *m, float *values, skel_pose *pose,
		  rig_pose_result *out);

/* The joint gaps alone, for a pose given by the user. */
void rig_pose_measure(const rig_scene *r, const rig_map *m, const skel_pose *pose, rig_pose_result *out);

#endif
