#include "rig_biped.h"

#include <math.h>
#include <stdio.h>

#include "rig_topology.h"

#define BIPED_SPINE_LEGS_COS (-0.5f) /* 120 degrees or more between spine and legs */
#define BIPED_HANDS_UP       0.25f  /* hands this share of the legs' height above the feet */

static vec3 at(const rig_scene *r, int j)
{
	return r->joint[j].head;
}

/* The file's axis (+-X, +-Y or +-Z) nearest v: its vertical when v runs
 * from the hips to the feet. A quadruped's hind legs may slope back far
 * enough to pass the spine test, and along their own line its forepaws,
 * lying ahead of them, would count as raised; along the file's vertical
 * they stand on the floor. */
static vec3 nearest_axis(vec3 v)
{
	float a[3] = { fabsf(v.x), fabsf(v.y), fabsf(v.z) };
	int k = a[1] > a[0] ? 1 : 0;
	k = a[2] > a[k] ? 2 : k;
	float s = (k == 0 ? v.x : k == 1 ? v.y : v.z) < 0.0f ? -1.0f : 1.0f;
	return (vec3){ k == 0 ? s : 0.0f, k == 1 ? s : 0.0f, k == 2 ? s : 0.0f };
}

/* A limb's end as mapped: the first of the slots given that is. */
static int mapped_end(const rig_map *m, const rig_scene *r, rig_side side, rig_slot end, rig_slot before)
{
	int j = rig_map_part_joint(m, r, side, end);
	return j >= 0 ? j : rig_map_part_joint(m, r, side, before);
}

/* The parts as the map has them (by the joints' names, a file, or the
 * shape), when it found the hips, the head and every limb's end: a rig
 * with control and IK chains beside its deforming bones (Paladin's
 * Ctrl_UpLeg_FK_Left) has more mirror pairs than limbs, and its shape alone
 * can take a control chain for a leg. */
static int mapped_parts(const rig_scene *r, const rig_map *m, rig_shape_parts *p)
{
	if (!m || m->hips < 0 || m->head < 0)
		return 0;
	*p = (rig_shape_parts){ .hips = m->hips, .chest = m->chest, .head = m->head };
	for (int k = 0; k < 2; k++) {
		rig_side side = k ? RIG_RIGHT : RIG_LEFT;
		p->leg_end[k] = mapped_end(m, r, side, RIG_FOOT, RIG_SHIN);
		p->arm_end[k] = mapped_end(m, r, side, RIG_HAND, RIG_FOREARM);
		if (p->leg_end[k] < 0 || p->arm_end[k] < 0)
			return 0;
	}
	return 1;
}

int rig_biped_check(const rig_scene *r, const rig_map *m, char *why, size_t n)
{
	rig_shape_parts p;
	if (!mapped_parts(r, m, &p) && !rig_topology_parts(r, &p))
		return 1;
	vec3 feet = vec3_scale(vec3_add(at(r, p.leg_end[0]), at(r, p.leg_end[1])), 0.5f);
	vec3 down = vec3_sub(feet, at(r, p.hips)), up = vec3_sub(at(r, p.head), at(r, p.hips));
	float leg = vec3_length(down);
	if (!(leg > 0.0f) || !(vec3_length(up) > 0.0f))
		return 1;
	float c = vec3_dot(vec3_normalize(up), vec3_scale(down, 1.0f / leg));
	if (c > BIPED_SPINE_LEGS_COS) {
		snprintf(why, n, "its spine and legs are %.0f degrees apart (a biped's hang the other way from it: 120 "
			 "or more): a quadruped, or a figure lying down", acos((double)c) * 180.0 / M_PI);
		return 0;
	}
	vec3 vertical = nearest_axis(down);
	float drop = vec3_dot(down, vertical), hands = -INFINITY;
	for (int k = 0; k < 2; k++)
		hands = fmaxf(hands, -vec3_dot(vec3_sub(at(r, p.arm_end[k]), feet), vertical) / drop);
	if (!(hands >= BIPED_HANDS_UP)) {
		snprintf(why, n, "its arms reach the floor like its legs (their ends %.0f%% of the legs' height %s the "
			 "feet, a biped's %.0f%% or more above): a quadruped", 100.0 * fabs((double)hands),
			 hands > 0.0f ? "above" : "below", 100.0 * (double)BIPED_HANDS_UP);
		return 0;
	}
	return 1;
}
