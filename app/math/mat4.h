/* 4x4 matrices for the renderer, column-major as OpenGL takes them
 * (m[col * 4 + row]). */
#ifndef MAT4_H
#define MAT4_H

#include "vec3.h"

typedef struct mat4 {
	float m[16];
} mat4;

mat4 mat4_identity(void);
mat4 mat4_mul(const mat4 *a, const mat4 *b);
mat4 mat4_perspective(float fovy_rad, float aspect, float znear, float zfar);
mat4 mat4_ortho(float left, float right, float bottom, float top, float znear, float zfar);
mat4 mat4_look_at(vec3 eye, vec3 target, vec3 up);
/* Rotation about the view axis by a multiple of 90 degrees (kiosk screens
 * mounted sideways). */
mat4 mat4_rotate_z90(int quarter_turns);
vec3 mat4_transform_point(const mat4 *a, vec3 p);

#endif
