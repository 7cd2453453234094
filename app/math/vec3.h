/* 3-vectors in single precision: the runtime's working type (Cortex-M4 has
 * a single-precision FPU only). */
#ifndef VEC3_H
#define VEC3_H

typedef struct vec3 {
	float x, y, z;
} vec3;

static inline vec3 vec3_make(float x, float y, float z) { vec3 v = { x, y, z }; return v; }
static inline vec3 vec3_add(vec3 a, vec3 b) { return vec3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 vec3_sub(vec3 a, vec3 b) { return vec3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 vec3_scale(vec3 a, float s) { return vec3_make(a.x * s, a.y * s, a.z * s); }
static inline float vec3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 vec3_cross(vec3 a, vec3 b)
{
	return vec3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/* a + b * s, the workhorse of skinning and FK */
static inline vec3 vec3_madd(vec3 a, vec3 b, float s)
{
	return vec3_make(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}

float vec3_length(vec3 a);
/* Unit vector along a; the zero vector stays zero. */
vec3 vec3_normalize(vec3 a);
/* Component by component: the corners of a bounding box. */
vec3 vec3_min(vec3 a, vec3 b);
vec3 vec3_max(vec3 a, vec3 b);
/* How far p lies from the segment a..b. */
float vec3_segment_distance(vec3 a, vec3 b, vec3 p);

#endif
