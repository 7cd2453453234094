#include "rig_proportions.h"

#include <math.h>
#include <string.h>

#define RATIO_MIN 0.5f
#define RATIO_MAX 2.0f
/* a mocap hand is a stub (CMU's lhand: a third of a palm), so the hand
 * may reach further to put the fingers' joint on the knuckles (2.6 times
 * on MakeHuman, 2.9 on the shared glb) */
#define RATIO_MAX_HAND 4.0f

static int part_joint(const rig_scene *r, const rig_map *m, int side, rig_slot slot)
{
	return rig_map_part_joint(m, r, (rig_side)side, slot);
}

/* Step 1: returns the scale applied. */
static float scale_by_legs(rig_scene *r, const rig_map *m, const skel_pose *p)
{
	float skel_len = 0.0f, mesh_len = 0.0f;
	vec3 skel_mid = vec3_make(0.0f, 0.0f, 0.0f), mesh_mid = skel_mid;
	int legs = 0;
	for (int side = RIG_LEFT; side <= RIG_RIGHT; side++) {
		int t = part_joint(r, m, side, RIG_THIGH), f = part_joint(r, m, side, RIG_FOOT);
		if (t < 0 || f < 0)
			continue;
		skel_len += vec3_length(vec3_sub(p->head[m->bone[f]], p->head[m->bone[t]]));
		mesh_len += vec3_length(vec3_sub(r->joint[f].head, r->joint[t].head));
		skel_mid = vec3_add(skel_mid, p->head[m->bone[t]]);
		mesh_mid = vec3_add(mesh_mid, r->joint[t].head);
		legs++;
	}
	float k = mesh_len > 0.0f && skel_len > 0.0f ? skel_len / mesh_len : 1.0f;
	if (!legs || !(k >= RATIO_MIN && k <= RATIO_MAX))
		return 1.0f;
	skel_mid = vec3_scale(skel_mid, 1.0f / (float)legs);
	mesh_mid = vec3_scale(mesh_mid, 1.0f / (float)legs);
	for (int v = 0; v < r->mesh->vert_count; v++)
		r->mesh->pos[v] = vec3_add(skel_mid, vec3_scale(vec3_sub(r->mesh->pos[v], mesh_mid), k));
	for (int j = 0; j < r->joint_count; j++)
		r->joint[j].head = vec3_add(skel_mid, vec3_scale(vec3_sub(r->joint[j].head, mesh_mid), k));
	return k;
}

static int is_ancestor(const skel *s, int a, int b)
{
	for (; b >= 0; b = s->bone[b].parent)
		if (b == a)
			return 1;
	return 0;
}

/* Step 2 for one pair of parts: bones a .. parent of b. */
static void stretch_between(skel *s, const skel_pose *p, int a, int b, vec3 mesh_a, vec3 mesh_b, float max,
			    rig_proportions *out)
{
	if (a < 0 || b < 0 || a == b || !is_ancestor(s, a, b))
		return;
	float ds = vec3_length(vec3_sub(p->head[b], p->head[a]));
	float dm = vec3_length(vec3_sub(mesh_b, mesh_a));
	if (!(ds > 0.0f) || !(dm > 0.0f))
		return;
	float ratio = fminf(max, fmaxf(RATIO_MIN, dm / ds));
	for (int k = s->bone[b].parent; k >= 0; k = s->bone[k].parent) {
		s->bone[k].length *= ratio;
		if (k == a)
			break;
	}
	out->scaled++;
	out->min_ratio = fminf(out->min_ratio, ratio);
	out->max_ratio = fmaxf(out->max_ratio, ratio);
}

/* The chain's first bone reaches from where it starts on the skeleton (a
 * clavicle at the spine) to the mesh's next joint; rig_pose.h aims it there. */
static void stretch_chain(skel *s, const skel_pose *p, const rig_scene *r, const rig_map *m, int side,
			  const rig_slot *slots, int n, rig_proportions *out)
{
	for (int i = 0; i + 1 < n; i++) {
		int a = m->parts.bone[side][slots[i]], b = m->parts.bone[side][slots[i + 1]];
		vec3 mesh_a, mesh_b;
		if (rig_map_part_head(m, r, (rig_side)side, slots[i], &mesh_a) &&
		    rig_map_part_head(m, r, (rig_side)side, slots[i + 1], &mesh_b))
			stretch_between(s, p, a, b, i == 0 ? p->head[a] : mesh_a, mesh_b,
					slots[i + 1] == RIG_FINGERS ? RATIO_MAX_HAND : RATIO_MAX, out);
	}
}

/* Step 3: the thigh's parent chain back to the root, when it has no channels. */
static void place_hip_bones(skel *s, const float *values, skel_pose *p, const rig_scene *r, const rig_map *m,
			    rig_proportions *out)
{
	for (int side = RIG_LEFT; side <= RIG_RIGHT; side++) {
		int j = part_joint(r, m, side, RIG_THIGH);
		if (j < 0)
			continue;
		int h = s->bone[m->bone[j]].parent;
		if (h <= 0 || s->bone[h].parent != 0 || s->bone[h].channel_count != 0)
			continue;
		vec3 d = vec3_sub(r->joint[j].head, p->head[h]);
		float len = vec3_length(d);
		if (!(len > 0.0f))
			continue;
		s->bone[h].direction = quat_rotate(quat_conj(p->rot[0]), vec3_scale(d, 1.0f / len));
		s->bone[h].length = len;
		out->hip_bones++;
		fk_pose(s, values, p);
	}
}

void rig_fit_proportions(skel *s, const float *values, skel_pose *pose, rig_scene *r, const rig_map *m,
			 rig_proportions *out)
{
	memset(out, 0, sizeof *out);
	out->min_ratio = INFINITY;
	out->max_ratio = 0.0f;
	out->mesh_scale = 1.0f;
	out->mesh_scale = scale_by_legs(r, m, pose);
	place_hip_bones(s, values, pose, r, m, out);
	/* the skeleton's pelvis stays: the spine is measured from its root
	 * (the mesh's hips joint sits anywhere in the pelvis: Rigify's below
	 * the hip joints) */
	int chest = m->chest >= 0 ? m->chest : m->head;
	if (chest >= 0)
		stretch_between(s, pose, 0, m->bone[chest], pose->head[0], r->joint[chest].head, RATIO_MAX, out);
	if (m->chest >= 0 && m->head >= 0)
		stretch_between(s, pose, m->bone[m->chest], m->bone[m->head], r->joint[m->chest].head,
				r->joint[m->head].head, RATIO_MAX, out);
	static const rig_slot arm[] = { RIG_CLAVICLE, RIG_UPPER_ARM, RIG_FOREARM, RIG_HAND, RIG_FINGERS };
	static const rig_slot leg[] = { RIG_THIGH, RIG_SHIN, RIG_FOOT, RIG_TOE };
	for (int side = RIG_LEFT; side <= RIG_RIGHT; side++) {
		stretch_chain(s, pose, r, m, side, arm, 5, out);
		stretch_chain(s, pose, r, m, side, leg, 4, out);
	}
	fk_pose(s, values, pose);
}
