/* A generated "mannequin" body around any skeleton, in its rest pose with
 * the arms out (skel_tpose.h):
 * one implicit field (a smooth union of tapered, partly squashed capsules:
 * torso, neck, head, one per limb bone) polygonised with marching
 * tetrahedra. The result is closed, 2-manifold and outward oriented by
 * construction, so skinning and the renderer can rely on it when no
 * artist mesh fits the skeleton. */
#ifndef MANNEQUIN_H
#define MANNEQUIN_H

#include <stdint.h>

#include "fk.h"
#include "mesh.h"
#include "skel.h"
#include "skel_tpose.h"
#include "skp_error.h"

#define MANQ_MAX_PARTS      (SKP_MAX_BONES + 3)  /* bones + torso, neck, head */
#define MANQ_MIN_DETAIL     8
#define MANQ_MAX_DETAIL     256
#define MANQ_DEFAULT_DETAIL 72    /* grid cells across the body's largest extent */
#define MANQ_MAX_SIDE       (MANQ_MAX_DETAIL + 16) /* samples along x or y */
#define MANQ_HASH_SIZE      (2 * SKP_MAX_VERTS)    /* power of two, load <= 1/2 */

/* The field of one part is |squash(p - closest point on a..b)| - radius. */
typedef struct manq_part {
	vec3 a, b;
	vec3 axis;          /* unit a->b, zero for a point */
	float len;
	float ra, rb;       /* radius at a and at b, linear in between */
	float cap_scale;    /* >= 1: flattens the end caps along the axis */
	vec3 flat;          /* unit axis squashed by flat_scale */
	float flat_scale;   /* >= 1 */
	vec3 box_lo, box_hi; /* bounds of the segment a..b */
	float r_max;
} manq_part;

typedef struct manq_body {
	int count;
	float height;       /* scale H: the joints' rest extent along Y */
	float blend;        /* smooth-union width */
	vec3 lo, hi;        /* bounds of every part's surface (before blending) */
	manq_part part[MANQ_MAX_PARTS];
} manq_body;

/* Working memory of manq_build (about 2 MB: callers keep it static). */
typedef struct manq_work {
	float pose_value[SKP_MAX_DOF];  /* the pose built around (skel_tpose): the bind pose */
	int arms_raised;                /* 0: pose_value is all 0, the rest pose */
	skel_pose rest;                 /* that pose */
	manq_body body;
	float slice[2][MANQ_MAX_SIDE * MANQ_MAX_SIDE];
	uint32_t edge_key[MANQ_HASH_SIZE];   /* 0 empty, else 1 + grid edge id */
	uint32_t edge_vert[MANQ_HASH_SIZE];
	uint16_t near[MANQ_MAX_PARTS];       /* parts close to the current row */
} manq_work;

/* Builds the body in the skeleton's units around its rest pose, with any
 * hanging arms raised (w->pose_value, w->arms_raised). detail is
 * the number of grid cells across the largest extent (0: the default).
 * Fails on a skeleton without extent, a detail out of range or a body
 * over the board's vertex/triangle limits. */
skp_status manq_build(const skel *s, int detail, manq_work *w, mesh *out, skp_error *err);

/* The parts of the body around the rest pose rest (mannequin_body.c). */
skp_status manq_body_from_skel(const skel *s, const skel_pose *rest, manq_body *out,
			       skp_error *err);

/* The field (negative inside, zero on the surface) and its outward unit
 * gradient by central differences of width step (mannequin_field.c). */
float manq_field(const manq_body *b, vec3 p);
vec3 manq_field_normal(const manq_body *b, vec3 p, float step);

/* The field of the listed parts only, far (> 0) when the list is empty:
 * exact wherever the parts left out are further than the blend width
 * plus the value from p. */
float manq_field_of(const manq_body *b, const uint16_t *which, int n, float far, vec3 p);

#endif
