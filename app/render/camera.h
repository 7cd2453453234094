/* A camera that follows the body's root smoothly, so a walk stays in frame
 * without the picture jerking with every step; given the space the body
 * takes over a clip, it frames all of it (camera_frame_box). */
#ifndef CAMERA_H
#define CAMERA_H

#include "mat4.h"

typedef struct follow_camera {
	vec3 target;       /* smoothed point the camera looks at */
	int started;
	float height;      /* the body's largest extent: sets distance and framing */
	float floor_y;     /* the ground under the body */
	float azimuth;     /* radians around Y, 0 = in front (+Z) */
	float azimuth_goal; /* where camera_follow turns it */
	/* the device's own view (board.ini [camera]; render_set_view) */
	float pitch;       /* radians from above a framed box is seen (default CAMERA_PITCH) */
	float distance;    /* times the distance that frames the box (1) */
	vec3 aim;          /* the point looked at, from the box's centre, in body heights */
} follow_camera;

#define CAMERA_PITCH 0.11f   /* a framed box is seen this far from above (radians) */

void camera_init(follow_camera *c, float skel_height, float floor_y, float azimuth);

/* Moves the target towards center (the middle of the posed skeleton) and
 * the azimuth towards its goal (the short way round) over dt seconds, time
 * constant 0.6 s: smooth, yet a jump stays in frame. */
void camera_follow(follow_camera *c, vec3 center, float dt);

/* Sets the azimuth to turn to; immediate: there at once (a first frame). */
void camera_turn_to(follow_camera *c, float azimuth, int immediate);

/* View-projection for a viewport of the given aspect ratio. */
mat4 camera_matrix(const follow_camera *c, float aspect);

/* How far a smoothed value moves towards its goal in dt seconds: 1 -
 * exp(-dt / 0.6 s), the camera's time constant. */
float camera_ease(float dt);

/* The share of the way an exponential ease with a time constant of seconds
 * covers in dt seconds; all of it for dt <= 0 (a first frame, a still). */
float camera_ease_in(float dt, float seconds);

/* View-projection for a viewport of the given aspect ratio that shows the
 * whole box [lo, hi] (world space) from the camera's azimuth, a little from
 * above, as large as it fits between the rows ndc_bottom and ndc_top
 * (-1..1, bottom to top; the rest of the viewport is kept for text) and
 * across the whole width, centred in both. */
mat4 camera_frame_box(const follow_camera *c, vec3 lo, vec3 hi, float aspect, float ndc_bottom, float ndc_top);

#endif
