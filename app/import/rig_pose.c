#include "rig_pose.h"

#include <math.h>
#include <string.h>

#include "skel_tpose.h"

static float deg_between(vec3 a, vec3 b)
{
	float c = vec3_dot(vec3_normalize(a), vec3_normalize(b));
	return acosf(fmaxf(-1.0f, fminf(1.0f, c))) * 57.29578f;
}

/* Each bone aimed at the mesh's next joint, but not the hand at the
 * fingers: aimed at the knuckles (MakeHuman's hands turned by 30 and 43
 * degrees), the walk's hands came out bent back at the wrist with the
 * fingers splayed, where unaimed they hang as modelled. */
#define CHAIN_LEN 4

static const rig_slot chains[2][CHAIN_LEN] = {
	{ RIG_CLAVICLE, RIG_UPPER_ARM, RIG_FOREARM, RIG_HAND },
	{ RIG_THIGH, RIG_SHIN, RIG_FOOT, RIG_TOE },
};

static void aim_one(const skel *s, const rig_scene *r, const rig_map *m, rig_side side, rig_slot from,
		    rig_slot to, float *values, skel_pose *pose, rig_pose_result *out)
{
	int bone = m->parts.bone[side][from];
	vec3 next;
	if (bone < 0 || rig_map_part_joint(m, r, side, from) < 0 ||
	    !rig_map_part_head(m, r, side, to, &next) || out->aim_count == RIG_POSE_MAX_AIMS)
		return;
	fk_pose(s, values, pose);
	/* at the mesh's next joint from where the bone starts now: a clavicle
	 * starting elsewhere than the mesh's still puts the shoulder on it */
	vec3 target = vec3_sub(next, pose->head[bone]);
	vec3 before = vec3_sub(pose->tip[bone], pose->head[bone]);
	if (vec3_length(target) <= 0.0f || vec3_length(before) <= 0.0f)
		return;
	float cos_left = skel_aim(s, bone, vec3_normalize(target), values, pose);
	rig_pose_aim *a = &out->aim[out->aim_count++];
	a->bone = bone;
	a->turned_deg = deg_between(before, vec3_sub(pose->tip[bone], pose->head[bone]));
	a->left_deg = acosf(fmaxf(-1.0f, fminf(1.0f, cos_left))) * 57.29578f;
}

void rig_pose_measure(const rig_scene *r, const rig_map *m, const skel_pose *pose, rig_pose_result *out)
{
	out->pairs = 0;
	out->mean_gap = out->worst_gap = 0.0f;
	out->worst_joint = -1;
	for (int side = RIG_CENTRE; side <= RIG_RIGHT; side++)
		for (int slot = RIG_HEAD; slot < RIG_SLOT_COUNT; slot++) {
			int j = rig_map_part_joint(m, r, (rig_side)side, (rig_slot)slot);
			vec3 head;
			if (j < 0 || !rig_map_part_head(m, r, (rig_side)side, (rig_slot)slot, &head))
				continue;
			float gap = vec3_length(vec3_sub(pose->head[m->bone[j]], head));
			out->mean_gap += gap;
			out->pairs++;
			if (gap > out->worst_gap) {
				out->worst_gap = gap;
				out->worst_joint = j;
			}
		}
	if (out->pairs)
		out->mean_gap /= (float)out->pairs;
}

void rig_pose_fit(const skel *s, const rig_scene *r, const rig_map *m, float *values, skel_pose *pose,
		  rig_pose_result *out)
{
	memset(out, 0, sizeof *out);
	for (int side = RIG_LEFT; side <= RIG_RIGHT; side++)
		for (int c = 0; c < 2; c++)
			for (int k = 0; k + 1 < CHAIN_LEN; k++)
				aim_one(s, r, m, (rig_side)side, chains[c][k], chains[c][k + 1], values, pose, out);
	fk_pose(s, values, pose);
	rig_pose_measure(r, m, pose, out);
}
