/* Reads a flash image (app/image/image_format.h) from a skp_blockdev with fixed
 * memory: the header and the clip directory at open, then the skeleton and
 * the bound body into the caller's structs. Every block read is checked
 * (image_block.h: CRC, image id, index, kind); a block that fails is
 * rebuilt (image_recover.h) from its parity group, or from its copy (block
 * 0 from the header, a directory block from the directory copy), else the
 * error names it. Playback of the clips is app/image/image_stream.h. */
#ifndef IMAGE_READ_H
#define IMAGE_READ_H

#include "blockdev.h"
#include "codec_decode.h"
#include "image_block.h"
#include "image_format.h"
#include "mesh.h"
#include "skel.h"
#include "image_recover.h"
#include "skin_weights.h"
#include "tex_image.h"
#include "skp_error.h"

/* The block size in a raw first block when it holds a whole header of this
 * version (magic, version, CRC) with a size in range, else 0. Front ends
 * use it to open storage with the image's own block size. */
uint32_t skp_image_block_size_hint(const uint8_t *block0, uint32_t n);

/* The header copy's bytes: the header and the block's CRC, at the end of
 * its block. */
#define SKP_IMAGE_TAIL (SKP_IMAGE_HEADER_SIZE + SKP_IMAGE_BLOCK_CRC)

/* 1 when the SKP_IMAGE_HEADER_SIZE bytes at p, byte offset `at` of the
 * storage, are a header copy: a whole header of this version, where its
 * own layout puts its copy. The header in *h. */
int skp_image_copy_at(const uint8_t *p, uint64_t at, skp_image_header *h);

/* Searches a byte stream (a file, a partition) from its start for a header
 * copy: a whole header of this version at the end of a block, where its own
 * layout puts its copy (at + SKP_IMAGE_TAIL == (copy_block + 1) * block
 * size), whatever comes after it. win: cap >= 512 bytes of the caller's.
 * Returns 1 with the header in *h and its byte offset in *at, 0 when the
 * stream holds none, or when its first SKP_IMAGE_FIND_BARREN bytes hold
 * nothing that looks like a block of any image (a zero-filled 2 GiB slot is
 * refused in milliseconds, not searched to its end). */
#define SKP_IMAGE_FIND_BARREN (16u << 20)
int skp_image_find_copy(skp_reader rd, uint8_t *win, uint32_t cap, skp_image_header *h, uint64_t *at);

typedef struct skp_image {
	const skp_blockdev *dev;
	skp_image_header hdr;
	int clip_count;
	skp_image_clip clip[SKP_IMAGE_MAX_CLIPS];
	/* section stream state, over buf */
	uint32_t s_block, s_end, s_pos, s_left;
	uint8_t s_kind;
	uint16_t s_item;
	uint8_t buf[SKP_IMAGE_BLOCK_SIZE];
	uint8_t scratch[SKP_IMAGE_BLOCK_SIZE];   /* a rebuild's group reads */
	unsigned long rebuilt;                  /* blocks rebuilt (parity or copy) since open */
	const char *rebuilt_from;               /* the last one's source: "parity", "the header",
	                                         * "the directory copy", "the directory" */
	int header_from_copy;                   /* block 0 was bad: the copy's header */
	int header_from_parity;                 /* ... and the copy lost too: block 0 rebuilt
	                                         * from parity (image_header_parity.h) */
	uint32_t missing;                       /* blocks at the image's end the storage lacks
	                                         * (copies, parity): a warning */
	/* version 7's per-block digests (image_digests.h) */
	uint32_t digest_first;                  /* H: blocks 0..H-1 have a leaf; 0 none */
	int digests;                            /* 1: every block read is checked against its leaf */
	int digests_broken;                     /* the digest blocks do not give the header's root */
	uint32_t leaves_at;                     /* the digest block held in leaves (UINT32_MAX none) */
	uint8_t top[SKP_IMAGE_MAX_DIGEST_BLOCKS][SKP_IMAGE_LEAF_BYTES]; /* each digest block's leaf */
	uint8_t leaves[SKP_IMAGE_BLOCK_SIZE];   /* a digest block, checked against top */
	/* When set (before open), told of every block rebuilt from parity or
	 * a copy (block 0 also when the header came from the copy). */
	void (*on_rebuild)(void *ctx, uint32_t block);
	void *on_rebuild_ctx;
	/* Where skp_image_load_bind puts a version 8 body's texture (set it
	 * before; NULL: not kept). texture_skipped: the body had one that was
	 * not kept (none asked for, or larger than SKP_MAX_TEXTURE_SIDE): the
	 * body plays in its colours (mesh.textured 0). */
	tex_image *texture;
	int texture_skipped;
} skp_image;

/* Reads and checks the header (block 0, or its copy when block 0 is bad:
 * at the storage's end, else searched for), the board limits, that the
 * storage holds every data block, and the clip directory (from its copy
 * where a block is beyond parity). A bad image gives SKP_ERR_CORRUPT (or
 * SKP_ERR_LIMIT, SKP_ERR_IO) naming the block and what was expected; an
 * image of an older format version is refused by name. im->missing counts
 * blocks of the image's end the storage lacks (it still opens). dev must
 * stay valid while im is used. */
skp_status skp_image_open(skp_image *im, const skp_blockdev *dev, skp_error *err);

/* The skeleton, exactly as packed. */
skp_status skp_image_load_skel(skp_image *im, skel *s, skp_error *err);

/* The bound mesh (normals included), its weights, and the bind pose as one
 * frame of values (bind_values[SKP_MAX_DOF]; *bind_number -1 and all zero
 * for the rest pose, -1 and not all zero for a derived pose). s is the
 * image's skeleton. */
skp_status skp_image_load_bind(skp_image *im, const skel *s, mesh *m, skin_weights *w,
			       float *bind_values, long *bind_number, skp_error *err);

/* The clip's per-dof quantisation (qmin, qstep: clip->dofs floats each);
 * of a compressed clip, each track's range as one: min, and a step 65535
 * of which reach its top. */
skp_status skp_image_load_quant(skp_image *im, int clip, float *qmin, float *qstep, skp_error *err);

/* A compressed clip's header (tracks and segments, app/codec), checked. */
skp_status skp_image_load_codec(skp_image *im, int clip, codec_clip *cc, skp_error *err);

/* Where compressed segment s lies in the clip's stream: bytes
 * [span[0], span[1]), checked against the stream and the board's
 * SKP_CODEC_SEGMENT_BYTES. */
skp_status skp_image_load_span(skp_image *im, int clip, uint32_t s, uint32_t span[2], skp_error *err);

/* The clip's last frames block holds the frames the directory leaves for
 * it: SKP_OK, also when the block cannot be read (its frames are held
 * when played); else SKP_ERR_CORRUPT naming the block. */
skp_status skp_image_check_frames(skp_image *im, int clip, skp_error *err);

/* Index of the clip with that name, or -1. */
int skp_image_find_clip(const skp_image *im, const char *name);

#endif
