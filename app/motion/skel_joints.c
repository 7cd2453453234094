#include "skel_joints.h"

#include <math.h>
#include <string.h>

#include "skp_format.h"

static const char *const kind_names[JOINT_KIND_COUNT] = {
	"JOINT", "HIPS", "BACK", "CHEST", "NECK", "HEAD",
	"COLLAR BONE", "SHOULDER", "ELBOW", "WRIST", "HAND", "FINGERS", "THUMB",
	"PELVIS", "HIP", "KNEE", "ANKLE", "TOES", "UPPER ARM", "FOREARM", "THIGH", "SHIN",
};

static float bone_len(const skel_pose *p, int b)
{
	return vec3_length(vec3_sub(p->tip[b], p->head[b]));
}

/* The child of b that reaches furthest (the limb's main line), or -1. */
static int main_child(const skel *s, const skel_roles *r, const skel_pose *p, int b)
{
	int best = -1;
	float far = -1.0f;
	for (int c = 1; c < s->count; c++) {
		if (s->bone[c].parent != b)
			continue;
		float reach = bone_len(p, c) + r->reach[c];
		if (reach > far)
			far = reach, best = c;
	}
	return best;
}

static int has_word(const char *name, const char *word)
{
	size_t n = strlen(word);
	for (const char *c = name; *c; c++) {
		size_t i = 0;
		while (i < n && (c[i] | 0x20) == word[i])
			i++;
		if (i == n)
			return 1;
	}
	return 0;
}

/* l/L or r/R before a capital or as CMU's prefix (lhumerus), "left" /
 * "right" anywhere, or _L/.L at the end. */
static skel_side side_from_name(const char *name)
{
	size_t n = strlen(name);
	if (has_word(name, "left"))
		return SIDE_LEFT;
	if (has_word(name, "right"))
		return SIDE_RIGHT;
	if (n >= 2 && (name[n - 2] == '_' || name[n - 2] == '.' || name[n - 2] == ' ')) {
		if ((name[n - 1] | 0x20) == 'l')
			return SIDE_LEFT;
		if ((name[n - 1] | 0x20) == 'r')
			return SIDE_RIGHT;
	}
	if (n >= 2 && (name[0] == 'l' || name[0] == 'L'))
		return SIDE_LEFT;
	if (n >= 2 && (name[0] == 'r' || name[0] == 'R'))
		return SIDE_RIGHT;
	return SIDE_NONE;
}

static int is_twist(const skel *s, int b)
{
	return has_word(s->bone[b].name, "twist");
}

static skel_joint_kind beyond_hand(const skel *s, int b)
{
	if (has_word(s->bone[b].name, "thumb"))
		return JOINT_THUMB;
	if (has_word(s->bone[b].name, "finger") || has_word(s->bone[b].name, "index"))
		return JOINT_FINGERS;
	return JOINT_HAND;
}

/* A limb's main line from its branch start (each bone's main child) and
 * each bone's length with the twist bones after it (endorphin splits the
 * forearm in two: its head is no joint). */
typedef struct limb_line {
	int bone[SKP_MAX_BONES], n;
	float len[SKP_MAX_BONES];
} limb_line;

static void trace_line(const skel *s, const skel_roles *r, const skel_pose *p, int start, limb_line *l)
{
	int carry = 0;
	l->n = 0;
	for (int b = start; b >= 0 && l->n < SKP_MAX_BONES; b = main_child(s, r, p, b)) {
		l->bone[l->n] = b;
		l->len[l->n] = 0.0f;
		if (!is_twist(s, b) || l->n == 0)
			carry = l->n;
		l->len[carry] += bone_len(p, b);
		l->n++;
	}
}

/* The index on the line of the limb's upper bone (upper arm, thigh): the
 * one before the last long bone (forearm, shin; the hand's and foot's
 * bones are short), long being at least 0.45 of the line's longest. Not
 * the longest pair: CMU's collar bone and upper arm are longer together
 * than the upper arm and forearm. */
static int upper_index(const skel *s, const limb_line *l)
{
	int lower = 0, upper = 0;
	float longest = 0.0f;
	for (int i = 0; i < l->n; i++)
		longest = fmaxf(longest, l->len[i]);
	for (int i = 0; i < l->n; i++)
		if (!is_twist(s, l->bone[i]) && l->len[i] >= 0.45f * longest)
			lower = i;
	for (int i = 0; i < lower; i++)
		if (!is_twist(s, l->bone[i]))
			upper = i;
	return upper;
}

/* Names one limb: the bones before the upper one (collar, pelvis), the
 * upper one, then joint by joint down its main line, a twist bone by the
 * bone it splits; side branches (a thumb) by name beyond the hand. */
static void name_limb(const skel *s, const skel_roles *r, const skel_pose *p, int start, skel_joints *j)
{
	static const uint8_t arm_line[] = { JOINT_SHOULDER, JOINT_ELBOW, JOINT_WRIST };
	static const uint8_t leg_line[] = { JOINT_HIP, JOINT_KNEE, JOINT_ANKLE };
	static const uint8_t arm_twist[] = { JOINT_UPPER_ARM, JOINT_FOREARM, JOINT_HAND };
	static const uint8_t leg_twist[] = { JOINT_THIGH, JOINT_SHIN, JOINT_TOES };
	static limb_line l; /* 1 KiB: not on a small stack */
	int arm = r->arm[start];
	trace_line(s, r, p, start, &l);
	int upper = upper_index(s, &l), depth = -1;
	for (int i = 0; i < l.n; i++) {
		int b = l.bone[i], twist = is_twist(s, b) && depth >= 0;
		if (i == upper)
			depth = 0;
		else if (depth >= 0 && !twist)
			depth++;
		if (depth < 0)
			j->kind[b] = arm ? JOINT_COLLAR : JOINT_PELVIS;
		else if (depth < 3)
			j->kind[b] = twist ? (arm ? arm_twist : leg_twist)[depth] : (arm ? arm_line : leg_line)[depth];
		else
			j->kind[b] = arm ? beyond_hand(s, b) : JOINT_TOES;
	}
	for (int b = 1; b < s->count; b++)
		if (j->kind[b] == JOINT_OTHER && skel_branch_start(s, r, b) == start)
			j->kind[b] = arm ? beyond_hand(s, b) : JOINT_TOES;
}

/* Along the spine by height: the hips at the root, the neck and head at
 * the top. */
static skel_joint_kind spine_kind(const skel_roles *r, const skel_pose *p, int b)
{
	if (b == r->head_bone)
		return JOINT_NECK;
	float h = (p->head[b].y - r->ymin) / (r->H > 0.0f ? r->H : 1.0f);
	return h > 0.80f ? JOINT_NECK : h > 0.66f ? JOINT_CHEST : h > 0.56f ? JOINT_BACK : JOINT_HIPS;
}

static skel_side side_of(const skel *s, const skel_pose *p, int b)
{
	skel_side sd = side_from_name(s->bone[b].name);
	if (sd != SIDE_NONE)
		return sd;
	float dx = p->head[b].x - p->tip[0].x;
	return dx > 0.0f ? SIDE_LEFT : SIDE_RIGHT;
}

void skel_joints_find(const skel *s, const skel_pose *p, skel_joints *out)
{
	skel_roles r;
	memset(out, 0, sizeof *out);
	out->count = s->count;
	out->skel = s;
	if (s->count < 2) {
		out->kind[0] = JOINT_HIPS;
		return;
	}
	skel_find_roles(s, p, &r);
	out->biped = skel_roles_biped(s, &r);
	out->kind[0] = JOINT_HIPS;
	for (int b = 1; b < s->count; b++)
		if (r.spine[b])
			out->kind[b] = spine_kind(&r, p, b);
		else if (skel_branch_start(s, &r, b) == b)
			name_limb(s, &r, p, b, out);
	for (int b = 1; b < s->count; b++)
		if (!r.spine[b] && out->kind[b] != JOINT_PELVIS)
			out->side[b] = side_of(s, p, b);
}

const char *skel_joint_name(const skel_joints *j, int bone, char *buf, size_t cap)
{
	static const char *const sides[] = { "", "LEFT ", "RIGHT " };
	if (bone < 0 || bone >= j->count)
		return skp_format(buf, cap, "JOINT"), buf;
	if (cap == 0)
		return buf;
	if (!j->biped && j->skel) {
		size_t i = 0;
		for (const char *c = j->skel->bone[bone].name; *c && i + 1 < cap; c++)
			buf[i++] = *c >= 'a' && *c <= 'z' ? (char)(*c - 'a' + 'A') : *c;
		buf[i] = '\0';
		return buf;
	}
	int k = j->kind[bone] < JOINT_KIND_COUNT ? j->kind[bone] : JOINT_OTHER;
	int sd = j->side[bone] <= SIDE_RIGHT ? j->side[bone] : SIDE_NONE;
	skp_format(buf, cap, "%s%s", sides[sd], kind_names[k]);
	return buf;
}

/* The bone's rotation since the bind pose, in world axes. */
static quat moved(const skel_pose *bind, const skel_pose *pose, int b)
{
	return quat_mul(pose->rot[b], quat_conj(bind->rot[b]));
}

/* Whether the joint moved since the bind pose: what the close-up's choice
 * of joint goes by (not how bent it is: an elbow bound bent is no reason
 * to tell of it rather than the wrist). */
static float moved_most(skel_joint_turn t)
{
	return t.swing > t.twist ? t.swing : t.twist;
}

int skel_joint_turning(const skel *s, const skel_joints *j, const skel_pose *bind, const skel_pose *pose, int bone,
		       skel_joint_turn *t)
{
	*t = skel_joint_turned(s, j, bind, pose, bone);
	int up = bone > 0 && bone < s->count ? s->bone[bone].parent : -1;
	if (up <= 0 || moved_most(*t) >= 30.0f)
		return bone;
	skel_joint_turn u = skel_joint_turned(s, j, bind, pose, up);
	if (moved_most(u) < 30.0f)
		return bone;
	*t = u;
	return up;
}

skel_turn_kind skel_joint_turn_say(skel_joint_turn t, char *buf, size_t cap, int *degrees)
{
	skel_turn_kind k = t.twist >= 30.0f && t.twist >= t.bend ? SKEL_TURN_TWIST
			   : t.bend >= 30.0f			   ? SKEL_TURN_BEND
								   : SKEL_TURN_SLIGHT;
	*degrees = k == SKEL_TURN_TWIST ? (int)lroundf(t.twist) : k == SKEL_TURN_BEND ? (int)lroundf(t.bend) : 0;
	if (k == SKEL_TURN_SLIGHT)
		skp_format(buf, cap, "%s", "");
	else
		skp_format(buf, cap, "%s %d DEG", k == SKEL_TURN_TWIST ? "TWISTED" : "BENT", *degrees);
	return k;
}

static float angle_deg(vec3 a, vec3 b)
{
	float c = fmaxf(-1.0f, fminf(1.0f, vec3_dot(a, b)));
	return acosf(c) * 57.29578f;
}

/* The bone's direction in pose p, or 0 when it has no length. */
static int direction(const skel_pose *p, int b, vec3 *d)
{
	vec3 v = vec3_sub(p->tip[b], p->head[b]);
	if (vec3_dot(v, v) < 1e-12f)
		return 0;
	*d = vec3_normalize(v);
	return 1;
}

/* The torso's bone above a limb: the first ancestor on the spine (a
 * collar bone and CMU's hipjoint, the pelvis, are the limb's). */
static int torso_above(const skel *s, const skel_joints *j, int bone)
{
	int a = s->bone[bone].parent;
	while (a > 0 && (j->side[a] != SIDE_NONE || j->kind[a] == JOINT_PELVIS))
		a = s->bone[a].parent;
	return a < 0 ? 0 : a;
}

/* How bent the joint is as a visitor measures it, or -1 to go by the
 * swing since the bind pose. An elbow or knee: the angle between its two
 * bones now, 0 the limb straight (not since the bind pose: the mesh's rest
 * pose may be bent, MakeHuman's elbows by 47 degrees, and a curl to 150
 * then read 103). A shoulder or hip: the limb's angle from hanging down
 * the torso (the bind pose's down turned with the torso since), 0 at the
 * side, 170 an arm raised 80 degrees above the horizontal (the swing from
 * MakeHuman's A-pose read 112). */
static float visitor_bend(const skel *s, const skel_joints *j, const skel_pose *bind, const skel_pose *pose,
			  int bone, int up)
{
	vec3 d, u;
	if (!j->biped || !direction(pose, bone, &d))
		return -1.0f;
	switch (j->kind[bone]) {
	case JOINT_ELBOW:
	case JOINT_KNEE:
		return up >= 0 && direction(pose, up, &u) ? angle_deg(u, d) : -1.0f;
	case JOINT_SHOULDER:
	case JOINT_HIP:
		u = quat_rotate(moved(bind, pose, torso_above(s, j, bone)), vec3_make(0.0f, -1.0f, 0.0f));
		return angle_deg(u, d);
	default:
		return -1.0f;
	}
}

skel_joint_turn skel_joint_turned(const skel *s, const skel_joints *j, const skel_pose *bind, const skel_pose *pose,
				  int bone)
{
	skel_joint_turn t = { 0.0f, 0.0f, 0.0f };
	if (bone <= 0 || bone >= s->count)
		return t;
	int up = s->bone[bone].parent;
	while (up > 0 && j->kind[up] == j->kind[bone] && j->side[up] == j->side[bone])
		up = s->bone[up].parent;
	/* the turn in the bind pose's world axes: the parent's motion undone */
	quat q = quat_mul(quat_conj(moved(bind, pose, up < 0 ? 0 : up)), moved(bind, pose, bone));
	vec3 axis;
	if (!direction(bind, bone, &axis))
		return t;
	if (q.w < 0.0f)
		q = (quat){ -q.w, -q.x, -q.y, -q.z };
	float along = q.x * axis.x + q.y * axis.y + q.z * axis.z;
	t.twist = fabsf(2.0f * atan2f(along, q.w)) * 57.29578f;
	t.swing = angle_deg(quat_rotate(q, axis), axis);
	float bend = visitor_bend(s, j, bind, pose, bone, up);
	t.bend = bend >= 0.0f ? bend : t.swing;
	return t;
}
