/* skintool pack's compressed clips: a motion file encoded by app/encode
 * within an error budget and written into the image (image_write.h). */
#ifndef PACK_ENCODE_H
#define PACK_ENCODE_H

#include "image_write.h"
#include "tool_clip.h"

typedef struct pack_codec {
	double error_cm;        /* the worst shell error allowed (ACL's default 0.01 cm) */
	double unit_cm;         /* cm a skeleton unit; 0: skel_unit_cm */
} pack_codec;

/* Encodes clip (frames of w->s) and writes it as name at fps; prints its
 * figures on the summary stream. -1 after reporting (path names it). */
int pack_encode_clip(skp_image_writer *w, const char *path, const char *name, double fps,
		     const tool_clip *clip, const pack_codec *o);

/* The largest |decoded - source| of rotation and translation dofs over
 * every frame of an encoded clip (decoded segment by segment). */
void pack_value_errors(const skel *s, const float *frames, const codec_clip *cc, const uint8_t *bytes,
		       const uint32_t *offsets, float *rot, float *trans);

#endif
