/* Biovision BVH: the HIERARCHY as a skel (one bone per joint) and the
 * MOTION frames streamed one at a time as amc_frames, so that everything
 * downstream plays BVH exactly as it plays ASF/AMC. Fixed memory, no
 * allocation, the text read through the same line reader.
 *
 * Mapping (exact: forward kinematics gives the file's joint positions):
 *   - joint J -> bone J, head at J; its segment (direction * length) is the
 *     OFFSET of its first child joint, else of its End Site, else empty;
 *   - a further child K of J sits at offset_K - segment_J from J's tip
 *     (skel_bone.offset), so siblings may branch anywhere;
 *   - rotation channels, listed in any order, are applied as BVH applies
 *     them (Z X Y: the matrix Rz Rx Ry, Y first), in degrees;
 *   - position channels (the root's, or any joint's: up to 6 channels) give
 *     the joint's position relative to its parent in place of its OFFSET,
 *     as Blender reads them;
 *   - the root OFFSET is skel.root_position.
 * Frames are numbered from 1. Keywords in any case; LF, CRLF, tabs. */
#ifndef BVH_H
#define BVH_H

#include "amc.h"
#include "skel.h"
#include "text_lines.h"

/* Frame times a BVH may give: 1 us to 10 s (1e6 to 0.1 frames a second). */
#define BVH_MIN_FRAME_TIME 1e-6
#define BVH_MAX_FRAME_TIME 10.0

/* How the values on a frame line land in a frame (amc_frame.value). */
typedef struct bvh_layout {
	int channels;                       /* values per frame line */
	long frames;                        /* "Frames:" */
	double frame_time;                  /* "Frame Time:", seconds */
	uint16_t dof[SKP_MAX_DOF];          /* file value i -> frame value index */
	uint8_t rotation[SKP_MAX_DOF];      /* file value i is an angle (degrees) */
	float minus[SKP_MAX_DOF];           /* position values: the OFFSET they replace */
} bvh_layout;

/* Reads HIERARCHY and the MOTION header (through "Frame Time:") into s and
 * layout; tl is then at the first frame line. Errors name the line. */
skp_status bvh_parse(skel *s, bvh_layout *layout, text_lines *tl, skp_error *err);

typedef struct bvh_stream {
	const skel *s;
	const bvh_layout *layout;
	text_lines *tl;
	long next;                          /* frames returned */
	long cut_frames;                    /* frames the file lacks of "Frames:", else 0 */
} bvh_stream;

void bvh_open(bvh_stream *b, const skel *s, const bvh_layout *layout, text_lines *tl);

/* Returns 1 with the next frame in *f (numbered from 1), 0 after the last
 * (the file ending early: 0 with cut_frames set), or a negative
 * skp_status (err names the line and what was expected). */
int bvh_next(bvh_stream *b, amc_frame *f, skp_error *err);

/* 1 when path ends in .bvh (any case): the front ends' switch. */
int bvh_is_path(const char *path);

#endif
