/* The skinplay flash image (.skn), format version 7: a skeleton, a bound
 * body and motion clips packed once by `skintool pack` and played from
 * CRC-checked fixed-size blocks with fixed memory (app/image/image_read.h,
 * app/image/image_stream.h), with XOR parity that rebuilds any one bad block
 * per parity group, a copy of the directory and a copy of the header.
 * Every block carries the image's own random 128-bit id, and the header a
 * SHA-256 digest of every data block, so a block of another image is never
 * taken (nor "repaired" into this one). Images of versions 1 to 3 (skintool
 * 0.16 and older: no image id) are refused by name: pack the show again.
 * Version 5 adds compressed clips (app/codec/codec_format.h; what pack
 * writes unless told --raw) beside version 4's 16-bit quantised ones, and
 * five fields to each directory entry; a version 4 image still reads (its
 * clips are all quantised). Version 6 adds each vertex's colour to the
 * bind section. Version 7 gives every data block its own digest, checked
 * whenever the block is read (DIGESTS below); versions 4 to 6 still read
 * and play, checked by their CRCs and the whole-image digest. Version 8
 * adds the body's texture coordinates and base colour texture to the bind
 * section; version 7 images still read and play (no texture).
 *
 * All integers are little-endian; floats are IEEE-754 binary32 stored as
 * their little-endian bit pattern; a "str" is a u8 length then that many
 * bytes (no NUL, length < SKP_MAX_NAME).
 *
 * BLOCKS. The image is block_count blocks of block_size B bytes (default
 * 4096; 512..SKP_IMAGE_BLOCK_SIZE, a multiple of 16). Every block but the
 * parity blocks is
 *
 *     offset  size  field
 *     0       16    image id: random, chosen by pack, the header's; a block
 *                   with another id is another image's (an update stopped
 *                   halfway, two packs in one second, a block copied in):
 *                   bad, rebuilt from parity, never taken
 *     16      4     block index: the block's own position
 *     20      1     kind: 1 header, 2 skeleton, 3 bind, 4 clip directory,
 *                   5 clip quantisation, 6 clip frames
 *     21      1     0
 *     22      2     item: the clip's index for kinds 5 and 6; 1 for the
 *                   copies (header copy, directory copy); else 0
 *     24      B-28  payload; bytes not used are 0
 *     B-4     4     CRC-32 (app/base/crc32.h) of bytes 0..B-5
 *
 * Sections of kind 2..5 are byte streams cut into (B-28)-byte payloads over
 * consecutive blocks. Layout, in block order:
 *
 *     block 0          header
 *     skeleton         kind 2
 *     bind             kind 3
 *     per clip         kind 5 (its quantisation), then kind 6 (its frames)
 *     directory        kind 4
 *     digests          kind 7 (version 7)
 *     parity           P blocks
 *     directory copy   kind 4, item 1: the directory's payloads again
 *     header copy      kind 1, item 1: the last block of the image
 *
 * DIGESTS (version 7). The blocks before the digest section, 0 .. H-1
 * (H: the directory's first block plus its count), each have a leaf: the
 * first 16 bytes of the SHA-256 of the whole block (frame and CRC), block
 * 0's leaf 16 zero bytes (the header, checked by its CRC and its copy).
 * The digest section (kind 7, item 0) is the H leaves in block order as a
 * byte stream, 254 to a block at B = 4096 ((B - 28) / 16): its blocks,
 * ceil(16 H / (B - 28)), end the data blocks (D = H + that). Each digest
 * block's own leaf is taken likewise (its whole B bytes), and the header's
 * digest field holds the root: the SHA-256 of the digest blocks' leaves
 * in order. A reader checks the digest blocks against the root when it
 * opens the image (a digest block that fails is rebuilt from parity, and
 * kept when the rebuilt one gives the root), then every block it reads
 * against its leaf: a block whose content changed, even with its CRC made
 * again, is a bad block, rebuilt from parity or held like any other.
 *
 * The blocks up to the directory (version 7: up to the digests) are the D
 * data blocks. PARITY: data block
 * b belongs to parity group b mod P, and parity block D + g is the XOR of
 * every data block of group g, all B bytes of each (frame, CRC and all; no
 * frame of its own). Any one data block of a group that cannot be read or
 * fails its check is rebuilt bit-identical from the group's other blocks
 * and its parity block, and then passes its CRC. Interleaving the groups
 * means a run of up to P consecutive bad blocks (an erase block of an SD
 * card, a scratch) is also repaired. Groups hold at most pack --parity G
 * blocks (P = ceil(D / G)); the default G is 8 (12.5%), larger when the
 * image is small so that parity and the copies stay within 15% where they
 * can.
 *
 * COPIES. Block 0 is the header and zeros, so it is rebuilt from the header
 * copy when its parity group cannot rebuild it; a directory block from its
 * copy likewise. So no single lost block, and no lost block of the header
 * or the directory that its copy survives, refuses the image. The header
 * copy holds the header at the end of its payload (bytes B-4-168 .. B-5):
 * a reader whose block 0 is bad looks for it at the end of the storage
 * first, then searches the storage for it (a slot on a raw partition, a
 * padded download: bytes after the image are ignored), checking its CRC
 * and that it sits where its own layout puts it. A missing header copy
 * (the storage ends before it) is a warning, not a refusal.
 *
 * pack writes the data, the parity, the header copy and block 0 last (to a
 * temporary file renamed into place): until the copy is written no valid
 * header exists and the slot is refused; once it is whole, every block
 * before it is too, so a write cut short after it still plays.
 *
 * HEADER (payload of block 0, 168 bytes):
 *
 *     0    8   magic "SKPIMAGE"
 *     8    2   format version (5; 4 still read)
 *     10   2   header size (168)
 *     12   4   block size B
 *     16   4   block count
 *     20   8   sequence (pack --sequence, default the unix time): of two
 *              valid slots the larger sequence plays
 *     28   16  image id (random; in every block's frame)
 *     44   4   bones the image needs          (board limit SKP_MAX_BONES)
 *     48   4   dofs per frame                 (SKP_MAX_DOF)
 *     52   4   mesh vertices                  (SKP_MAX_VERTS)
 *     56   4   mesh triangles                 (SKP_MAX_TRIS)
 *     60   4   influences per vertex (4)      (SKP_MAX_INFLUENCES)
 *     64   4   clips                          (SKP_IMAGE_MAX_CLIPS)
 *     68   48  sections: skeleton, bind, directory, clips (every kind 5
 *              and 6 block), each u32 first block, u32 block count,
 *              u32 bytes (0 for clips: not a byte stream)
 *     116  4   data blocks D
 *     120  4   parity blocks P (0: none)
 *     124  4   directory copy: first block (D + P; as many blocks as the
 *              directory)
 *     128  4   header copy block (the last)
 *     132  32  digest: SHA-256 of data blocks 1 .. D-1, whole (frames and
 *              CRCs included), in order; version 7: the root of the
 *              blocks' digests (DIGESTS)
 *     164  4   header CRC: CRC-32 of header bytes 0..163
 *
 * SKELETON (kind 2): everything app/motion/skel.h's skel holds, so that it is
 * rebuilt exactly (no ASF parsing on the device):
 *
 *     str name, str version, f32 length_scale, f32 mass_scale,
 *     u8 angle_in_degrees, f32 root_position[3], u16 bone count,
 *     u16 dof count, u8 eval_order[count], then per bone (0 = root):
 *     str name, i32 id, i16 parent (-1 root), f32 direction[3], f32 length,
 *     f32 axis_angle[3], u8 axis_order[3], u8 channel_count,
 *     u8 channel[channel_count] (skel_channel), u8 has_limits,
 *     f32 limit[channel_count][2], u16 dof_offset, f32 axis_rot[4] (w x y z),
 *     f32 offset[3] (a BVH joint's head off its parent's tip)
 *
 * BIND (kind 3): the body as bound (after --fit), and its bind pose:
 *
 *     u32 vertices V, u32 triangles T, u8 bind pose (0 the rest pose,
 *     1 a frame or a pose derived from the rest pose: the generated body's
 *     arms raised), i32 its frame number (-1 when derived), f32 values[dof
 *     count] (only when 1; as amc_frame.value), then f32 origin[3],
 *     f32 step[3], u16 position[V][3]: origin + q * step per axis, origin
 *     the least and step (greatest - least) / 65535 over the vertices, so
 *     |error| <= step / 2 per axis (the compact streams' quantisation,
 *     app/skin/skin_compact.h); i16 normal[V][2]: octahedral, 32767 = 1,
 *     within 5e-5 of the unit normal; u32 triangle[T][3]; per vertex u8
 *     influence count (1..4), u8 bone[4], u16 weight[4]: weight / 65535, the
 *     used ones summing to exactly 65535 (largest remainder), so |error| <=
 *     1/65535 per weight. 23 bytes a vertex.
 *     Version 6: u8 coloured (0 or 1), then when 1 u8 colour[V][3], each
 *     vertex's sRGB base colour. Version 8: u8 textured (0 or 1), then
 *     when 1: f32 uv_origin[2], f32 uv_step[2], u16 uv[V][2] (origin + q *
 *     step, as the positions; GL's: (0, 0) the texture's bottom left,
 *     repeating), u8 sampled[V] (1: the vertex's colour is multiplied by
 *     the texture's at uv; 0: its colour alone), u16 width, u16 height
 *     (powers of two), u8 format (1: ETC1), u32 bytes, then the ETC1 mip
 *     chain to 1x1 (app/texture/tex_mip.h), level 0 first, each level's
 *     4x4 blocks left to right, rows in GL's order (the first row at
 *     v = 0, the picture's bottom: glCompressedTexImage2D takes them as
 *     they are), 8 bytes each (OES_compressed_ETC1_RGB8_texture). A reader whose
 *     board keeps no texture that large (SKP_MAX_TEXTURE_SIDE) plays the
 *     body in its colours.
 *
 * CLIP QUANTISATION (kind 5, item = clip), of a quantised clip (coded 0):
 * per dof f32 min, f32 step.
 * A frame value is min + q * step for a u16 q; pack rounds to the nearest q,
 * so |decoded - AMC value| <= step / 2 (+ float rounding of the decoded
 * value), step = (max - min) / 65535 over the clip (0 for a constant dof).
 *
 * CLIP FRAMES (kind 6, item = clip), of a quantised clip: a u16 count of
 * the frames the block
 * holds, then whole frames, never split: frames_per_block =
 * floor((B - 30) / (2 * dofs)); frame i is in block frames_first + i /
 * frames_per_block at payload offset 2 + (i % frames_per_block) * 2 * dofs,
 * its u16 q values in dof order. Every block but a clip's last is full; the
 * last's count is what the directory's frame count leaves. A bad block
 * loses only the frames inside it (32 frames of a CMU clip at 4 KiB: 0.27 s
 * at 120 Hz).
 *
 * COMPRESSED CLIP (version 5, coded 1). Its kind 5 section (the codec's
 * header, app/codec/codec_format.h) is u16 tracks (= dofs), u16
 * segment_frames, per track f32 base, f32 step, u8 bits, then u32
 * offset[segments + 1]: segment s is bytes [offset[s], offset[s + 1]) of
 * the clip's stream, offset[0] = 0, offset[segments] = stream bytes, no
 * segment longer than the board's SKP_CODEC_SEGMENT_BYTES. Its kind 6
 * blocks hold the stream: a u16 count of the stream bytes in the block, then
 * those bytes; every block but the last holds B - 30, the last what the
 * directory's stream bytes leave (checked as a quantised clip's frame
 * count is). A player gathers a segment's bytes from its blocks into one
 * buffer and decodes it frame by frame; a seek starts the segment it lands
 * in over. A bad block that parity cannot rebuild loses the segments
 * touching it (about 2 s at 120 Hz each), not the clip.
 *
 * DIRECTORY (kind 4): u16 clip count, then per clip
 *
 *     str name (the AMC file name without extension), f32 fps,
 *     u32 frame count, i32 first frame number (frames are numbered
 *     consecutively from it), u16 dofs, u16 frames_per_block (0 when
 *     compressed), u32 quant first block, u32 quant block count,
 *     u32 frames first block, u32 frame block count,
 *     f32 worst-case rotation error (radians), f32 worst-case translation
 *     error (ASF length units): the largest |decoded - packed value| of
 *     each kind of dof (quantised: the largest step / 2),
 *     version 5 only:
 *     u8 coded (0 quantised, 1 compressed), u32 stream bytes, u32 segments
 *     (both 0 when quantised), f32 worst shell error (cm: ACL's measure,
 *     points 3 cm from each joint, app/encode/encode_error.h; 0 when not
 *     measured), f32 cm a skeleton length unit (0 when not known)
 *
 * Compatibility: a reader refuses any other magic or version (naming an
 * older one as such), a header size or CRC that does not match, and limits
 * beyond its board's. */
#ifndef IMAGE_FORMAT_H
#define IMAGE_FORMAT_H

#include <stdint.h>

#include "board_limits.h"

/* Boards that do not set the image limits get the host's. */
#ifndef SKP_IMAGE_BLOCK_SIZE
#define SKP_IMAGE_BLOCK_SIZE  4096
#endif
#ifndef SKP_IMAGE_RING_BLOCKS
#define SKP_IMAGE_RING_BLOCKS    4
#endif
#ifndef SKP_IMAGE_CACHE_BLOCKS
#define SKP_IMAGE_CACHE_BLOCKS   4
#endif
#ifndef SKP_IMAGE_MAX_CLIPS
#define SKP_IMAGE_MAX_CLIPS     64
#endif
/* Digest blocks (version 7) whose own digests the reader keeps: each
 * covers (B - 28) / 16 blocks, 254 at B = 4096 (64: images to 66 MB). */
#ifndef SKP_IMAGE_MAX_DIGEST_BLOCKS
#define SKP_IMAGE_MAX_DIGEST_BLOCKS 64
#endif

#define SKP_IMAGE_MAGIC        "SKPIMAGE"
#define SKP_IMAGE_VERSION      8
#define SKP_IMAGE_VERSION_MIN  4     /* the oldest version still read */
#define SKP_IMAGE_HEADER_SIZE  168
#define SKP_IMAGE_ID_BYTES     16
#define SKP_IMAGE_DIGEST_BYTES 32    /* SHA-256 */
#define SKP_IMAGE_LEAF_BYTES   16    /* a block's digest: SHA-256's first 16 bytes */
#define SKP_IMAGE_DEFAULT_GROUP  8    /* data blocks per parity group */
#define SKP_IMAGE_BLOCK_HDR    24    /* id, index, kind, 0, item */
#define SKP_IMAGE_BLOCK_CRC    4
#define SKP_IMAGE_BLOCK_EXTRA  (SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_BLOCK_CRC)
#define SKP_IMAGE_FRAMES_COUNT 2     /* a frames block's u16 count of its frames */

/* The stream bytes a compressed clip's frames block holds. */
static inline uint32_t skp_image_stream_room(uint32_t block_size)
{
	return block_size - SKP_IMAGE_BLOCK_EXTRA - SKP_IMAGE_FRAMES_COUNT;
}
#define SKP_IMAGE_MIN_BLOCK    512
#define SKP_IMAGE_DEFAULT_BLOCK 4096
#define SKP_IMAGE_QMAX         65535u
#define SKP_IMAGE_TEXTURE_ETC1 1     /* the bind section's texture format */
/* a vertex's influences in the bind section: count, bones, weights */
#define SKP_IMAGE_INFLUENCE_BYTES     (1 + 3 * SKP_MAX_INFLUENCES)
/* the frame fields, at the block's start */
#define SKP_IMAGE_AT_INDEX     16
#define SKP_IMAGE_AT_KIND      20
#define SKP_IMAGE_AT_ITEM      22

enum skp_image_kind {
	SKP_KIND_HEADER = 1,
	SKP_KIND_SKELETON,
	SKP_KIND_BIND,
	SKP_KIND_DIRECTORY,
	SKP_KIND_QUANT,
	SKP_KIND_FRAMES,
	SKP_KIND_DIGESTS         /* version 7: each data block's digest */
};

enum skp_image_section_id {
	SKP_SEC_SKELETON,
	SKP_SEC_BIND,
	SKP_SEC_DIRECTORY,
	SKP_SEC_CLIPS,
	SKP_SEC_COUNT
};

typedef struct skp_image_section {
	uint32_t first, count, bytes;
} skp_image_section;

/* The earliest unix time pack takes from the clock for a sequence
 * (2024-01-01): a clock behind it is wrong (a board without a real-time
 * clock starts in 1970), and `info` says when a sequence lies ahead of
 * its own clock. */
#define SKP_IMAGE_SEQUENCE_CLOCK_FLOOR 1704067200L

typedef struct skp_image_header {
	uint16_t version;
	uint16_t header_size;
	uint32_t block_size, block_count;
	uint64_t sequence;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	uint32_t bones, dofs, verts, tris, influences, clips;
	skp_image_section sec[SKP_SEC_COUNT];
	uint32_t data_blocks;     /* D */
	uint32_t parity_blocks;   /* P: 0 for none */
	uint32_t dir_copy;        /* the directory copy's first block */
	uint32_t copy_block;      /* the header copy */
	uint8_t digest[SKP_IMAGE_DIGEST_BYTES];
	uint32_t crc;
} skp_image_header;

typedef struct skp_image_clip {
	char name[SKP_MAX_NAME];
	float fps;
	uint32_t frame_count;
	int32_t first_number;
	uint16_t dofs, frames_per_block;
	uint32_t quant_first, quant_blocks;
	uint32_t frames_first, frame_blocks;
	float max_rot_err, max_trans_err;
	/* version 5 */
	uint8_t coded;           /* 1: compressed (app/codec), 0: quantised */
	uint32_t stream_bytes, segments;
	float shell_err, unit_cm;
} skp_image_clip;

/* Little-endian fields, whatever the CPU. */
static inline void le_put16(uint8_t *p, uint16_t v)
{
	p[0] = (uint8_t)v;
	p[1] = (uint8_t)(v >> 8);
}

static inline void le_put32(uint8_t *p, uint32_t v)
{
	le_put16(p, (uint16_t)v);
	le_put16(p + 2, (uint16_t)(v >> 16));
}

static inline void le_put64(uint8_t *p, uint64_t v)
{
	le_put32(p, (uint32_t)v);
	le_put32(p + 4, (uint32_t)(v >> 32));
}

static inline uint16_t le_get16(const uint8_t *p)
{
	return (uint16_t)(p[0] | (p[1] << 8));
}

static inline uint32_t le_get32(const uint8_t *p)
{
	return (uint32_t)le_get16(p) | ((uint32_t)le_get16(p + 2) << 16);
}

static inline uint64_t le_get64(const uint8_t *p)
{
	return (uint64_t)le_get32(p) | ((uint64_t)le_get32(p + 4) << 32);
}

/* Encodes a header (SKP_IMAGE_HEADER_SIZE bytes) with its CRC. */
void skp_image_header_put(uint8_t *p, const skp_image_header *h);

/* Decodes a header from n bytes at p. Returns 1 when it is one of this
 * version (magic, version, size, CRC), else 0; h is filled as far as the
 * bytes go either way (messages use it: an older version is named). */
int skp_image_header_get(const uint8_t *p, uint32_t n, skp_image_header *h);

/* Frames a block: id, index, kind and item into its first
 * SKP_IMAGE_BLOCK_HDR bytes (the payload and CRC untouched). */
void skp_block_frame(uint8_t *block, const uint8_t id[SKP_IMAGE_ID_BYTES], uint32_t index, int kind,
		     unsigned item);

/* Sets a framed block's CRC. */
void skp_block_seal(uint8_t *block, uint32_t block_size);

/* The frames clip block b (0-based in the clip) holds: every block but
 * the last is full. */
static inline uint32_t skp_image_frames_in(const skp_image_clip *c, uint32_t b)
{
	uint64_t before = (uint64_t)b * c->frames_per_block, left = before < c->frame_count ? c->frame_count - before : 0;
	return (uint32_t)(left < c->frames_per_block ? left : c->frames_per_block);
}

/* The stream bytes compressed clip block b (0-based in the clip) holds. */
static inline uint32_t skp_image_bytes_in(const skp_image_clip *c, uint32_t room, uint32_t b)
{
	uint64_t before = (uint64_t)b * room, left = before < c->stream_bytes ? c->stream_bytes - before : 0;
	return (uint32_t)(left < room ? left : room);
}

/* The count a clip's frames block b must hold: frames, or stream bytes
 * (room: the bytes a block holds after its count). */
static inline uint32_t skp_image_block_count(const skp_image_clip *c, uint32_t room, uint32_t b)
{
	return c->coded ? skp_image_bytes_in(c, room, b) : skp_image_frames_in(c, b);
}

/* The parity group of data block b (images with parity). */
static inline uint32_t skp_image_group(const skp_image_header *h, uint32_t b)
{
	return h->parity_blocks ? b % h->parity_blocks : 0;
}

#endif
