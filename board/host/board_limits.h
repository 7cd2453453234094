/* Compile-time limits of the host board: every fixed array in app/ is sized
 * from these, so `make size` shows the whole static memory the device needs. */
#ifndef BOARD_LIMITS_H
#define BOARD_LIMITS_H

#define SKP_MAX_BONES      128  /* bones including the root */
#define SKP_MAX_NAME        48  /* bone / skeleton name, with NUL */
#define SKP_MAX_LINE     16384  /* longest text line of ASF/AMC/BVH/OBJ, bytes: a BVH frame is one line */
#define SKP_MAX_TOKENS      32  /* tokens on one line */
#define SKP_READ_CHUNK    4096  /* bytes a text reader pulls per callback */

#define SKP_MAX_VERTS    65536  /* mesh vertices (MakeHuman body: 13380) */
#define SKP_MAX_TRIS    131072  /* mesh triangles after triangulation */
#define SKP_MAX_INFLUENCES   4  /* bones per vertex */

/* The largest side of a body's base colour texture (a power of two): the
 * tool scales a larger one down to it, and the device keeps its ETC1 mip
 * chain (side * side / 2 * 4 / 3 bytes) and, for a GPU without ETC1, one
 * level decoded to RGB565 (side * side * 2 bytes) in static RAM. */
#define SKP_MAX_TEXTURE_SIDE 1024

/* The largest frame skinplay renders headless or reads back for --out
 * (its buffer is W * H * 4 bytes of static RAM) and a board config may ask
 * for; a screen's own mode may be larger. */
#define SKP_DISPLAY_MAX_W 3840
#define SKP_DISPLAY_MAX_H 2160

/* Each bone has at most 7 dof (rx ry rz tx ty tz l); the root has 6. */
#define SKP_MAX_DOF (7 * SKP_MAX_BONES)

/* Packed flash images (app/image/image_format.h): the largest block the board
 * reads, the blocks kept in RAM ahead of the play head, and the clips one
 * image may hold. Playback needs RING * BLOCK bytes whatever the clip's length. */
#define SKP_IMAGE_BLOCK_SIZE  4096
#define SKP_IMAGE_RING_BLOCKS    4
#define SKP_IMAGE_CACHE_BLOCKS   4   /* blocks rebuilt from parity, kept for the next passes */
#define SKP_IMAGE_MAX_CLIPS     64
#define SKP_IMAGE_MAX_DIGEST_BLOCKS 1024 /* each digest block covers 254 blocks: images to 1 GB */

#endif
