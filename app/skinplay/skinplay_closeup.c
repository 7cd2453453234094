/* What the compare view's close-up shows and what the difference view
 * colours, from the skinned results of the frame: the joint where LBS and
 * DQBS part most (held, app/render/render_closeup.h), its name, how it
 * has turned, and how far apart the two methods put its skin;
 * per vertex, LBS's distance from DQBS or the skin's from its bone. */
#include <math.h>
#include <stdio.h>

#include "skinplay.h"

/* Every 8th frame the GPU-skinned panels are skinned on the CPU too, for
 * the close-up's choice alone. */
#define CLOSEUP_CPU_EVERY 8

void closeup_setup(skinplay *p)
{
	skin_diff_init(&p->diff, &p->body.skel, &p->body.pose, &p->skin.soa);
	skel_joints_find(&p->body.skel, &p->body.pose, &p->joints);
	closeup_pick_init(&p->pick);
	if (p->render_ready)
		render_set_units(&p->r, (float)(10.0 * skel_unit_cm(&p->body.skel)));
}

/* The panels' positions for the measures: the CPU's, skinned here for a
 * panel the GPU skins. 0 when this frame has none. */
static int positions(skinplay *p, int need_every_frame)
{
	int gpu = 0;
	for (int i = 0; i < p->panel_count; i++)
		gpu |= p->gpu[i];
	if (!gpu)
		return 1;
	if (!need_every_frame && p->shown % CLOSEUP_CPU_EVERY)
		return 0;
	for (int i = 0; i < p->panel_count; i++)
		if (p->gpu[i])
			cli_skin_run(&p->skin, p->algo[i], p->pos[i], p->nrm[i]);
	return 1;
}

/* "TWISTED 178 DEG" or "BENT 150 DEG", whichever the joint did more; ""
 * when it hardly moved. */
static float turned(const skel_joint_turn *t)
{
	return t->bend > t->twist ? t->bend : t->twist;
}

/* The joint a visitor should be told of: the one whose vertices part, or
 * its parent joint when that one turned and it did not (the skin between
 * CMU's wrist and hand is nearest the hand's joint, the twist is the
 * wrist's). */
static int turning_joint(skinplay *p, int joint, skel_joint_turn *t)
{
	int up = p->body.skel.bone[joint].parent;
	*t = skel_joint_turned(&p->body.skel, &p->joints, &p->body.pose, &p->skin.pose, joint);
	if (up <= 0 || turned(t) >= 30.0f)
		return joint;
	skel_joint_turn u = skel_joint_turned(&p->body.skel, &p->joints, &p->body.pose, &p->skin.pose, up);
	if (turned(&u) < 30.0f)
		return joint;
	*t = u;
	return up;
}

static const char *turn_note(skinplay *p, const skel_joint_turn *tp)
{
	skel_joint_turn t = *tp;
	p->closeup_note[0] = '\0';
	if (t.twist >= 30.0f && t.twist >= t.bend) {
		snprintf(p->closeup_note, sizeof p->closeup_note, "TWISTED %d DEG", (int)lroundf(t.twist));
		return "LOOK AT ITS WIDTH";
	}
	if (t.bend >= 30.0f) {
		snprintf(p->closeup_note, sizeof p->closeup_note, "BENT %d DEG", (int)lroundf(t.bend));
		return "LOOK AT THE BEND";
	}
	return "LOOK AT ITS SHAPE";
}

/* How far apart the two methods put the joint's skin, in millimetres:
 * the figure the close-up was chosen by. */
static void apart_note(skinplay *p, int joint, float mm)
{
	snprintf(p->closeup_apart, sizeof p->closeup_apart, "LBS %d MM FROM DQBS",
		 (int)lroundf(p->diff.score[joint] * mm));
}

static void fill_closeup(skinplay *p, render_frame *f, int joint)
{
	render_closeup *c = &f->closeup;
	c->joint = joint;
	if (joint < 0)
		return;
	int found;
	vec3 at = skin_diff_focus(&p->diff, p->pos[0], p->pos[1], joint, &found);
	c->focus = found ? at : p->skin.pose.head[joint];
	c->span = found ? skin_diff_reach(&p->diff, p->pos[0], p->pos[1], joint, at) : 0.0f;
	skel_joint_turn t;
	int named = turning_joint(p, joint, &t);
	c->title = skel_joint_name(&p->joints, named, p->closeup_title, sizeof p->closeup_title);
	/* the visitor is told what to look at, the engineer by how much */
	const char *look = turn_note(p, &t);
	c->note = p->closeup_note[0] ? p->closeup_note : NULL;
	apart_note(p, joint, p->r.mm_per_unit);
	for (int i = 0; i < p->panel_count; i++)
		c->effect[i] = p->o.hud == BOARD_HUD_VISITOR ? look : p->closeup_apart;
}

void closeup_frame(skinplay *p, render_frame *f)
{
	int diff_view = f->view == RENDER_VIEW_DIFFERENCE;
	f->diff = NULL;
	f->closeup.joint = -1;
	if (p->hold || !positions(p, diff_view)) {
		if (p->panel_count > 1 && !p->hold)
			fill_closeup(p, f, p->pick.joint); /* between the frames measured: the last choice */
		return;
	}
	float *dist = diff_view ? p->diff_value : NULL;
	if (p->panel_count > 1) {
		skin_diff_between(&p->diff, p->pos[0], p->pos[1], dist);
		fill_closeup(p, f, closeup_pick_update(&p->pick, p->diff.score, p->body.skel.count, f->dt));
	} else if (diff_view) {
		skin_diff_from_bind(&p->diff, &p->skin.pose, p->pos[0], dist);
	}
	f->diff = dist;
	f->diff_signed = p->panel_count < 2;
}
