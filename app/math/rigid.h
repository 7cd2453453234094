/* Rigid transforms as a 3x4 matrix: a row-major rotation r[row][col] and a
 * translation t, acting on column vectors: p' = R p + t. This is the form the
 * linear blend skinning path and the renderer consume; dq.h converts to and
 * from it. */
#ifndef RIGID_H
#define RIGID_H

#include "quat.h"
#include "vec3.h"

typedef struct rigid {
	float r[3][3];
	vec3 t;
} rigid;

rigid rigid_identity(void);
/* Rotate by the unit quaternion q, then translate by t. */
rigid rigid_from_quat_trans(quat q, vec3 t);
/* a * b: apply b first, then a (same order as quat_mul). */
rigid rigid_mul(const rigid *a, const rigid *b);
/* Exact for a rigid transform: the transpose is the inverse rotation. */
rigid rigid_inverse(const rigid *a);
vec3 rigid_apply_point(const rigid *a, vec3 p);
/* Rotation only: valid for normals because R is orthonormal. */
vec3 rigid_apply_normal(const rigid *a, vec3 n);

#endif
