/* One pass over a clip before it plays: how long it is, which way the
 * body faces on average (the camera's `yaw = auto` turns to it, so a clip
 * captured facing away is seen from the front) and the space the skeleton
 * takes over the whole clip, root motion taken out as in place (the
 * camera frames it). */
#ifndef PLAY_EXTENT_H
#define PLAY_EXTENT_H

#include "fk.h"
#include "play_source.h"

typedef struct play_extent {
	long frames;             /* frames read */
	float facing;            /* mean facing about the vertical, radians:
	                          * 0 = +z, pi/2 = +x */
	int facing_known;        /* 0: no frame said (no feet, no frames) */
	vec3 lo, hi;             /* joint bounds over the clip, the root's
	                          * horizontal travel taken out */
	vec3 first_root;         /* the first frame's root: every frame's
	                          * root is moved over it for lo, hi */
	vec3 travel_lo, travel_hi; /* the root's way over the ground from the
	                          * first frame's, x and z (y 0): a wall's
	                          * camera frames lo, hi moved along all of it */
} play_extent;

/* Reads src from its first frame to its last (FK every `stride`-th frame,
 * >= 1) and seeks back to the first. Frame buffers are the caller's
 * (frame, pose). SKP_OK or the source's error. */
skp_status play_extent_clip(const skel *s, const play_source *src, int stride, amc_frame *frame,
			    skel_pose *pose, play_extent *out, skp_error *err);

/* The direction a posed body faces, about the vertical: adds the unit
 * vectors its feet point along (ankle to toe tip, whatever the skeleton's
 * names: a leaf bone near the ground that lies flat, and the flat bones
 * above it) to *sin_sum (x) and *cos_sum (z). Returns the length of what
 * it added: 0 for a skeleton without feet (a prop, a tube), whose facing
 * is not known. */
float play_pose_facing(const skel *s, const skel_pose *p, float *sin_sum, float *cos_sum);

#endif
