#include "camera.h"

#include <math.h>

void camera_init(follow_camera *c, float skel_height, float floor_y, float azimuth)
{
	c->started = 0;
	c->height = skel_height > 0 ? skel_height : 1.0f;
	c->floor_y = floor_y;
	c->azimuth = c->azimuth_goal = azimuth;
	c->target = vec3_make(0, floor_y + 0.5f * c->height, 0);
	c->pitch = CAMERA_PITCH;
	c->distance = 1.0f;
	c->aim = vec3_make(0, 0, 0);
}

#define CAMERA_FOVY 0.6f     /* radians, vertical */
#define CAMERA_MARGIN 0.04f  /* of the space it may take, left clear round a framed box */

float camera_ease_in(float dt, float seconds)
{
	return dt > 0.0f ? 1.0f - expf(-dt / seconds) : 1.0f;
}

float camera_ease(float dt)
{
	return 1.0f - expf(-dt / 0.6f);
}

void camera_follow(follow_camera *c, vec3 center, float dt)
{
	vec3 want = center;
	if (!c->started) {
		c->target = want;
		c->started = 1;
		return;
	}
	float k = camera_ease(dt);
	c->target = vec3_add(c->target, vec3_scale(vec3_sub(want, c->target), k));
	float turn = remainderf(c->azimuth_goal - c->azimuth, 6.2831853f);
	c->azimuth = turn * turn < 1e-10f ? c->azimuth_goal : c->azimuth + turn * k;
}

void camera_turn_to(follow_camera *c, float azimuth, int immediate)
{
	c->azimuth_goal = azimuth;
	if (immediate)
		c->azimuth = azimuth;
}

mat4 camera_matrix(const follow_camera *c, float aspect)
{
	float dist = 2.3f * c->height / (aspect < 1.0f ? aspect : 1.0f);
	vec3 eye = vec3_make(c->target.x + dist * sinf(c->azimuth),
			     c->target.y + 0.25f * c->height,
			     c->target.z + dist * cosf(c->azimuth));
	mat4 view = mat4_look_at(eye, c->target, vec3_make(0, 1, 0));
	mat4 proj = mat4_perspective(CAMERA_FOVY, aspect, 0.05f * c->height, 20.0f * c->height);
	return mat4_mul(&proj, &view);
}

/* Looking at centre from distance d along dir: the camera's axes. */
typedef struct box_view {
	vec3 eye, side, up, ahead;
} box_view;

static box_view view_from(vec3 centre, vec3 dir, float d)
{
	box_view v;
	v.eye = vec3_madd(centre, dir, d);
	v.ahead = vec3_scale(dir, -1.0f);
	v.side = vec3_normalize(vec3_cross(v.ahead, vec3_make(0, 1, 0)));
	v.up = vec3_cross(v.side, v.ahead);
	return v;
}

/* The box's corners projected (normalised device coordinates before any
 * shift): their extent across, x0..x1, and up, y0..y1. */
static void box_extent(const box_view *v, vec3 lo, vec3 hi, float aspect, float ext[4])
{
	float t = tanf(CAMERA_FOVY * 0.5f);
	ext[0] = ext[2] = INFINITY;
	ext[1] = ext[3] = -INFINITY;
	for (int k = 0; k < 8; k++) {
		vec3 p = vec3_make(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
		vec3 r = vec3_sub(p, v->eye);
		float z = vec3_dot(r, v->ahead);
		float x = vec3_dot(r, v->side) / (z * t * aspect), y = vec3_dot(r, v->up) / (z * t);
		ext[0] = fminf(ext[0], x);
		ext[1] = fmaxf(ext[1], x);
		ext[2] = fminf(ext[2], y);
		ext[3] = fmaxf(ext[3], y);
	}
}

static int box_fits(const box_view *v, vec3 lo, vec3 hi, float aspect, float room_h, float ext[4])
{
	box_extent(v, lo, hi, aspect, ext);
	return ext[1] - ext[0] <= 2.0f * (1.0f - CAMERA_MARGIN) && ext[3] - ext[2] <= room_h * (1.0f - CAMERA_MARGIN);
}

mat4 camera_frame_box(const follow_camera *c, vec3 lo, vec3 hi, float aspect, float ndc_bottom, float ndc_top)
{
	vec3 centre = vec3_scale(vec3_add(lo, hi), 0.5f);
	float radius = 0.5f * vec3_length(vec3_sub(hi, lo)) + 1e-6f, room = ndc_top - ndc_bottom, ext[4];
	vec3 dir = vec3_make(sinf(c->azimuth) * cosf(c->pitch), sinf(c->pitch), cosf(c->azimuth) * cosf(c->pitch));
	/* the nearest distance at which the box fits: every corner in front
	 * from just outside its sphere, the projection shrinking as it goes */
	float close = 1.05f * radius, d = 4.0f * radius;
	for (int i = 0; i < 40; i++, d *= 2.0f) {
		box_view v = view_from(centre, dir, d);
		if (box_fits(&v, lo, hi, aspect, room, ext))
			break;
	}
	for (int i = 0; i < 24; i++) {
		float mid = 0.5f * (close + d);
		box_view v = view_from(centre, dir, mid);
		if (box_fits(&v, lo, hi, aspect, room, ext))
			d = mid;
		else
			close = mid;
	}
	/* the device's own view: nearer or farther, aimed off the centre (then
	 * not re-centred: the aim is the point the integrator asked for) */
	int own = c->distance != 1.0f || c->aim.x != 0.0f || c->aim.y != 0.0f || c->aim.z != 0.0f;
	d *= c->distance;
	centre = vec3_madd(centre, c->aim, c->height);
	box_view v = view_from(centre, dir, d);
	box_extent(&v, lo, hi, aspect, ext);
	if (own)
		ext[0] = ext[2] = -1.0f, ext[1] = ext[3] = 1.0f;
	mat4 view = mat4_look_at(v.eye, centre, vec3_make(0, 1, 0));
	mat4 proj = mat4_perspective(CAMERA_FOVY, aspect, 0.02f * d, d + 20.0f * c->height + radius);
	/* centred: across the width, and between the rows kept for the box */
	mat4 shift = mat4_identity();
	shift.m[12] = -0.5f * (ext[0] + ext[1]);
	shift.m[13] = 0.5f * (ndc_bottom + ndc_top) - 0.5f * (ext[2] + ext[3]);
	mat4 m = mat4_mul(&proj, &view);
	return mat4_mul(&shift, &m);
}
