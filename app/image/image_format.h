/* The skinplay flash image (.skn), format version 3: a skeleton, a bound
 * body and motion clips packed once by `skintool pack` and played from
 * CRC-checked fixed-size blocks with fixed memory (app/image/image_read.h,
 * app/image/image_play.h), with XOR parity that rebuilds any one bad block
 * per parity group and a second copy of the header. Versions 1 (without
 * parity and copy) and 2 (float positions and normals, 16-bit bone
 * indices in the bind section) are still read.
 *
 * All integers are little-endian; floats are IEEE-754 binary32 stored as
 * their little-endian bit pattern; a "str" is a u8 length then that many
 * bytes (no NUL, length < SKP_MAX_NAME).
 *
 * BLOCKS. The image is block_count blocks of block_size B bytes (default
 * 4096; 512..SKP_IMAGE_BLOCK_SIZE, a multiple of 16). Every block is
 *
 *     offset  size  field
 *     0       4     tag: image tag = (u32)sequence ^ (u32)(sequence >> 32),
 *                   so a block left over from another image is refused even
 *                   though its own CRC is good (an update stopped halfway)
 *     4       4     block index: the block's own position
 *     8       1     kind: 1 header, 2 skeleton, 3 bind, 4 clip directory,
 *                   5 clip quantisation, 6 clip frames
 *     9       1     0
 *     10      2     item: the clip's index for kinds 5 and 6, else 0
 *     12      B-16  payload; bytes not used are 0
 *     B-4     4     CRC-32 (app/base/crc32.h) of bytes 0..B-5
 *
 * Sections of kind 2..5 are byte streams cut into (B-16)-byte payloads over
 * consecutive blocks. Layout, in block order:
 *
 *     block 0          header
 *     skeleton         kind 2
 *     bind             kind 3
 *     per clip         kind 5 (its quantisation), then kind 6 (its frames)
 *     directory        kind 4
 *     (version 2)      P parity blocks, then the header copy: the last block
 *
 * The blocks up to the directory are the D data blocks. PARITY (version 2):
 * data block b belongs to parity group b mod P, and parity block D + g is
 * the XOR of every data block of group g, all B bytes of each (frame, CRC
 * and all; no frame of its own). Any one data block of a group that cannot
 * be read or fails its check is rebuilt bit-identical from the group's other
 * blocks and its parity block, and then passes its CRC. Interleaving the
 * groups means a run of up to P consecutive bad blocks (an erase block of an
 * SD card, a scratch) is also repaired. Groups hold at most pack --parity G
 * blocks (P = ceil(D / G)); the default G is 8 (12.5%), larger when the
 * image is small so that parity and copy stay within 15% where they can.
 *
 * HEADER COPY (version 2): block D + P, the last, framed as kind 1 with
 * item 1; the header is at the end of its payload (bytes B-4-116 .. B-5),
 * so the last 120 bytes of the image hold it whatever B is: a reader whose
 * block 0 is bad finds B and the layout there.
 *
 * pack writes block 0 last (and to a temporary file renamed into place), so
 * a write cut short leaves no valid header and the slot is refused.
 *
 * HEADER (payload of block 0, 116 bytes; 104 in version 1):
 *
 *     0    8   magic "SKPIMAGE"
 *     8    2   format version (3; 1 and 2 still read)
 *     10   2   header size (104)
 *     12   4   block size B
 *     16   4   block count
 *     20   8   sequence (pack --sequence, default the unix time): of two
 *              valid slots the larger sequence plays
 *     28   4   bones the image needs          (board limit SKP_MAX_BONES)
 *     32   4   dofs per frame                 (SKP_MAX_DOF)
 *     36   4   mesh vertices                  (SKP_MAX_VERTS)
 *     40   4   mesh triangles                 (SKP_MAX_TRIS)
 *     44   4   influences per vertex (4)      (SKP_MAX_INFLUENCES)
 *     48   4   clips                          (SKP_IMAGE_MAX_CLIPS)
 *     52   48  sections: skeleton, bind, directory, clips (every kind 5
 *              and 6 block), each u32 first block, u32 block count,
 *              u32 bytes (0 for clips: not a byte stream)
 *     100  4   data blocks D                  (version 2; version 1: CRC)
 *     104  4   parity blocks P (0: none)
 *     108  4   header copy block (D + P)
 *     112  4   header CRC: CRC-32 of header bytes 0..111 (version 1: of
 *              0..99, at 100)
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
 *     f32 offset[3] (version 2; a BVH joint's head off its parent's tip)
 *
 * BIND (kind 3): the body as bound (after --fit), and its bind pose:
 *
 *     u32 vertices V, u32 triangles T, u8 bind pose (0 the rest pose,
 *     1 a frame or a pose derived from the rest pose: the generated body's
 *     arms raised), i32 its frame number (-1 when derived), f32 values[dof
 *     count] (only when 1; as amc_frame.value), then (version 3)
 *     f32 origin[3], f32 step[3], u16 position[V][3]: origin + q * step per
 *     axis, origin the least and step (greatest - least) / 65535 over the
 *     vertices, so |error| <= step / 2 per axis (the compact streams'
 *     quantisation, app/skin/skin_compact.h); i16 normal[V][2]: octahedral,
 *     32767 = 1, within 5e-5 of the unit normal; u32 triangle[T][3]; per
 *     vertex u8 influence count (1..4), u8 bone[4], u16 weight[4]: weight /
 *     65535, the used ones summing to exactly 65535 (largest remainder), so
 *     |error| <= 1/65535 per weight. 23 bytes a vertex, 41 in version 2,
 *     whose bind section after the bind pose is f32 position[V][3],
 *     f32 normal[V][3], u32 triangle[T][3], then per vertex u8 count,
 *     u16 bone[4], u16 weight[4].
 *
 * CLIP QUANTISATION (kind 5, item = clip): per dof f32 min, f32 step.
 * A frame value is min + q * step for a u16 q; pack rounds to the nearest q,
 * so |decoded - AMC value| <= step / 2 (+ float rounding of the decoded
 * value), step = (max - min) / 65535 over the clip (0 for a constant dof).
 *
 * CLIP FRAMES (kind 6, item = clip): whole frames per block, never split:
 * frames_per_block = floor((B - 16) / (2 * dofs)); frame i is in block
 * frames_first + i / frames_per_block at payload offset
 * (i % frames_per_block) * 2 * dofs, its u16 q values in dof order. A bad
 * block loses only the frames inside it (32 frames of a CMU clip at 4 KiB:
 * 0.27 s at 120 Hz).
 *
 * DIRECTORY (kind 4): u16 clip count, then per clip
 *
 *     str name (the AMC file name without extension), f32 fps,
 *     u32 frame count, i32 first frame number (frames are numbered
 *     consecutively from it), u16 dofs, u16 frames_per_block,
 *     u32 quant first block, u32 quant block count,
 *     u32 frames first block, u32 frame block count,
 *     f32 worst-case rotation error (radians), f32 worst-case translation
 *     error (ASF length units): the largest step / 2 of each kind of dof
 *
 * Compatibility: a reader refuses any other magic or version, a header
 * size or CRC that does not match, and limits beyond its board's; it reads
 * version 1 images as they are (no parity, no copy) and version 2 bind
 * sections in their float form. */
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
#ifndef SKP_IMAGE_MAX_CLIPS
#define SKP_IMAGE_MAX_CLIPS     64
#endif

#define SKP_IMAGE_MAGIC        "SKPIMAGE"
#define SKP_IMAGE_VERSION      3
#define SKP_IMAGE_HEADER_SIZE  116   /* versions 2 and 3; version 1: 104 */
#define SKP_IMAGE_HEADER_V1    104
#define SKP_IMAGE_DEFAULT_GROUP  8    /* data blocks per parity group */
#define SKP_IMAGE_BLOCK_HDR    12    /* tag, index, kind, 0, item */
#define SKP_IMAGE_BLOCK_CRC    4
#define SKP_IMAGE_BLOCK_EXTRA  (SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_BLOCK_CRC)
#define SKP_IMAGE_MIN_BLOCK    512
#define SKP_IMAGE_DEFAULT_BLOCK 4096
#define SKP_IMAGE_QMAX         65535u
/* a vertex's influences in the bind section: count, bones, weights */
#define SKP_IMAGE_INFLUENCE_BYTES     (1 + 3 * SKP_MAX_INFLUENCES)  /* version 3 */
#define SKP_IMAGE_INFLUENCE_BYTES_V2  (1 + 4 * SKP_MAX_INFLUENCES)  /* versions 1 and 2 */

enum skp_image_kind {
	SKP_KIND_HEADER = 1,
	SKP_KIND_SKELETON,
	SKP_KIND_BIND,
	SKP_KIND_DIRECTORY,
	SKP_KIND_QUANT,
	SKP_KIND_FRAMES
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

typedef struct skp_image_header {
	uint16_t version;
	uint16_t header_size;
	uint32_t block_size, block_count;
	uint64_t sequence;
	uint32_t bones, dofs, verts, tris, influences, clips;
	skp_image_section sec[SKP_SEC_COUNT];
	uint32_t data_blocks;     /* D: block_count for version 1 */
	uint32_t parity_blocks;   /* P: 0 for version 1 */
	uint32_t copy_block;      /* the header copy, 0 for none */
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
} skp_image_clip;

static inline uint32_t skp_image_tag(uint64_t sequence)
{
	return (uint32_t)sequence ^ (uint32_t)(sequence >> 32);
}

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

/* Encodes a version 2 header (116 bytes) with its CRC. */
void skp_image_header_put(uint8_t *p, const skp_image_header *h);

/* Decodes a header of either version from n bytes at p. Returns 1 when it
 * is one (magic, a known version, its size, its CRC), else 0; h is filled
 * as far as the bytes go either way (messages use it). */
int skp_image_header_get(const uint8_t *p, uint32_t n, skp_image_header *h);

/* The parity group of data block b (version 2 with parity). */
static inline uint32_t skp_image_group(const skp_image_header *h, uint32_t b)
{
	return h->parity_blocks ? b % h->parity_blocks : 0;
}

#endif
