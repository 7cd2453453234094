/* The artifact measures of a skinned pose against the mesh as bound, shared
 * by skintool metrics and skintool compare so that both print the same
 * numbers for the same inputs (metrics.h has the measures):
 *   volume_ratio   enclosed volume / the volume as bound, of the mesh's
 *                  outer closed parts (parts.h: not the joint balls,
 *                  eyes or teeth inside them)
 *   radius ratios  a vertex's distance to the nearest posed bone segment
 *                  over the same distance in the bind pose, for vertices
 *                  farther than 1e-4 of the mesh's size from the bones. */
#ifndef MEASURE_H
#define MEASURE_H

#include "mesh.h"
#include "metrics.h"
#include "parts.h"

/* About 1 MB: keep it static. */
typedef struct measure_state {
	const mesh *mesh;
	int bone_count;
	double rest_volume;
	float min_rest;                 /* rest distances at or below are skipped */
	float rest_dist[SKP_MAX_VERTS];
	metrics_segments seg;              /* the current pose's bones */
	float bind_xyz[3 * SKP_MAX_VERTS];
	/* the volume is that of the outer closed parts (parts.h); with none,
	 * of every triangle, and volume_closed is 0: the figure means nothing */
	parts_summary parts;
	int volume_closed;
	int vol_tri_count;
	uint32_t vol_tri[SKP_MAX_TRIS][3];
} measure_state;

typedef struct measure_row {
	double volume_ratio;
	metrics_radius radius;
	int worst_vertex;               /* the smallest ratio's vertex, -1 if none */
} measure_row;

/* The rest state of m (bound in pose bind of a skeleton of bone_count
 * bones), and the current pose set to bind. Returns 0, or -1 after
 * reporting that the mesh encloses no volume (what names it). */
int measure_init(measure_state *t, const mesh *m, const skel_pose *bind, int bone_count,
		      const char *what);

/* Sets the posed bones the radius ratios are measured against. */
void measure_pose(measure_state *t, const skel_pose *pose);

/* The volume ratio alone of skinned positions (xyz per vertex). */
double measure_volume(const measure_state *t, const float *xyz);

/* Measures skinned positions (xyz per vertex) in the current pose. ratio,
 * when not NULL, gets every vertex's radius ratio (NAN where skipped). */
measure_row measure_skinned(const measure_state *t, const float *xyz, float *ratio);

#endif
