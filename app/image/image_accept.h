/* What a packed image must mean before it plays, beyond its CRCs and its
 * format: the same checks for skinplay (a slot that fails is not chosen, a
 * clip that fails is skipped), skintool info (which says why) and skintool
 * pack (which refuses to write what skinplay would refuse). Each returns
 * SKP_OK or SKP_ERR_RANGE with err naming what is wrong and by how much. */
#ifndef IMAGE_ACCEPT_H
#define IMAGE_ACCEPT_H

#include "fk.h"
#include "image_format.h"
#include "mesh.h"
#include "skp_error.h"

/* The fixed-point kernel's range (fx_pos: +-32767 units): the skeleton's
 * reach from the origin, its root's travel included, stays inside it. */
#define SKP_ACCEPT_REACH 32767.0

/* Rotation channels: a million degrees (2,778 turns) either way, where a
 * float still holds a sixteenth of a degree; past it a value is noise
 * (1e30 plays as garbage). */
#define SKP_ACCEPT_ANGLE 1e6

/* Clip rates: a frame time from 1 us to 10 s. */
#define SKP_ACCEPT_MIN_FPS 0.1
#define SKP_ACCEPT_MAX_FPS 1e6

/* The skeleton: finite geometry, a direction for every bone with a
 * length, unit axis rotations, and a reach (skel_reach: the longest chain
 * of offsets and lengths from the root's position) within
 * SKP_ACCEPT_REACH. */
skp_status skp_accept_skel(const skel *s, skp_error *err);

/* The bound body against its bind pose: vertices and triangles, most
 * triangles with an area, thickness along every axis, every joint within
 * the body's bounds grown by its size, and the skeleton's centre (what
 * the camera looks at) within half its size. */
skp_status skp_accept_body(const skel *s, const skel_pose *bind, const mesh *m, skp_error *err);

/* A clip: a rate of SKP_ACCEPT_MIN_FPS..SKP_ACCEPT_MAX_FPS, frames,
 * finite non-negative steps, translation channels whose range keeps the
 * skeleton within SKP_ACCEPT_REACH and rotation channels within
 * SKP_ACCEPT_ANGLE. */
skp_status skp_accept_clip(const skel *s, const skp_image_clip *c, const float *qmin, const float *qstep,
			   skp_error *err);

#endif
