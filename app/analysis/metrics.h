/* Measures of skinning artifacts, as pure functions over vertex positions
 * (xyz float triples, as the float kernels write them):
 *   - the volume a closed triangle mesh encloses (LBS loses volume where
 *     it blends rotations: "candy wrapper" in a twist, collapse in a bend);
 *   - each vertex's distance to the posed skeleton's bone segments, and the
 *     range over vertices of posed distance / rest distance (how much the
 *     limbs thin or swell; 1 everywhere for a rigid motion). */
#ifndef METRICS_H
#define METRICS_H

#include <stdint.h>

#include "fk.h"

/* The bone segments head -> tip of a posed skeleton, zero-length bones
 * (the root, Acclaim's dummy bones) left out: a point has no side to
 * measure a radius from. */
typedef struct metrics_segments {
	int count;
	vec3 head[SKP_MAX_BONES];
	vec3 tip[SKP_MAX_BONES];
	vec3 axis[SKP_MAX_BONES];      /* tip - head */
	float inv_len2[SKP_MAX_BONES]; /* 1 / |axis|^2 */
} metrics_segments;

/* Keeps the bones of p (bone_count of them) longer than 1e-6 of the
 * longest one. */
void metrics_segments_from_pose(metrics_segments *out, const skel_pose *p, int bone_count);

/* Distance from q to the nearest segment (0 when there is none). */
float metrics_segment_distance(const metrics_segments *g, vec3 q);

/* out[v] = metrics_segment_distance(g, vertex v) for n vertices. */
void metrics_distances(const metrics_segments *g, const float *xyz, int n, float *out);

/* Signed volume enclosed by the triangles (counter-clockwise seen from
 * outside: positive), by the divergence theorem, summed in double about
 * the first corner so that the result does not depend on where the mesh
 * is. Only meaningful for a closed mesh. */
double metrics_mesh_volume(const float *xyz, const uint32_t (*tri)[3], int tri_count);

typedef struct metrics_radius {
	float min, max;  /* of posed / rest distance; both 1 when counted is 0 */
	int counted;     /* vertices measured */
} metrics_radius;

/* Range of metrics_segment_distance(posed, vertex v) / rest[v] over the n
 * vertices whose rest distance exceeds min_rest (a vertex on a bone has
 * no radius to keep). */
metrics_radius metrics_radius_ratio(const metrics_segments *posed, const float *xyz, const float *rest,
			      int n, float min_rest);

#endif
