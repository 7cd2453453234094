#include "report_render.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli_inputs.h"
#include "report_chart.h"
#include "png_writer.h"

static int open_display(report_view *v, int w, int h)
{
	skp_error err;
	display_config cfg = { w, h, NULL, 0 };
	v->disp = display_find("surfaceless");
	if (v->disp->init(&cfg, &v->info, &err) != 0) {
		fprintf(stderr, "skintool compare: surfaceless: %s; trying osmesa\n", err.msg);
		v->disp = display_find("osmesa");
		if (v->disp->init(&cfg, &v->info, &err) != 0) {
			fprintf(stderr, "skintool compare: osmesa: %s\n", err.msg);
			v->disp = NULL;
			return -1;
		}
	}
	if (gl_api_load(&v->gl, v->disp->get_proc, &err) != SKP_OK) {
		fprintf(stderr, "skintool compare: %s: %s\n", v->disp->name, err.msg);
		v->disp->shutdown();
		v->disp = NULL;
		return -1;
	}
	return 0;
}

int report_view_open(report_view *v, const cli_skin *sk, const mesh *m, float floor_y, int w, int h)
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
	v->started = 1;
	return 0;
}

/* The joint's pixel in panel i (top-down rows) for the camera just used. */
static void project(const report_view *v, int i, vec3 joint, float *x, float *y)
{
	int hw = v->info.width / 2, h = v->info.height;
	mat4 vp = camera_matrix(&v->r.cam, (float)hw / (float)h);
	vec3 ndc = mat4_transform_point(&vp, joint);
	*x = (float)(i * hw) + (ndc.x * 0.5f + 0.5f) * (float)hw;
	*y = (float)h - (ndc.y * 0.5f + 0.5f) * (float)h;
}

static void mark(report_view *v, vec3 joint, int closeup)
{
	static const rgba8 dark = { 20, 20, 20, 200 }, hot = { 255, 196, 0, 255 };
	canvas c = { v->top_down, v->info.width, v->info.height };
	float radius = (float)v->info.height * (closeup ? 0.16f : 0.055f);
	for (int i = 0; i < 2; i++) {
		float x, y;
		project(v, i, joint, &x, &y);
		canvas_ring(&c, x, y, radius, 6.0f, dark);
		canvas_ring(&c, x, y, radius, 3.0f, hot);
	}
}

static void flip(report_view *v)
{
	size_t row = (size_t)v->info.width * 4;
	for (int y = 0; y < v->info.height; y++)
		memcpy(v->top_down + row * (size_t)y, v->rgba + row * (size_t)(v->info.height - 1 - y), row);
}

/* Aims the camera: the whole body (snapped to the skeleton's centre by the
 * next draw), or the joint from near, from the side it sticks out to. */
static void aim(report_view *v, const cli_skin *sk, vec3 joint, int closeup, follow_camera *saved)
{
	follow_camera *cam = &v->r.cam;
	*saved = *cam;
	cam->started = 0;
	if (!closeup)
		return;
	vec3 root = sk->pose.tip[0];
	float dx = joint.x - root.x, dz = joint.z - root.z;
	cam->started = 1;
	cam->target = joint;
	cam->height = 0.35f * saved->height;
	if (dx * dx + dz * dz > 1e-6f * saved->height * saved->height)
		cam->azimuth = atan2f(dx, dz);
}

int report_view_compare(report_view *v, cli_skin *sk, vec3 joint, int closeup, const char *hud0,
			const char *hud1, const char *path)
{
	skp_error err;
	render_frame f;
	memset(&f, 0, sizeof f);
	f.pose = &sk->pose;
	f.bones = &sk->bones;
	f.panel_count = 2;
	f.view = RENDER_VIEW_BODY;
	f.hud[0] = hud0;
	f.hud[1] = hud1;
	f.dt = 0.0f;
	static const skin_algo algo[2] = { SKIN_LBS, SKIN_DQBS };
	static const char *label[2] = { "LBS", "DQBS" };
	for (int i = 0; i < 2; i++) {
		cli_skin_run(sk, algo[i], v->pos[i], v->nrm[i]);
		f.panel[i] = (render_panel){ .algo = algo[i], .pos = v->pos[i], .nrm = v->nrm[i], .label = label[i] };
	}
	follow_camera saved;
	aim(v, sk, joint, closeup, &saved);
	render_upload(&v->r, &f);
	render_draw(&v->r, &f);
	v->gl.Finish();
	render_read_rgba(&v->r, v->rgba);
	flip(v);
	mark(v, joint, closeup);
	v->r.cam = saved;
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
