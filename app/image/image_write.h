/* Writes a flash image (app/image/image_format.h) block by block through a
 * skp_blockdev's write callback, with fixed memory: clips are streamed
 * twice by the caller, first into an skp_clip_range (the per-dof range the
 * quantisation needs), then frame by frame into the image. Block 0 (the
 * header) is written last. */
#ifndef IMAGE_WRITE_H
#define IMAGE_WRITE_H

#include "amc.h"
#include "codec_format.h"
#include "blockdev.h"
#include "fk.h"
#include "image_format.h"
#include "mesh.h"
#include "sha256.h"
#include "skin_weights.h"
#include "tex_image.h"

/* Pass 1 over a clip: frame count, numbering, per-dof min and max. */
typedef struct skp_clip_range {
	int dofs;
	long frames;
	long first_number, last_number;
	float min[SKP_MAX_DOF], max[SKP_MAX_DOF];
} skp_clip_range;

void skp_clip_range_init(skp_clip_range *r, const skel *s);
/* Fails on a frame number that does not follow the previous one, or a
 * value that is not finite (err names the frame's line). */
skp_status skp_clip_range_add(skp_clip_range *r, const amc_frame *f, skp_error *err);

typedef struct skp_image_writer {
	skp_blockdev *dev;
	const skel *s;
	uint32_t bs, payload;     /* block size, payload bytes per block */
	sha256_ctx digest;        /* of data blocks 1.. as they are written */
	uint32_t next_block;      /* next block to write */
	skp_image_header hdr;
	/* the section being written */
	uint8_t kind;
	uint16_t item;
	uint32_t sec_first, sec_bytes, fill;
	/* the clip being written */
	skp_image_clip *clip;
	uint32_t frames_left;
	uint16_t in_block;        /* frames in the block being filled */
	long next_number;
	float qmin[SKP_MAX_DOF], qstep[SKP_MAX_DOF];
	int clip_count;
	skp_image_clip dir[SKP_IMAGE_MAX_CLIPS];
	int parity_group;         /* data blocks per parity group: 0 default, < 0 none */
	/* the body's texture (version 8), set before skp_image_write_bind:
	 * packed with the mesh's uv when the mesh is textured; NULL none */
	const tex_image *texture;
	uint8_t block[SKP_IMAGE_BLOCK_SIZE];
	uint8_t head[SKP_IMAGE_BLOCK_SIZE], tmp[SKP_IMAGE_BLOCK_SIZE];
} skp_image_writer;

/* Starts an image on dev (dev->block_size is the image's block size) and
 * writes the skeleton section. id: the image's random id (every block
 * carries it). Set w->parity_group after it to choose the parity (default
 * 0: groups of 8 or more, see image_format.h), w->hdr.version to 4 to
 * write a version 4 image (quantised clips only: for tests of old images). */
skp_status skp_image_write_begin(skp_image_writer *w, skp_blockdev *dev, uint64_t sequence,
				 const uint8_t id[SKP_IMAGE_ID_BYTES], const skel *s, skp_error *err);

/* The bound body: mesh, weights, and the bind pose (bind_values: one frame
 * as amc_frame.value numbered bind_number, or NULL for the rest pose). */
skp_status skp_image_write_bind(skp_image_writer *w, const mesh *m, const skin_weights *wt,
				const float *bind_values, long bind_number, skp_error *err);

/* Starts a clip of range->frames frames (range from pass 1), then takes its
 * frames in order; the clip ends after the last one. */
skp_status skp_image_clip_begin(skp_image_writer *w, const char *name, float fps,
				const skp_clip_range *range, skp_error *err);
skp_status skp_image_clip_frame(skp_image_writer *w, const amc_frame *f, skp_error *err);

/* A compressed clip as app/encode made it (the writer copies it into
 * blocks; version 5 images only). */
typedef struct skp_coded_clip {
	const codec_clip *clip;
	const uint8_t *bytes;     /* the segments, one after another */
	uint32_t nbytes;
	const uint32_t *offsets;  /* segments + 1: segment s is [offsets[s], offsets[s + 1]) */
	uint32_t segments;
	long first_number;        /* the first frame's number */
	float max_rot_err, max_trans_err;  /* the largest |decoded - source| per kind of dof */
	float shell_err, unit_cm;          /* the worst shell error (cm), cm a length unit */
} skp_coded_clip;

/* Writes a whole compressed clip (after any other clip has ended). */
skp_status skp_image_clip_coded(skp_image_writer *w, const char *name, float fps, const skp_coded_clip *k,
				skp_error *err);

/* Writes the directory, the parity blocks and the directory copy (reading
 * the data blocks back: dev must read as well as write), the header copy,
 * then the header, with the digest of the data blocks. */
skp_status skp_image_write_end(skp_image_writer *w, skp_error *err);

#endif
