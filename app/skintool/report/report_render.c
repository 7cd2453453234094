#include "report_render.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli_inputs.h"
#include "png_writer.h"
#include "report_chart.h"
#include "skel.h"

static int open_display(report_view *v, int w, int h)
{
	skp_error err, first;
	display_config cfg = { w, h, NULL, 0 };
	v->disp = display_open("headless", &cfg, &v->info, &first, &err);
	if (first.code != SKP_OK)
		fprintf(stderr, "skintool compare: %s; trying osmesa\n", first.msg);
	if (!v->disp) {
		fprintf(stderr, "skintool compare: %s\n", err.msg);
		return -1;
	}
	if (gl_api_load(&v->gl, v->disp->get_proc, &err) != SKP_OK) {
		fprintf(stderr, "skintool compare: %s: %s\n", v->disp->name, err.msg);
		v->disp->shutdown();
		v->disp = NULL;
		return -1;
	}
	return 0;
}

int report_view_open(report_view *v, const runtime_skin *sk, const mesh *m, const tex_image *tex, float floor_y,
		     int w, int h)
{
	skp_error err;
	if (w > REPORT_VIEW_MAX_W || h > REPORT_VIEW_MAX_H) {
		fprintf(stderr, "skintool compare: renders are at most %dx%d\n", REPORT_VIEW_MAX_W,
			REPORT_VIEW_MAX_H);
		return -1;
	}
	if (open_display(v, w, h) < 0)
		return -1;
	if (v->info.width != w || v->info.height != h) {
		fprintf(stderr, "skintool compare: %s gave %dx%d, not %dx%d\n", v->disp->name,
			v->info.width, v->info.height, w, h);
		report_view_close(v);
		return -1;
	}
	if (render_init(&v->r, &v->gl, w, h, 0, sk->skel, &sk->soa, (const uint32_t (*)[3])m->tri,
			m->tri_count, floor_y, &err) != SKP_OK) {
		fprintf(stderr, "skintool compare: renderer: %s\n", err.msg);
		report_view_close(v);
		return -1;
	}
	render_set_colours(&v->r, m->coloured ? (const uint8_t (*)[3])m->colour : NULL);
	if (tex && render_set_texture(&v->r, m, tex, 1, &err) != SKP_OK)
		fprintf(stderr, "skintool compare: renderer: %s: the body drawn in its colours\n", err.msg);
	v->started = 1;
	v->scene = 0;
	render_set_units(&v->r, (float)(10.0 * skel_unit_cm(sk->skel)));
	v->span = CLOSEUP_SPAN * v->r.cam.height;
	skel_joints_find(sk->skel, sk->bind, &v->joints);
	skin_diff_init(&v->diff, sk->skel, sk->bind, &v->joints, &sk->soa);
	return 0;
}

void report_view_scene(report_view *v, float span)
{
	v->span = span;
	/* the inset and its ring on the body show CLOSEUP_SPAN of this */
	v->r.cam.height = span / CLOSEUP_SPAN;
	v->scene = 1;
}

/* A scene: the main camera frames both posed bodies, from the root's
 * horizontal place (render_set_extent). */
static void frame_both(report_view *v, const runtime_skin *sk)
{
	vec3 lo = vec3_make(INFINITY, INFINITY, INFINITY), hi = vec3_scale(lo, -1.0f);
	for (int i = 0; i < 2; i++)
		for (int k = 0; k < sk->soa.count; k++) {
			vec3 p = vec3_make(v->pos[i][3 * k], v->pos[i][3 * k + 1], v->pos[i][3 * k + 2]);
			lo = vec3_min(lo, p);
			hi = vec3_max(hi, p);
		}
	vec3 root = vec3_make(sk->pose.tip[0].x, 0.0f, sk->pose.tip[0].z);
	render_set_extent(&v->r, vec3_sub(lo, root), vec3_sub(hi, root), 1);
}

static vec3 vertex(const float *xyz, int k)
{
	return vec3_make(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
}

/* How far from the focus the joint's vertices that part by half its
 * largest distance or more lie, on either body: of those the focus
 * counts (not a folded elbow's hidden crease, which the ring would reach
 * round). */
static float reach(const report_view *v, int joint, const skin_focus *at)
{
	float far = 0.0f, half = 0.5f * v->diff.score[joint];
	for (int k = 0; k < v->diff.count; k++) {
		if (v->diff.joint[k] != joint || !(v->dist[k] >= half) || !skin_focus_counts(at, v->pos[0], v->pos[1], k))
			continue;
		for (int i = 0; i < 2; i++)
			far = fmaxf(far, vec3_length(vec3_sub(vertex(v->pos[i], k), at->at)));
	}
	return far;
}

/* The inset's texts: the joint's name, how it turned, how far apart the
 * methods put its skin (in mm at the body's size, as the kiosk says it; a
 * synthetic scene in its own units). */
static void describe(report_view *v, const runtime_skin *sk, report_part *p)
{
	p->mm_per_unit = v->r.mm_per_unit;
	p->size_assumed = v->r.size_assumed;
	p->in_units = v->scene;
	p->name[0] = p->note[0] = p->effect[0] = '\0';
	if (p->joint < 0)
		return;
	skel_joint_turn t;
	int named = skel_joint_turning(sk->skel, &v->joints, sk->bind, &sk->pose, p->joint, &t);
	skel_joint_name(&v->joints, named, p->name, sizeof p->name);
	p->turn = skel_joint_turn_say(t, p->note, sizeof p->note, &p->turn_deg);
	if (p->in_units)
		snprintf(p->effect, sizeof p->effect, "LBS %.2f FROM DQBS", (double)p->apart);
	else
		snprintf(p->effect, sizeof p->effect, "LBS %d MM FROM DQBS", (int)lroundf(p->apart * p->mm_per_unit));
}

const report_part *report_view_pose(report_view *v, runtime_skin *sk)
{
	static const skin_algo algo[2] = { SKIN_LBS, SKIN_DQBS };
	report_part *p = &v->part;
	for (int i = 0; i < 2; i++)
		runtime_skin_run(sk, algo[i], v->pos[i], v->nrm[i]);
	skin_diff_between(&v->diff, v->pos[0], v->pos[1], v->dist);
	p->joint = skin_diff_worst(&v->diff);
	p->apart = p->joint >= 0 ? v->diff.score[p->joint] : 0.0f;
	p->focus = sk->pose.tip[0];
	p->reach = 0.0f;
	if (p->joint >= 0) {
		skin_focus at = skin_diff_focus(&v->diff, &sk->pose, v->pos[0], v->pos[1], p->joint);
		p->focus = at.at;
		p->reach = reach(v, p->joint, &at);
	}
	describe(v, sk, p);
	if (v->scene)
		frame_both(v, sk);
	return p;
}

/* The close-up camera on the focus, at once, as the kiosk's renderer
 * moves it (seen square to the bend, or across the bone). */
static void aim_inset(report_view *v, const runtime_skin *sk)
{
	int j = v->part.joint, up = sk->skel->bone[j].parent;
	vec3 axis = vec3_sub(sk->pose.tip[j], sk->pose.head[j]);
	vec3 parent = up >= 0 ? vec3_sub(sk->pose.tip[up], sk->pose.head[up]) : vec3_make(0.0f, 0.0f, 0.0f);
	closeup_camera_follow(&v->r.inset, v->part.focus, axis, parent, v->r.cam.azimuth, 0.0f, 1);
}

/* The radius of the sphere the close-up shot shows: the inset's, or
 * more when the skin parts further out, so that the ring fits. */
static float closeup_radius(const report_view *v)
{
	return fmaxf(v->span, 1.4f * v->part.reach);
}

/* The close-up shot: the main camera put where the close-up camera is
 * (its target and side, at the distance that shows closeup_radius), for
 * render_draw's next frame (dt 0: it stays). */
static void aim_near(report_view *v)
{
	follow_camera *cam = &v->r.cam;
	float radius = closeup_radius(v);
	cam->started = 1;
	cam->target = v->r.inset.target;
	cam->azimuth = cam->azimuth_goal = v->r.inset.azimuth;
	/* camera_matrix stands 2.3 heights off: the view's half height there is the radius */
	cam->height = radius / (2.3f * tanf(0.3f));
	v->r.framed = 0;
}

/* The focus's pixel in panel i (top-down rows) for the camera just used;
 * *px_per_unit: a length there across the view, in pixels. */
static void project(const report_view *v, int i, vec3 at, float *x, float *y, float *px_per_unit)
{
	int hw = v->info.width / 2, h = v->info.height;
	mat4 vp = camera_matrix(&v->r.cam, (float)hw / (float)h);
	vec3 ndc = mat4_transform_point(&vp, at);
	float dx = v->r.cam.height; /* a step across the view, square to the camera */
	vec3 side = vec3_make(cosf(v->r.cam.azimuth), 0.0f, -sinf(v->r.cam.azimuth));
	vec3 ndc2 = mat4_transform_point(&vp, vec3_madd(at, side, dx));
	*x = (float)(i * hw) + (ndc.x * 0.5f + 0.5f) * (float)hw;
	*y = (float)h - (ndc.y * 0.5f + 0.5f) * (float)h;
	*px_per_unit = fabsf(ndc2.x - ndc.x) * 0.5f * (float)hw / dx;
}

/* Rings where the methods part in both halves of the close-up shot. */
static void ring_part(report_view *v)
{
	static const rgba8 dark = { 20, 20, 20, 200 }, hot = { 255, 196, 0, 255 };
	canvas c = { v->top_down, v->info.width, v->info.height };
	float radius = fmaxf(1.15f * v->part.reach, 0.3f * closeup_radius(v));
	for (int i = 0; i < 2; i++) {
		float x, y, scale;
		project(v, i, v->part.focus, &x, &y, &scale);
		canvas_ring(&c, x, y, radius * scale, 6.0f, dark);
		canvas_ring(&c, x, y, radius * scale, 3.0f, hot);
	}
}

static void flip(report_view *v)
{
	size_t row = (size_t)v->info.width * 4;
	for (int y = 0; y < v->info.height; y++)
		memcpy(v->top_down + row * (size_t)y, v->rgba + row * (size_t)(v->info.height - 1 - y), row);
}

int report_view_write(report_view *v, const runtime_skin *sk, report_shot shot, const char *hud0, const char *hud1,
		      const char *path)
{
	static const char *label[2] = { "LBS", "DQBS" };
	static const skin_algo algo[2] = { SKIN_LBS, SKIN_DQBS };
	skp_error err;
	render_frame f;
	memset(&f, 0, sizeof f);
	f.pose = &sk->pose;
	f.bones = &sk->bones;
	f.panel_count = 2;
	f.view = shot == REPORT_SHOT_DIFFERENCE ? RENDER_VIEW_DIFFERENCE : RENDER_VIEW_BODY;
	f.diff = shot == REPORT_SHOT_DIFFERENCE ? v->dist : NULL;
	f.hud[0] = hud0;
	f.hud[1] = hud1;
	f.dt = 0.0f;
	for (int i = 0; i < 2; i++)
		f.panel[i] = (render_panel){ .algo = algo[i], .pos = v->pos[i], .nrm = v->nrm[i], .label = label[i] };
	follow_camera saved = v->r.cam;
	int framed = v->r.framed;
	v->r.cam.started = 0; /* the whole body: snapped to it by the draw */
	f.closeup.joint = -1;
	if (v->part.joint >= 0) {
		aim_inset(v, sk);
		if (shot == REPORT_SHOT_CLOSEUP) {
			aim_near(v);
		} else {
			f.closeup = (render_closeup){ .joint = v->part.joint, .focus = v->part.focus, .title = v->part.name,
						      .note = v->part.note[0] ? v->part.note : NULL,
						      .effect = { v->part.effect, v->part.effect } };
		}
	}
	render_upload(&v->r, &f);
	render_draw(&v->r, &f);
	v->gl.Finish();
	render_read_rgba(&v->r, v->rgba);
	flip(v);
	if (shot == REPORT_SHOT_CLOSEUP && v->part.joint >= 0)
		ring_part(v);
	v->r.cam = saved;
	v->r.framed = framed;
	if (cli_output_check(path) < 0)
		return -1;
	if (png_write_rgba(path, v->top_down, v->info.width, v->info.height, 0, &err) != 0) {
		fprintf(stderr, "%s: %s\n", path, err.msg);
		return -1;
	}
	return 0;
}

void report_view_close(report_view *v)
{
	if (v->started)
		render_shutdown(&v->r);
	v->started = 0;
	if (v->disp)
		v->disp->shutdown();
	v->disp = NULL;
}
