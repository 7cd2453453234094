/* Headless LBS | DQBS pictures of single poses for the comparison report
 * (skintool compare): the renderer's compare view on the surfaceless
 * display (OSMesa when EGL cannot start), read back, written as PNG.
 *
 * The close-up is the kiosk's (app/skin/skin_diff.h, render_closeup.h):
 * the joint where LBS and DQBS part most in the pose (skin_diff_worst),
 * looked at from the close-up camera, centred on where they part
 * (skin_diff_focus), named for people (skel_joints.h). */
#ifndef REPORT_RENDER_H
#define REPORT_RENDER_H

#include "runtime_skin.h"
#include "display.h"
#include "render.h"
#include "skel_joints.h"
#include "skin_diff.h"

#define REPORT_VIEW_MAX_W 1600
#define REPORT_VIEW_MAX_H 800

/* Where the current pose's LBS and DQBS part (report_view_pose). */
typedef struct report_part {
	int joint;                  /* skin_diff_worst; -1: they do not differ */
	vec3 focus;                 /* skin_diff_focus on it (its head when none) */
	float apart;                /* the joint's largest distance, skeleton units */
	float reach;                /* how far from focus its vertices parted by half that or more lie */
	float mm_per_unit;          /* the renderer's (render_set_units) */
	int size_assumed;           /* the units gave no human size: the body taken as 1.75 m */
	int in_units;               /* a synthetic scene: effect in its own units, not mm */
	skel_turn_kind turn;        /* how it (or its parent joint, named) turned from the bind pose */
	int turn_deg;               /* by how much */
	char name[48];              /* skel_joint_name: "LEFT ELBOW" (skel_joint_turning: the wrist's twist
	                             * parts the skin nearest CMU's hand joint) */
	char note[32];              /* "TWISTED 180 DEG", "BENT 95 DEG", "" */
	char effect[48];            /* "LBS 23 MM FROM DQBS" */
} report_part;

/* What a picture shows: LBS on the left, DQBS on the right, always. */
typedef enum report_shot {
	REPORT_SHOT_BODY,           /* the whole body, beside it the close-up inset (the kiosk's view) */
	REPORT_SHOT_CLOSEUP,        /* each half from the close-up's side, near; where they part ringed */
	REPORT_SHOT_DIFFERENCE,     /* as BODY, coloured by how far LBS lies from DQBS (legend in mm) */
} report_shot;

/* Tens of MB: keep it static. */
typedef struct report_view {
	const display_backend *disp;
	display_info info;
	gl_api gl;
	renderer r;
	int started;                      /* renderer initialised */
	float span;                       /* the close-up shows a sphere this radius (units) */
	int scene;                        /* report_view_scene */
	skin_diff diff;
	skel_joints joints;
	report_part part;
	float pos[2][3 * SKP_MAX_VERTS], nrm[2][3 * SKP_MAX_VERTS];
	float dist[SKP_MAX_VERTS];        /* per vertex, LBS's distance from DQBS */
	uint8_t rgba[REPORT_VIEW_MAX_W * REPORT_VIEW_MAX_H * 4];
	uint8_t top_down[REPORT_VIEW_MAX_W * REPORT_VIEW_MAX_H * 4];
} report_view;

/* Opens the display at w x h and uploads the body sk skins (m's
 * triangles and colours, tex its texture or NULL; floor_y the ground
 * height); the difference view's legend in millimetres at the skeleton's
 * size (skel_unit_cm). Returns 0 or -1 (reported). */
int report_view_open(report_view *v, const runtime_skin *sk, const mesh *m, const tex_image *tex, float floor_y,
		     int w, int h);

/* A synthetic scene rather than a body: the main camera frames the
 * posed bodies of the next report_view_pose, the close-up shows a sphere
 * of radius span round where they part. */
void report_view_scene(report_view *v, float span);

/* Skins sk's current pose with LBS and DQBS and finds where they part.
 * Returns v->part. */
const report_part *report_view_pose(report_view *v, runtime_skin *sk);

/* Renders the pose of the last report_view_pose as shot, with up to two
 * HUD lines, to path. Returns 0 or -1 (reported). */
int report_view_write(report_view *v, const runtime_skin *sk, report_shot shot, const char *hud0, const char *hud1,
		      const char *path);

void report_view_close(report_view *v);

#endif
