/* BVH out. A BVH joint J per bone b, at b's head, turning as b does: its
 * world rotation is b's (G_b), so its local rotation is C_b M_b C_b^-1
 * (the bone's channels M_b conjugated by its axis C_b) and a child's OFFSET
 * is the rest-pose vector between the two heads. The rotation goes out as
 * Euler angles Z Y X, decomposed in double precision. */
#include <math.h>
#include <string.h>

#include "convert.h"
#include "motion_file.h"

#define DEG_PER_RAD 57.295779513082320876798

typedef struct dquat {
	double w, x, y, z;
} dquat;

static dquat dq_mul(dquat a, dquat b)
{
	return (dquat){ a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
			a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
			a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
			a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w };
}

static dquat dq_of(quat q)
{
	return (dquat){ q.w, q.x, q.y, q.z };
}

static dquat dq_axis(int axis, double angle)
{
	dquat q = { cos(angle / 2), 0, 0, 0 };
	double s = sin(angle / 2);
	if (axis == 0) q.x = s;
	else if (axis == 1) q.y = s;
	else q.z = s;
	return q;
}

/* C M C^-1 with M from the rotation channels, first listed applied first. */
static dquat local_rotation(const skel_bone *b, const float *v)
{
	dquat m = { 1, 0, 0, 0 };
	for (int i = 0; i < b->channel_count; i++)
		if (b->channel[i] <= SKEL_RZ)
			m = dq_mul(dq_axis(b->channel[i] - SKEL_RX, v[i]), m);
	dquat c = dq_of(b->axis_rot), ci = { c.w, -c.x, -c.y, -c.z };
	return dq_mul(dq_mul(c, m), ci);
}

/* Rz(a) Ry(b) Rx(c) = q, in degrees. */
static void euler_zyx(dquat q, double out[3])
{
	double n = sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
	double w = q.w / n, x = q.x / n, y = q.y / n, z = q.z / n;
	double r00 = 1 - 2 * (y * y + z * z), r10 = 2 * (x * y + w * z), r20 = 2 * (x * z - w * y);
	double r21 = 2 * (y * z + w * x), r22 = 1 - 2 * (x * x + y * y);
	double r01 = 2 * (x * y - w * z), r11 = 1 - 2 * (x * x + z * z);
	double cb = sqrt(r00 * r00 + r10 * r10);
	double b = atan2(-r20, cb), a, c;
	if (cb > 1e-12) {
		a = atan2(r10, r00);
		c = atan2(r21, r22);
	} else {        /* gimbal lock: only a - c (or a + c) matters */
		a = atan2(-r01, r11);
		c = 0;
	}
	out[0] = a * DEG_PER_RAD;
	out[1] = b * DEG_PER_RAD;
	out[2] = c * DEG_PER_RAD;
}

const char *convert_unsupported(const skel *s, int *bone)
{
	for (int b = 0; b < s->count; b++)
		for (int i = 0; i < s->bone[b].channel_count; i++)
			if (s->bone[b].channel[i] == SKEL_L) {
				*bone = b;
				return "has a length channel (l), which BVH cannot carry";
			}
	return NULL;
}

static int translates(const skel_bone *b)
{
	for (int i = 0; i < b->channel_count; i++)
		if (b->channel[i] >= SKEL_TX && b->channel[i] <= SKEL_TZ)
			return 1;
	return 0;
}

static vec3 segment(const skel_bone *b)
{
	return vec3_scale(b->direction, b->length);
}

/* Rest-pose vector from the parent joint's head to b's head. */
static vec3 joint_offset(const skel *s, int b)
{
	const skel_bone *p = &s->bone[s->bone[b].parent];
	return vec3_add(s->bone[b].parent == 0 ? vec3_make(0, 0, 0) : segment(p), s->bone[b].offset);
}

static void indent(FILE *f, int depth)
{
	for (int i = 0; i < depth; i++)
		fputc('\t', f);
}

static void write_joint(FILE *f, const skel *s, int b, int depth)
{
	const skel_bone *bone = &s->bone[b];
	vec3 o = b == 0 ? s->root_position : joint_offset(s, b);
	indent(f, depth);
	fprintf(f, "%s %s\n", b == 0 ? "ROOT" : "JOINT", bone->name);
	indent(f, depth);
	fprintf(f, "{\n");
	indent(f, depth + 1);
	fprintf(f, "OFFSET %.9g %.9g %.9g\n", (double)o.x, (double)o.y, (double)o.z);
	indent(f, depth + 1);
	if (b == 0 || translates(bone))
		fprintf(f, "CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n");
	else
		fprintf(f, "CHANNELS 3 Zrotation Yrotation Xrotation\n");
	int children = 0;
	for (int c = 1; c < s->count; c++)
		if (s->bone[c].parent == b) {
			write_joint(f, s, c, depth + 1);
			children++;
		}
	if (!children) {
		vec3 e = segment(bone);
		indent(f, depth + 1);
		fprintf(f, "End Site\n");
		indent(f, depth + 1);
		fprintf(f, "{\n");
		indent(f, depth + 2);
		fprintf(f, "OFFSET %.9g %.9g %.9g\n", (double)e.x, (double)e.y, (double)e.z);
		indent(f, depth + 1);
		fprintf(f, "}\n");
	}
	indent(f, depth);
	fprintf(f, "}\n");
}

/* The joint's position relative to its parent's head, in the parent's frame. */
static vec3 joint_position(const skel *s, int b, const float *v)
{
	const skel_bone *bone = &s->bone[b];
	float t[3] = { 0, 0, 0 };
	for (int i = 0; i < bone->channel_count; i++)
		if (bone->channel[i] >= SKEL_TX && bone->channel[i] <= SKEL_TZ)
			t[bone->channel[i] - SKEL_TX] = v[i];
	vec3 trans = vec3_make(t[0], t[1], t[2]);
	if (b == 0)
		return vec3_add(s->root_position, trans);
	return vec3_add(joint_offset(s, b), quat_rotate(bone->axis_rot, trans));
}

static void write_frame_joint(FILE *f, const skel *s, int b, const float *values)
{
	const skel_bone *bone = &s->bone[b];
	const float *v = values + bone->dof_offset;
	if (b == 0 || translates(bone)) {
		vec3 p = joint_position(s, b, v);
		fprintf(f, "%.9g %.9g %.9g ", (double)p.x, (double)p.y, (double)p.z);
	}
	double e[3];
	euler_zyx(local_rotation(bone, v), e);
	fprintf(f, "%.9g %.9g %.9g", e[0], e[1], e[2]);
	for (int c = 1; c < s->count; c++)
		if (s->bone[c].parent == b) {
			fputc(' ', f);
			write_frame_joint(f, s, c, values);
		}
}

int convert_write_bvh(FILE *f, const skel *s, motion_file *m, long frames, double frame_time)
{
	static amc_frame fr;
	fprintf(f, "HIERARCHY\n");
	write_joint(f, s, 0, 0);
	fprintf(f, "MOTION\nFrames: %ld\nFrame Time: %.9g\n", frames, frame_time);
	int r = 0;
	for (long i = 0; i < frames && (r = motion_file_next(m, &fr)) > 0; i++) {
		write_frame_joint(f, s, 0, fr.value);
		fputc('\n', f);
	}
	return r < 0 ? -1 : 0;
}
