/* Compile-time limits of the Cortex-M4 board (mps2-an386 under QEMU, and
 * any M4F with a few hundred KiB of RAM): enough for a CMU skeleton
 * (31 bones) and a low-detail body. */
#ifndef BOARD_LIMITS_H
#define BOARD_LIMITS_H

#define SKP_MAX_BONES       40  /* bones including the root */
#define SKP_MAX_NAME        32  /* bone / skeleton name, with NUL */
#define SKP_MAX_LINE       256  /* longest text line of ASF/AMC/OBJ, bytes */
#define SKP_MAX_TOKENS      32  /* tokens on one line */
#define SKP_READ_CHUNK     256  /* bytes a text reader pulls per callback */

#define SKP_MAX_VERTS     2048  /* mesh vertices */
#define SKP_MAX_TRIS      4096  /* mesh triangles after triangulation */
#define SKP_MAX_INFLUENCES   4  /* bones per vertex */

/* No GPU: an image's texture is skipped (the body keeps its colours). */
#define SKP_MAX_TEXTURE_SIDE 0

/* Each bone has at most 7 dof (rx ry rz tx ty tz l); the root has 6. */
#define SKP_MAX_DOF (7 * SKP_MAX_BONES)

/* Packed flash images (app/image/image_format.h): same block size as the host
 * (an image written there reads here), fewer blocks in RAM and clips. */
#define SKP_IMAGE_BLOCK_SIZE  4096
#define SKP_IMAGE_RING_BLOCKS    4
#define SKP_IMAGE_CACHE_BLOCKS   2   /* blocks rebuilt from parity, kept for the next passes */
#define SKP_IMAGE_MAX_CLIPS      8

#endif
