/* The skeleton layer: an Acclaim ASF skeleton in fixed arrays, which a BVH
 * hierarchy maps onto one joint per bone (bvh.h). Bone 0 is the root;
 * bones 1..count-1 follow the file's order. */
#ifndef SKEL_H
#define SKEL_H

#include <stdint.h>

#include "board_limits.h"
#include "quat.h"
#include "vec3.h"

typedef enum skel_channel {
	SKEL_RX, SKEL_RY, SKEL_RZ, SKEL_TX, SKEL_TY, SKEL_TZ, SKEL_L
} skel_channel;

#define SKEL_MAX_CHANNELS 7

typedef struct skel_bone {
	char name[SKP_MAX_NAME];
	long id;
	int parent;                     /* bone index, -1 for the root */
	vec3 direction;                 /* unit vector in world space at rest */
	float length;
	vec3 offset;                    /* head - parent's tip at rest, world space (BVH: a
	                                 * sibling joint off its parent's segment; ASF: 0) */
	vec3 axis_angle;                /* `axis a b c` (root: orientation), ASF angle units */
	uint8_t axis_order[3];          /* rotation axes (0 x,1 y,2 z), first applied first */
	uint8_t channel[SKEL_MAX_CHANNELS]; /* dof (root: order) as skel_channel */
	uint8_t channel_count;
	float limit[SKEL_MAX_CHANNELS][2];  /* per dof: min, max (may be +-inf) */
	uint8_t has_limits;
	uint16_t dof_offset;            /* index of the first value in a frame */
	quat axis_rot;                  /* C from the axis line */
} skel_bone;

typedef struct skel {
	char name[SKP_MAX_NAME];
	char version[16];
	float length_scale;             /* :units length L: applied, lengths read are divided by L */
	float mass_scale;               /* :units mass (recorded: nothing uses masses) */
	uint8_t angle_in_degrees;       /* :units angle deg (1) or rad (0) */
	vec3 root_position;             /* :root position */
	int count;                      /* bones including the root */
	int dof_count;                  /* values in one frame */
	uint8_t eval_order[SKP_MAX_BONES]; /* parents before children */
	skel_bone bone[SKP_MAX_BONES];
} skel;

/* The largest distance a skeleton may reach at rest (the root's position,
 * then offsets and lengths along a chain) and the largest translation a
 * frame may give, in the skeleton's units: within it forward kinematics in
 * floats stays finite (a kilometre in micrometres). The parsers refuse
 * beyond it; a flash image keeps to the fixed-point kernel's tighter range
 * (app/image/image_accept.h). */
#define SKEL_MAX_REACH 1e9

/* The skeleton's reach at rest (infinite when a value is not finite). */
double skel_reach(const skel *s);

/* The first bone (in parents-first order; 0 the root's position) whose
 * chain reaches beyond SKEL_MAX_REACH or is not finite, or -1. */
int skel_beyond_reach(const skel *s);

/* Index of the bone with that name ("root" is 0), or -1. */
int skel_find(const skel *s, const char *name);

/* 1 / :units length: what a length read from the ASF or its AMC is
 * multiplied by (CMU's 0.45 turns its units into inches). */
double skel_length_factor(const skel *s);

/* Centimetres a skeleton length unit (after :units length): inches for
 * the CMU convention (length 0.45: CMU and HDM05), else centimetres (BVH
 * files, the endorphin export's length 0.01). */
double skel_unit_cm(const skel *s);

/* Converts an angle in the skeleton's ASF units to radians. */
float skel_angle_to_rad(const skel *s, float value);

#endif
