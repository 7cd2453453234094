/* The ends of a limb in the mesh's own pose (bind_pose_guess.h does the
 * upper and lower bones): below the forearm or shin, each bone of the
 * limb's longest chain (wrist, hand, fingers; foot, toes) is turned by its
 * own rotation channels toward the centroid of the mesh's vertices in a
 * cone ahead of it: within 1.1 times its reach, within 60 degrees of where
 * it points, past its joint along its parent. Each side branch off it (the
 * thumb) is turned square to the main chain, toward the body's front or
 * back as it leans, when the mesh has flesh there (20 vertices within 45
 * degrees of that square, nearer it than the main chain's direction).
 * Bones shorter than 3% of the limb, and turns under 8 degrees, are left. */
#ifndef BIND_POSE_ENDS_H
#define BIND_POSE_ENDS_H

#include "fk.h"
#include "mesh.h"
#include "skel_roles.h"

/* The direction of sum, a sum of n offsets from a joint, when n >= min_n
 * and sum is not zero: returns 1 and sets *out, else 0. */
int bind_guess_mean_dir(vec3 sum, int n, int min_n, vec3 *out);

/* Turns bone b (by its channels) toward the middle of the mesh's limb
 * where b ends: the centroid of the ring of vertices around it short of
 * its tip (a knee, an elbow; at 80% of its length, within 5% of it along
 * the bone and 30% across), when that is 2 degrees or more away (a
 * centroid of a ring is precise). Returns 1 when it turned. */
int bind_guess_ring(const skel *s, const mesh *m, int b, float *values, skel_pose *pose);

/* start: the bone after the limb's lower bone. values change in place,
 * pose is scratch. Returns the bones turned. */
int bind_guess_ends(const skel *s, const skel_roles *roles, const mesh *m, int start, float *values,
		    skel_pose *pose);

#endif
