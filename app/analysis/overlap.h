/* Where a closed mesh passes through itself (a thigh pressed into the
 * belly), its signed volume (metrics_mesh_volume) counts the overlap twice.
 * This measures that excess: the integral of w - [w >= 1] over space, w the
 * winding number of the surface around a point, so that the volume the
 * surface encloses is the signed volume minus the excess. It casts rays
 * along z through a grid of points over the mesh's x-y bounds and, on each,
 * sweeps the crossings in z order; exact along a ray, sampled across rays.
 * A surface that does not cross itself has no excess (w is 0 or 1 on every
 * ray), so the enclosed volume then is the signed one, exactly. */
#ifndef OVERLAP_H
#define OVERLAP_H

#include <stdint.h>

/* Caller-provided scratch: grid x grid rays, at most max_hits crossings. */
typedef struct overlap_work {
	int grid;
	int max_hits;
	int *ray_start;       /* grid * grid + 1 */
	float *hit_z;         /* max_hits */
	signed char *hit_dir; /* max_hits: +1 entering, -1 leaving */
} overlap_work;

/* The excess volume of the mesh (vert_count xyz triples, triangles
 * counter-clockwise seen from outside), in its own units: positive where
 * parts overlap, negative where the surface is turned inside out. Returns
 * 0 with *ok = 1, or *ok = 0 when the crossings do not fit max_hits or the
 * mesh has no extent. */
double overlap_of_mesh(const float *xyz, int vert_count, const uint32_t (*tri)[3], int tri_count,
			 const overlap_work *w, int *ok);

#endif
