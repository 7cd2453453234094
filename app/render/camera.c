#include "camera.h"

#include <math.h>

void camera_init(follow_camera *c, float skel_height, float floor_y, float azimuth)
{
	c->started = 0;
	c->height = skel_height > 0 ? skel_height : 1.0f;
	c->floor_y = floor_y;
	c->azimuth = c->azimuth_goal = azimuth;
	c->target = vec3_make(0, floor_y + 0.5f * c->height, 0);

}

void camera_follow(follow_camera *c, vec3 center, float dt)
{
	vec3 want = center;
	if (!c->started) {
		c->target = want;
		c->started = 1;
		return;
	}
	float k = 1.0f - expf(-dt / 0.6f);
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
	mat4 proj = mat4_perspective(0.6f, aspect, 0.05f * c->height, 20.0f * c->height);
	return mat4_mul(&proj, &view);
}
