/* Rotation quaternions, w + xi + yj + zk, Hamilton convention, acting on
 * column vectors: quat_rotate(quat_mul(a, b), v) == rotate by b, then a. */
#ifndef QUAT_H
#define QUAT_H

#include "vec3.h"

typedef struct quat {
	float w, x, y, z;
} quat;

static inline quat quat_identity(void) { quat q = { 1.0f, 0.0f, 0.0f, 0.0f }; return q; }
static inline quat quat_conj(quat q) { quat r = { q.w, -q.x, -q.y, -q.z }; return r; }
static inline float quat_dot(quat a, quat b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }

quat quat_mul(quat a, quat b);
/* Rotation of `radians` about a unit axis. */
quat quat_from_axis_angle(vec3 unit_axis, float radians);
/* Rotation about the x (0), y (1) or z (2) axis. */
quat quat_from_basis_angle(int axis, float radians);
quat quat_normalize(quat q);
vec3 quat_rotate(quat q, vec3 v);
/* Row-major 3x3 rotation matrix m[row][col]. */
void quat_to_mat3(quat q, float m[3][3]);
/* Unit quaternion of a rotation matrix (Shepperd's method, robust near 180 degrees). */
quat quat_from_mat3(const float m[3][3]);
/* Spherical interpolation of unit quaternions on the shortest arc (b's
 * sign is flipped when a.b < 0): a at t = 0, b at t = 1, unit length.
 * Single-precision arithmetic and sqrtf only (quat_slerp.c), so every board
 * computes the same bits. */
quat quat_slerp(quat a, quat b, float t);

#endif
