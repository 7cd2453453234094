/* A camera that follows the body's root smoothly, so a walk stays in frame
 * without the picture jerking with every step. */
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
} follow_camera;

void camera_init(follow_camera *c, float skel_height, float floor_y, float azimuth);

/* Moves the target towards center (the middle of the posed skeleton) and
 * the azimuth towards its goal (the short way round) over dt seconds, time
 * constant 0.6 s: smooth, yet a jump stays in frame. */
void camera_follow(follow_camera *c, vec3 center, float dt);

/* Sets the azimuth to turn to; immediate: there at once (a first frame). */
void camera_turn_to(follow_camera *c, float azimuth, int immediate);

/* View-projection for a viewport of the given aspect ratio. */
mat4 camera_matrix(const follow_camera *c, float aspect);

#endif
