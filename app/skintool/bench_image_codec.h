/* skintool bench-image's figures of a clip's motion (bench_image_codec.c):
 * bytes a frame and the ratio against 10 float32 a bone a frame (ACL's raw
 * measure), the shell error against the source (ACL's measure: points 3 cm
 * along each joint's axes, cm) worst and 99th percentile, decode time a
 * frame, and ACL's figures on the same frames when its anchor is given. */
#ifndef BENCH_IMAGE_CODEC_H
#define BENCH_IMAGE_CODEC_H

#include "show_source.h"

/* src: the clip's source (AMC or BVH), or NULL; acl: the anchor's program
 * (../shared/tools/acl-bench, built), or NULL. -1 after reporting. */
int bench_clip_motion(show_image *img, const skel *s, int clip, const char *src, const char *acl);

#endif
