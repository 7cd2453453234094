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
	skel_joints_find(&p->body.skel, &p->body.pose, &p->joints);
	skin_diff_init(&p->diff, &p->body.skel, &p->body.pose, &p->joints, &p->skin.soa);
	closeup_pick_init(&p->pick);
	p->focus_joint = -1;
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
			runtime_skin_run(&p->skin, p->algo[i], p->pos[i], p->nrm[i]);
	return 1;
}

/* What the visitor should look at, by what the joint did. */
static const char *look_at(skel_turn_kind k)
{
	return k == SKEL_TURN_TWIST ? "LOOK AT ITS WIDTH" : k == SKEL_TURN_BEND ? "LOOK AT THE BEND" : "LOOK AT ITS SHAPE";
}

/* How far apart the two methods put the joint's skin, in millimetres:
 * the figure the close-up was chosen by. */
static void apart_note(skinplay *p, int joint, float mm)
{
	snprintf(p->closeup_apart, sizeof p->closeup_apart, "LBS %d MM FROM DQBS",
		 (int)lroundf(p->diff.score[joint] * mm));
}

/* The close-up on joint; measured: the panels' positions are this
 * frame's, else the focus of the frame last measured stands (it came from
 * the same positions). */
static void fill_closeup(skinplay *p, render_frame *f, int joint, int measured)
{
	render_closeup *c = &f->closeup;
	c->joint = joint;
	if (joint < 0)
		return;
	if (measured || joint != p->focus_joint) {
		p->focus = skin_diff_focus(&p->diff, &p->skin.pose, p->pos[0], p->pos[1], joint);
		p->focus_joint = joint;
	}
	c->focus = p->focus.at;
	c->span = p->focus.reach;
	skel_joint_turn t;
	int deg, named = skel_joint_turning(&p->body.skel, &p->joints, &p->body.pose, &p->skin.pose, joint, &t);
	c->title = skel_joint_name(&p->joints, named, p->closeup_title, sizeof p->closeup_title);
	/* the visitor is told what to look at, the engineer by how much */
	const char *look = look_at(skel_joint_turn_say(t, p->closeup_note, sizeof p->closeup_note, &deg));
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
			fill_closeup(p, f, p->pick.joint, 0); /* between the frames measured: the last choice */
		return;
	}
	float *dist = diff_view ? p->diff_value : NULL;
	if (p->panel_count > 1) {
		skin_diff_between(&p->diff, p->pos[0], p->pos[1], dist);
		fill_closeup(p, f, closeup_pick_update(&p->pick, p->diff.score, p->body.skel.count, f->dt), 1);
	} else if (diff_view) {
		skin_diff_from_bind(&p->diff, &p->skin.pose, p->pos[0], dist);
	}
	f->diff = dist;
	f->diff_signed = p->panel_count < 2;
}
