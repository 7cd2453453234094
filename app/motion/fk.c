#include "fk.h"

#include <math.h>

/* Rotation of a bone's rotational channels, first listed applied first;
 * translational channels go to *trans and `l` to *stretch. */
static quat channel_motion(const skel_bone *b, const float *v, vec3 *trans, float *stretch)
{
	quat m = quat_identity();
	float t[3] = { 0.0f, 0.0f, 0.0f };
	*stretch = 0.0f;
	for (int i = 0; i < b->channel_count; i++) {
		int c = b->channel[i];
		if (c <= SKEL_RZ)
			m = quat_mul(quat_from_basis_angle(c - SKEL_RX, v[i]), m);
		else if (c <= SKEL_TZ)
			t[c - SKEL_TX] = v[i];
		else
			*stretch = v[i];
	}
	*trans = vec3_make(t[0], t[1], t[2]);
	return m;
}

static quat conjugate_by(quat c, quat m)
{
	return quat_mul(quat_mul(c, m), quat_conj(c));
}

/* Bone i's local motion from its values (NULL: the rest pose). */
static quat bone_local(const skel *s, int i, const float *values, vec3 *trans, float *stretch)
{
	static const float zero[SKEL_MAX_CHANNELS];
	const skel_bone *b = &s->bone[i];
	return conjugate_by(b->axis_rot, channel_motion(b, values ? values + b->dof_offset : zero, trans, stretch));
}

void fk_local(const skel *s, const float *values, skel_local *out)
{
	for (int i = 0; i < s->count; i++)
		out->rot[i] = bone_local(s, i, values, &out->trans[i], &out->stretch[i]);
}

static int nonzero(vec3 v)
{
	return v.x != 0.0f || v.y != 0.0f || v.z != 0.0f;
}

static void pose_root(const skel *s, quat rot, vec3 trans, skel_pose *out)
{
	out->rot[0] = quat_normalize(rot);
	out->head[0] = out->tip[0] = vec3_add(s->root_position, trans);
}

static void pose_bone(const skel *s, int i, quat rot, vec3 trans, float stretch, skel_pose *out)
{
	const skel_bone *b = &s->bone[i];
	quat gp = out->rot[b->parent];
	quat g = quat_normalize(quat_mul(gp, rot));
	/* a joint translation lives in the bone's local (axis) frame at rest */
	vec3 head = out->tip[b->parent];
	if (nonzero(b->offset))
		head = vec3_add(head, quat_rotate(gp, b->offset));
	if (nonzero(trans))
		head = vec3_add(head, quat_rotate(quat_mul(gp, b->axis_rot), trans));
	out->rot[i] = g;
	out->head[i] = head;
	out->tip[i] = vec3_madd(head, quat_rotate(g, b->direction), b->length + stretch);
}

void fk_from_local(const skel *s, const skel_local *l, skel_pose *out)
{
	pose_root(s, l->rot[0], l->trans[0], out);
	for (int k = 1; k < s->count; k++) {
		int i = s->eval_order[k];
		pose_bone(s, i, l->rot[i], l->trans[i], l->stretch[i], out);
	}
}

void fk_pose_bone(const skel *s, int i, const float *values, skel_pose *out)
{
	vec3 trans;
	float stretch;
	quat rot = bone_local(s, i, values, &trans, &stretch);
	if (i == 0)
		pose_root(s, rot, trans, out);
	else
		pose_bone(s, i, rot, trans, stretch, out);
}

/* The same steps bone by bone, without a whole skel_local on the stack. */
void fk_pose(const skel *s, const float *values, skel_pose *out)
{
	fk_pose_bone(s, 0, values, out);
	for (int k = 1; k < s->count; k++)
		fk_pose_bone(s, s->eval_order[k], values, out);
}

vec3 fk_tip_centre(const skel_pose *pose, int count)
{
	vec3 lo = pose->tip[0], hi = lo;
	for (int b = 1; b < count; b++) {
		vec3 t = pose->tip[b];
		lo = vec3_make(fminf(lo.x, t.x), fminf(lo.y, t.y), fminf(lo.z, t.z));
		hi = vec3_make(fmaxf(hi.x, t.x), fmaxf(hi.y, t.y), fmaxf(hi.z, t.z));
	}
	return vec3_scale(vec3_add(lo, hi), 0.5f);
}
