/* Compile-time limits of the Cortex-M0 board: a CMU skeleton (31 bones)
 * and a small body; the fixed-point kernel streams the body from flash. */
#ifndef BOARD_LIMITS_H
#define BOARD_LIMITS_H

#define SKP_MAX_BONES       32  /* bones including the root */
#define SKP_MAX_NAME        32  /* bone / skeleton name, with NUL */
#define SKP_MAX_LINE       256  /* longest text line of ASF/AMC/OBJ, bytes */
#define SKP_MAX_TOKENS      32  /* tokens on one line */
#define SKP_READ_CHUNK     256  /* bytes a text reader pulls per callback */

#define SKP_MAX_VERTS     1024  /* mesh vertices */
#define SKP_MAX_TRIS      2048  /* mesh triangles after triangulation */
#define SKP_MAX_INFLUENCES   4  /* bones per vertex */

/* No GPU: an image's texture is skipped (the body keeps its colours). */
#define SKP_MAX_TEXTURE_SIDE 0

/* Each bone has at most 7 dof (rx ry rz tx ty tz l); the root has 6. */
#define SKP_MAX_DOF (7 * SKP_MAX_BONES)

/* Packed flash images (app/image/image_format.h): same block size as the host
 * (an image written there reads here), fewer blocks in RAM and clips. */
#define SKP_IMAGE_BLOCK_SIZE  4096
#define SKP_IMAGE_RING_BLOCKS    4
#define SKP_IMAGE_CACHE_BLOCKS   1   /* blocks rebuilt from parity, kept for the next passes */
#define SKP_IMAGE_MAX_CLIPS      4

#endif
