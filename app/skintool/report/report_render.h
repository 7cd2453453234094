/* Headless LBS | DQBS pictures of single frames for the comparison report
 * (skintool compare): the renderer's compare view on the surfaceless
 * display (OSMesa when EGL cannot start), read back, the joint of
 * interest ringed in both halves, written as PNG. */
#ifndef REPORT_RENDER_H
#define REPORT_RENDER_H

#include "cli_skin.h"
#include "display.h"
#include "render.h"

#define REPORT_VIEW_MAX_W 1600
#define REPORT_VIEW_MAX_H 800

/* Tens of MB: keep it static. */
typedef struct report_view {
	const display_backend *disp;
	display_info info;
	gl_api gl;
	renderer r;
	int started;                      /* renderer initialised */
	float pos[2][3 * SKP_MAX_VERTS], nrm[2][3 * SKP_MAX_VERTS];
	uint8_t rgba[REPORT_VIEW_MAX_W * REPORT_VIEW_MAX_H * 4];
	uint8_t top_down[REPORT_VIEW_MAX_W * REPORT_VIEW_MAX_H * 4];
} report_view;

/* Opens the display at w x h and uploads the body sk skins (m's
 * triangles; floor_y the ground height). Returns 0 or -1 (reported). */
int report_view_open(report_view *v, const cli_skin *sk, const mesh *m, float floor_y, int w, int h);

/* Renders sk's current pose, LBS left and DQBS right, with up to two HUD
 * lines; close-up: the camera looks at joint from near, from the side the
 * joint faces, else it frames the whole body. The joint is ringed in both
 * halves. Returns 0 or -1 (reported). */
int report_view_compare(report_view *v, cli_skin *sk, vec3 joint, int closeup, const char *hud0,
			const char *hud1, const char *path);

void report_view_close(report_view *v);

#endif
