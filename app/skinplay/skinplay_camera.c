/* The engineer's camera in a window: a drag with the left button turns it
 * round the body and up or down, one with the right or middle button (or
 * shift and left) moves the point it looks at, the wheel brings it nearer
 * or farther; f frames the body again, r puts the camera back where it
 * began. The moves are the device camera's (render_set_view: pitch,
 * distance, aim) and a turn added to the clip's yaw, so the framing that
 * follows the body and the clip changes keeps them. */
#include <math.h>
#include <stdio.h>

#include "cli_quiet.h"
#include "skinplay.h"

#define TURN_PER_PX 0.01f     /* radians a pixel dragged */
#define ZOOM_PER_CLICK 0.85f  /* the distance times this a wheel click nearer */

static float clampf(float v, float lo, float hi)
{
	return v < lo ? lo : v > hi ? hi : v;
}

static void apply(skinplay *p)
{
	render_set_view(&p->r, &p->o.view_cam);
	render_set_yaw(&p->r, p->yaw + p->cam_yaw, 1);
}

static void say(const skinplay *p, const char *what)
{
	fprintf(cli_note(), "input: %s -> camera yaw %+.0f, pitch %.0f, distance %.2f, aim %.2f %.2f %.2f\n", what,
		p->cam_yaw * 180.0 / M_PI, p->o.view_cam.pitch * 180.0 / M_PI, p->o.view_cam.distance,
		p->o.view_cam.aim.x, p->o.view_cam.aim.y, p->o.view_cam.aim.z);
}

/* A pan of dx, dy pixels: the aim moves across and up the picture, in
 * body heights, as far as the pointer went at the body's distance. */
static void pan(skinplay *p, int dx, int dy)
{
	float az = RENDER_CAMERA_AZIMUTH + p->yaw + p->cam_yaw;
	float k = 1.2f * p->o.view_cam.distance / (float)(p->info.height > 0 ? p->info.height : 1);
	vec3 side = vec3_make(cosf(az), 0.0f, -sinf(az)), *aim = &p->o.view_cam.aim;
	*aim = vec3_add(*aim, vec3_scale(side, -(float)dx * k));
	aim->y += (float)dy * k;
	aim->x = clampf(aim->x, -5.0f, 5.0f);
	aim->y = clampf(aim->y, -5.0f, 5.0f);
	aim->z = clampf(aim->z, -5.0f, 5.0f);
}

/* A move of the pointer's (or a camera key's as one): turn, tilt, pan,
 * zoom; what says which, for the log. */
static void camera_move(skinplay *p, const display_pointer *m, const char *what)
{
	p->cam_yaw -= (float)m->orbit_dx * TURN_PER_PX;
	p->o.view_cam.pitch = clampf(p->o.view_cam.pitch + (float)m->orbit_dy * TURN_PER_PX, -0.5f, 1.4f);
	if (m->pan_dx || m->pan_dy)
		pan(p, m->pan_dx, m->pan_dy);
	if (m->wheel)
		p->o.view_cam.distance = clampf(p->o.view_cam.distance * powf(ZOOM_PER_CLICK, (float)m->wheel), 0.2f, 10.0f);
	apply(p);
	if (what)
		say(p, what);
}

void camera_pointer(skinplay *p)
{
	display_pointer m;
	if (!p->disp || !p->disp->pointer || !p->render_ready)
		return;
	p->disp->pointer(&m);
	if (!m.orbit_dx && !m.orbit_dy && !m.pan_dx && !m.pan_dy && !m.wheel) {
		if (m.released)
			say(p, "drag");
		return;
	}
	camera_move(p, &m, m.released || m.wheel ? (m.wheel ? "wheel" : "drag") : NULL);
}

/* A console's camera key as the pointer's move: 15 degrees a turn, 10 a
 * tilt, a twentieth of the picture a move, a wheel click a zoom. */
static void camera_step(skinplay *p)
{
	const kiosk_camera_step *c = &p->kiosk.cam;
	int turn_px = (int)lroundf(0.2618f / TURN_PER_PX), tilt_px = (int)lroundf(0.1745f / TURN_PER_PX);
	int move_px = (p->info.height > 0 ? p->info.height : 480) / 20;
	display_pointer m = { c->turn * turn_px, c->tilt * tilt_px, -c->move_x * move_px, c->move_y * move_px, c->zoom, 0 };
	camera_move(p, &m, "camera key");
}

void camera_key(skinplay *p, unsigned act)
{
	if (!(act & KIOSK_ACT_CAMERA) || !p->render_ready)
		return;
	if (p->kiosk.camera == 3) {
		camera_step(p);
		return;
	}
	float pitch = p->o.view_cam.pitch;
	p->o.view_cam = p->view_home;
	if (p->kiosk.camera == 1)
		p->o.view_cam.pitch = pitch; /* f: the body framed again from where the camera is turned */
	else
		p->cam_yaw = 0.0f;
	apply(p);
	say(p, p->kiosk.camera == 1 ? "key f" : "key r");
}
