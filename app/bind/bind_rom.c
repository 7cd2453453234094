#include "bind_rom.h"

#include <math.h>
#include <string.h>

#include "skel_roles.h"

#define DEG 0.017453292519943295f

typedef struct rom_ctx {
	const skel *s;
	const skel_pose *p;
	skel_roles roles;
	vec3 front;
	bind_rom *out;
} rom_ctx;

static float bone_len(const skel_pose *p, int b)
{
	return vec3_length(vec3_sub(p->tip[b], p->head[b]));
}

static vec3 bone_dir(const skel_pose *p, int b)
{
	return vec3_normalize(vec3_sub(p->tip[b], p->head[b]));
}

/* The child reaching furthest, or -1. */
static int next_in_chain(const rom_ctx *c, int b)
{
	int next = -1;
	float best = -1.0f;
	for (int k = 1; k < c->s->count; k++)
		if (c->s->bone[k].parent == b && bone_len(c->p, k) + c->roles.reach[k] > best) {
			best = bone_len(c->p, k) + c->roles.reach[k];
			next = k;
		}
	return next;
}

static int chain_of(const rom_ctx *c, int start, int *chain)
{
	int n = 0;
	for (int b = start; b > 0 && n < SKP_MAX_BONES; b = next_in_chain(c, b))
		chain[n++] = b;
	return n;
}

/* How far the bone's head is out to the side of the root's vertical. */
static float out_to_side(const rom_ctx *c, int b)
{
	vec3 d = vec3_sub(c->p->head[b], c->p->head[0]);
	return vec3_length(vec3_sub(d, vec3_scale(c->roles.up, vec3_dot(d, c->roles.up))));
}

/* The limb's upper bone: one a motion turns (it has channels); a leg's
 * the first 0.6 as long as the limb's longest, an arm's the first 0.3 as
 * long starting out to the side by 0.3 of its length (not the clavicle,
 * which starts at the spine, however far a mesh's shoulders stretched it). */
static int is_upper(const rom_ctx *c, int b, int leg, float longest)
{
	float len = bone_len(c->p, b);
	if (!c->s->bone[b].channel_count)
		return 0;
	return leg ? len >= 0.6f * longest : len >= 0.3f * longest && out_to_side(c, b) >= 0.3f * len;
}

/* upper, lower and end bone of a limb: -1 where there is none */
static void limb_bones(const rom_ctx *c, int start, int *bones)
{
	int chain[SKP_MAX_BONES], n = chain_of(c, start, chain), k = 0;
	float longest = 0.0f;
	for (int i = 0; i < n; i++)
		longest = fmaxf(longest, bone_len(c->p, chain[i]));
	bones[0] = bones[1] = bones[2] = -1;
	for (int i = 0; i < n && k < 3; i++)
		if (k ? bone_len(c->p, chain[i]) > 0.05f * longest : is_upper(c, chain[i], c->roles.leg[start], longest))
			bones[k++] = chain[i];
}

/* The way the feet point, level; the skeleton's depth axis without feet. */
static vec3 find_front(const rom_ctx *c)
{
	vec3 f = vec3_make(0.0f, 0.0f, 0.0f);
	for (int b = 1; b < c->s->count; b++) {
		int bones[3];
		if (!c->roles.leg[b] || skel_branch_start(c->s, &c->roles, b) != b)
			continue;
		limb_bones(c, b, bones);
		if (bones[2] >= 0)
			f = vec3_add(f, vec3_sub(c->p->tip[bones[2]], c->p->head[bones[2]]));
	}
	float along = vec3_dot(f, c->roles.depth);
	return along < 0.0f ? vec3_scale(c->roles.depth, -1.0f) : c->roles.depth;
}

static void add(rom_ctx *c, int bone, bind_rom_kind kind, int degrees, vec3 axis)
{
	float len = vec3_length(axis);
	if (bone <= 0 || c->out->count == BIND_ROM_MAX_MOVES || !(len > 0.2f))
		return;   /* no bone, or the bone already points that way */
	bind_rom_move *m = &c->out->move[c->out->count++];
	m->bone = bone;
	m->kind = kind;
	m->degrees = degrees;
	m->turn = quat_from_axis_angle(vec3_scale(axis, 1.0f / len), (float)degrees * DEG);
}

/* Turns bone toward the direction to: about the axis bone x to. */
static void add_toward(rom_ctx *c, int bone, bind_rom_kind kind, int degrees, vec3 to)
{
	if (bone > 0)
		add(c, bone, kind, degrees, vec3_cross(bone_dir(c->p, bone), to));
}

static void add_limb(rom_ctx *c, int start)
{
	int b[3];
	limb_bones(c, start, b);
	vec3 up = c->roles.up, back = vec3_scale(c->front, -1.0f);
	if (c->roles.leg[start]) {
		float side = vec3_dot(vec3_sub(c->p->head[start], c->p->head[0]), c->roles.side);
		vec3 out = vec3_scale(c->roles.side, side < 0.0f ? -1.0f : 1.0f);
		add_toward(c, b[0], BIND_ROM_FORWARD, 60, c->front);
		add_toward(c, b[0], BIND_ROM_BACK, 20, back);
		add_toward(c, b[0], BIND_ROM_OUT, 30, out);
		add_toward(c, b[1], BIND_ROM_BEND, 90, back);
		add_toward(c, b[2], BIND_ROM_UP, 25, up);
		return;
	}
	add_toward(c, b[0], BIND_ROM_FORWARD, 60, c->front);
	add_toward(c, b[0], BIND_ROM_UP, 40, up);
	add_toward(c, b[0], BIND_ROM_DOWN, 40, vec3_scale(up, -1.0f));
	add_toward(c, b[1], BIND_ROM_BEND, 90, c->front);
	add_toward(c, b[2], BIND_ROM_FORWARD, 40, c->front);
}

/* The lowest spine bone with a length, and the one above the bone the
 * arms hang from (the neck). */
static void add_spine(rom_ctx *c)
{
	const skel *s = c->s;
	int low = -1, chest = -1;
	for (int b = c->roles.head_bone; b > 0; b = s->bone[b].parent)
		if (bone_len(c->p, b) > 0.0f)
			low = b;
	for (int b = 1; b < s->count; b++)
		if (c->roles.arm[b] && skel_branch_start(s, &c->roles, b) == b && c->roles.spine[s->bone[b].parent])
			chest = s->bone[b].parent;
	int neck = -1;
	for (int b = c->roles.head_bone; b > 0 && chest >= 0; b = s->bone[b].parent)
		if (s->bone[b].parent == chest)
			neck = b;
	add_toward(c, low, BIND_ROM_BEND, 30, c->front);
	if (low > 0)
		add(c, low, BIND_ROM_TWIST, 30, bone_dir(c->p, low));
	add_toward(c, neck, BIND_ROM_BEND, 30, c->front);
	if (neck > 0)
		add(c, neck, BIND_ROM_TWIST, 40, bone_dir(c->p, neck));
}

void bind_rom_build(const skel *s, const skel_pose *bind, bind_rom *out)
{
	rom_ctx c;
	memset(&c, 0, sizeof c);
	c.s = s;
	c.p = bind;
	c.out = out;
	out->count = 0;
	if (s->count < 2)
		return;
	skel_find_roles(s, bind, &c.roles);
	c.front = find_front(&c);
	for (int b = 1; b < s->count; b++)
		if ((c.roles.arm[b] || c.roles.leg[b]) && skel_branch_start(s, &c.roles, b) == b)
			add_limb(&c, b);
	add_spine(&c);
}

int bind_rom_below(const skel *s, int b, int a)
{
	for (int d = 0; b >= 0 && d <= SKP_MAX_BONES; b = s->bone[b].parent, d++)
		if (b == a)
			return 1;
	return 0;
}

void bind_rom_pose(const skel *s, const skel_pose *bind, const bind_rom_move *m, skel_pose *out)
{
	*out = *bind;
	vec3 pivot = bind->head[m->bone];
	for (int b = 0; b < s->count; b++) {
		if (!bind_rom_below(s, b, m->bone))
			continue;
		out->head[b] = vec3_add(pivot, quat_rotate(m->turn, vec3_sub(bind->head[b], pivot)));
		out->tip[b] = vec3_add(pivot, quat_rotate(m->turn, vec3_sub(bind->tip[b], pivot)));
		out->rot[b] = quat_mul(m->turn, bind->rot[b]);
	}
}

const char *bind_rom_kind_name(bind_rom_kind k)
{
	static const char *const names[BIND_ROM_KIND_COUNT] = {
		"forward", "back", "out", "up", "down", "bent", "twisted",
	};
	return k < BIND_ROM_KIND_COUNT ? names[k] : "?";
}
