/* skintool convert: motion out of skinplay's skeleton (skel) into the
 * interchange formats, so that ASF/AMC and BVH convert both ways and a
 * user's clip can go on to other tools. Both writers are exact for
 * forward kinematics: the converted file poses every joint where the
 * source did (up to the printed digits). */
#ifndef CONVERT_H
#define CONVERT_H

#include <stdio.h>

#include "motion_file.h"
#include "skel.h"

/* Why s cannot be written (a bone's length channel `l`, which neither
 * format's other side carries), or NULL. */
const char *convert_unsupported(const skel *s, int *bone);

/* BVH: HIERARCHY (a joint per bone, rotations Zrotation Yrotation
 * Xrotation, the root also Xposition Yposition Zposition, other joints
 * positions only when they translate), then MOTION with frames frames of
 * m. Returns 0, or -1 after reporting a read error of m. */
int convert_write_bvh(FILE *f, const skel *s, motion_file *m, long frames, double frame_time);

/* ASF with :units length 1 and angle deg; a bone that starts off its
 * parent's tip (a BVH sibling joint) or translates gets tx ty tz. */
void convert_write_asf(FILE *f, const skel *s);

/* AMC for that ASF: the frames of m numbered from 1, in degrees. Returns
 * the frame count, or -1 after reporting a read error of m. */
long convert_write_amc(FILE *f, const skel *s, motion_file *m);

#endif
