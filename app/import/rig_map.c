#include "rig_map.h"

#include <math.h>
#include <string.h>

#include "rig_topology.h"

static int depth_of(const rig_scene *r, int j)
{
	int d = 0;
	for (; j >= 0 && d <= RIG_MAX_JOINTS; j = r->joint[j].parent)
		d++;
	return d;
}

static int is_ancestor(const rig_scene *r, int a, int j)
{
	for (int d = 0; j >= 0 && d <= RIG_MAX_JOINTS; j = r->joint[j].parent, d++)
		if (j == a)
			return 1;
	return 0;
}

static int common_ancestor(const rig_scene *r, int a, int b)
{
	if (a < 0 || b < 0)
		return -1;
	for (int d = 0; a >= 0 && d <= RIG_MAX_JOINTS; a = r->joint[a].parent, d++)
		if (is_ancestor(r, a, b))
			return a;
	return -1;
}

/* The shallowest joint named as that part. */
static int named_joint(const rig_scene *r, const rig_map *m, rig_side side, rig_slot slot)
{
	int best = -1;
	for (int j = 0; j < r->joint_count; j++)
		if (m->name[j].slot == slot && m->name[j].side == side &&
		    (best < 0 || depth_of(r, j) < depth_of(r, best)))
			best = j;
	return best;
}

static int child_count(const rig_scene *r, int j)
{
	int n = 0;
	for (int c = 0; c < r->joint_count; c++)
		n += r->joint[c].parent == j;
	return n;
}

/* Longest chain of unsided joints below j. */
static int unsided_height(const rig_scene *r, int j, int *next)
{
	int best = 0;
	*next = -1;
	for (int c = 0; c < r->joint_count; c++) {
		int dummy;
		if (r->joint[c].parent != j || rig_name_side(r->joint[c].name) != RIG_CENTRE)
			continue;
		int h = 1 + unsided_height(r, c, &dummy);
		if (h > best) {
			best = h;
			*next = c;
		}
	}
	return best;
}

static void find_trunk(const rig_scene *r, rig_map *m)
{
	m->hips = common_ancestor(r, named_joint(r, m, RIG_LEFT, RIG_THIGH), named_joint(r, m, RIG_RIGHT, RIG_THIGH));
	m->head = named_joint(r, m, RIG_CENTRE, RIG_HEAD);
	m->chest = common_ancestor(r, named_joint(r, m, RIG_LEFT, RIG_CLAVICLE),
				   named_joint(r, m, RIG_RIGHT, RIG_CLAVICLE));
	if (m->chest < 0)
		m->chest = common_ancestor(r, named_joint(r, m, RIG_LEFT, RIG_UPPER_ARM),
					   named_joint(r, m, RIG_RIGHT, RIG_UPPER_ARM));
	/* no joint named head: the end of the unsided chain above the chest,
	 * or where it branches into a face (3 children or more) */
	for (int j = m->head < 0 ? m->chest : -1, next; j >= 0; j = next) {
		m->head = j;
		unsided_height(r, j, &next);
		if (j != m->chest && child_count(r, j) >= 3)
			break;
	}
	/* legs hung from a pelvis beside the spine (BCN_Epileptic's
	 * LowerPelvis): the spine starts where both meet */
	if (m->hips >= 0 && m->head >= 0 && !is_ancestor(r, m->hips, m->head))
		m->hips = common_ancestor(r, m->hips, m->head);
}

/* Where each joint of the chain sits along it: 0 at its first, 0.5 at
 * the chest (index chest; -1: none), 1 at its last, in proportion to the
 * distance along the chain in between. */
static void chain_places(const vec3 *head, int n, int chest, float *t)
{
	float total = 0.0f;
	t[0] = 0.0f;
	for (int i = 1; i < n; i++)
		t[i] = total += vec3_length(vec3_sub(head[i], head[i - 1]));
	float mid = chest > 0 && chest < n - 1 ? t[chest] : 0.5f * total;
	for (int i = 0; i < n; i++) {
		if (!(total > 0.0f))
			t[i] = (float)i / (float)(n > 1 ? n - 1 : 1);
		else if (t[i] <= mid)
			t[i] = mid > 0.0f ? 0.5f * t[i] / mid : 0.5f;
		else
			t[i] = 0.5f + 0.5f * (t[i] - mid) / (total - mid);
	}
}

static int index_in(const int *list, int n, int x)
{
	for (int i = 0; i < n; i++)
		if (list[i] == x)
			return i;
	return -1;
}

static void map_spine(const rig_scene *r, const skel_pose *p, rig_map *m)
{
	static vec3 mesh_head[RIG_MAX_JOINTS], skel_head[SKP_MAX_BONES];
	static float mt[RIG_MAX_JOINTS], st[SKP_MAX_BONES];
	int chain[RIG_MAX_JOINTS], n = 0;
	const rig_skel_parts *parts = &m->parts;
	if (m->hips < 0 || m->head < 0 || !is_ancestor(r, m->hips, m->head))
		return;
	for (int j = m->head; j >= 0 && n < RIG_MAX_JOINTS; j = r->joint[j].parent) {
		chain[n++] = j;
		if (j == m->hips)
			break;
	}
	int up[RIG_MAX_JOINTS];                         /* hips first */
	for (int i = 0; i < n; i++) {
		up[i] = chain[n - 1 - i];
		mesh_head[i] = r->joint[up[i]].head;
	}
	for (int i = 0; i < parts->spine_count; i++)
		skel_head[i] = p->head[parts->spine[i]];
	chain_places(mesh_head, n, index_in(up, n, m->chest), mt);
	chain_places(skel_head, parts->spine_count, index_in(parts->spine, parts->spine_count, parts->chest), st);
	for (int i = 0; i < n; i++) {
		int best = 0;
		for (int k = 1; k < parts->spine_count; k++)   /* ties: the later bone */
			if (fabsf(st[k] - mt[i]) <= fabsf(st[best] - mt[i]))
				best = k;
		m->bone[chain[n - 1 - i]] = parts->spine[best];
	}
	m->bone[m->hips] = parts->spine[0];
	m->bone[m->head] = parts->spine[parts->spine_count - 1];
}

/* The mapped joint toes or fingers hang from (the foot, the hand), or -1:
 * without it a toe or finger mapped alone would turn with the skeleton's
 * foot or hand while the rest of the foot or hand turns with the shin or
 * forearm, and the skin between them tears (RobotExpressive has no hand
 * joint: its Ring1.L, a Daz finger's name, beside palms and fingers
 * following LowerArm.L tore in CMU's kick). */
static int digits_holder(const rig_scene *r, const rig_map *m, rig_side side, rig_slot slot)
{
	int j = named_joint(r, m, side, slot == RIG_TOE ? RIG_FOOT : RIG_HAND);
	return j >= 0 && m->bone[j] >= 0 ? j : -1;
}

/* A limb part maps from its shallowest joint of that name; toes and
 * fingers from every one under the foot or hand (MakeHuman's five toes, a
 * hand's four fingers: the skeleton has one bone for them all). */
static void map_limbs(const rig_scene *r, rig_map *m)
{
	for (int side = RIG_LEFT; side <= RIG_RIGHT; side++)
		for (int slot = RIG_CLAVICLE; slot < RIG_SLOT_COUNT; slot++) {
			int j = named_joint(r, m, (rig_side)side, (rig_slot)slot), b = m->parts.bone[side][slot];
			if (j < 0 || b < 0)
				continue;
			if (slot != RIG_TOE && slot != RIG_FINGERS) {
				m->bone[j] = b;
				continue;
			}
			int holder = digits_holder(r, m, (rig_side)side, (rig_slot)slot);
			for (int k = 0; holder >= 0 && k < r->joint_count; k++)
				if ((int)m->name[k].slot == slot && (int)m->name[k].side == side && is_ancestor(r, holder, k))
					m->bone[k] = b;
		}
}

static skp_status apply_file(const rig_scene *r, const skel *s, const rig_map_file *f, rig_map *m,
			     skp_error *err)
{
	for (int i = 0; f && i < f->count; i++) {
		const rig_map_entry *e = &f->entry[i];
		int j = rig_find_joint(r, e->joint);
		if (j < 0)
			return skp_fail(err, SKP_ERR_RANGE, e->line, "the mesh has no joint named '%s'", e->joint);
		int b = strcmp(e->bone, "-") == 0 ? -1 : skel_find(s, e->bone);
		if (b < 0 && strcmp(e->bone, "-") != 0)
			return skp_fail(err, SKP_ERR_RANGE, e->line, "the skeleton has no bone named '%s'", e->bone);
		m->bone[j] = b;
		m->by_file[j] = 1;
	}
	return SKP_OK;
}

/* The mapped joint nearest joint j, or -1. */
static int nearest_mapped(const rig_scene *r, const rig_map *m, int j)
{
	int best = -1;
	float best_d = 0.0f;
	for (int a = 0; a < r->joint_count; a++) {
		float d = vec3_length(vec3_sub(r->joint[a].head, r->joint[j].head));
		if (m->bone[a] >= 0 && (best < 0 || d < best_d)) {
			best = a;
			best_d = d;
		}
	}
	return best;
}

/* An unmapped joint moves with its nearest mapped ancestor. One with none
 * that moves skin (a slot for a helmet parented to the armature, not to
 * the head, as Soldier's HelmetSlot) moves with the mapped joint nearest
 * it instead of the root. */
static void find_follow(const rig_scene *r, rig_map *m)
{
	m->mapped = 0;
	for (int j = 0; j < r->joint_count; j++) {
		m->mapped += m->bone[j] >= 0;
		m->follow[j] = 0;
		m->via[j] = -1;
		m->beside[j] = 0;
		int a = j;
		for (int d = 0; a >= 0 && d <= RIG_MAX_JOINTS && m->bone[a] < 0; d++)
			a = r->joint[a].parent;
		if (a < 0 && r->joint[j].weighted && (a = nearest_mapped(r, m, j)) >= 0)
			m->beside[j] = 1;
		if (a >= 0 && m->bone[a] >= 0) {
			m->follow[j] = m->bone[a];
			m->via[j] = a == j ? -1 : a;
		}
	}
}

static void find_family(const rig_scene *r, rig_map *m)
{
	int hits[16] = { 0 }, best = 0;
	for (int j = 0; j < r->joint_count; j++)
		for (int k = 0; k < 16; k++)
			hits[k] += (m->name[j].rig >> k) & 1;
	for (int k = 1; k < 16; k++)
		if (hits[k] > hits[best])
			best = k;
	m->family = hits[best] ? 1 << best : 0;
}

int rig_map_part_joint(const rig_map *m, const rig_scene *r, rig_side side, rig_slot slot)
{
	int b = m->parts.bone[side][slot], best = -1;
	for (int j = 0; b >= 0 && j < r->joint_count; j++)
		if (m->bone[j] == b && (best < 0 || depth_of(r, j) < depth_of(r, best)))
			best = j;
	return best;
}

int rig_map_part_head(const rig_map *m, const rig_scene *r, rig_side side, rig_slot slot, vec3 *head)
{
	int first = rig_map_part_joint(m, r, side, slot), n = 0;
	if (first < 0)
		return 0;
	int depth = depth_of(r, first);
	vec3 sum = vec3_make(0.0f, 0.0f, 0.0f);
	for (int j = 0; j < r->joint_count; j++)
		if (m->bone[j] == m->bone[first] && depth_of(r, j) == depth) {
			sum = vec3_add(sum, r->joint[j].head);
			n++;
		}
	*head = vec3_scale(sum, 1.0f / (float)n);
	return 1;
}

/* Limbs (upper and lower part on one side) the names say. */
static int named_limbs(const rig_scene *r, const rig_map *m)
{
	int n = 0;
	for (int side = RIG_LEFT; side <= RIG_RIGHT; side++)
		n += (named_joint(r, m, (rig_side)side, RIG_UPPER_ARM) >= 0 && named_joint(r, m, (rig_side)side, RIG_FOREARM) >= 0) +
		     (named_joint(r, m, (rig_side)side, RIG_THIGH) >= 0 && named_joint(r, m, (rig_side)side, RIG_SHIN) >= 0);
	return n;
}

skp_status rig_map_joints(const rig_scene *r, const skel *s, const skel_pose *p,
			  const rig_map_file *file, rig_map *out, skp_error *err)
{
	memset(out, 0, sizeof *out);
	rig_find_skel_parts(s, p, &out->parts);
	for (int j = 0; j < r->joint_count; j++) {
		out->bone[j] = -1;
		rig_name_parse(r->joint[j].name, &out->name[j]);
	}
	if (named_limbs(r, out) < 2)
		rig_topology_names(r, out->name);
	find_trunk(r, out);
	map_spine(r, p, out);
	map_limbs(r, out);
	skp_status rc = apply_file(r, s, file, out, err);
	if (rc != SKP_OK)
		return rc;
	find_follow(r, out);
	find_family(r, out);
	for (int side = RIG_LEFT; side <= RIG_RIGHT; side++) {
		out->limbs += rig_map_part_joint(out, r, side, RIG_UPPER_ARM) >= 0 &&
			      rig_map_part_joint(out, r, side, RIG_FOREARM) >= 0;
		out->limbs += rig_map_part_joint(out, r, side, RIG_THIGH) >= 0 &&
			      rig_map_part_joint(out, r, side, RIG_SHIN) >= 0;
	}
	return SKP_OK;
}
