/* Compile-time limits of the Raspberry Pi 4 kiosk, fitted to it: skinplay's
 * static RAM is about 26 MB here (`make BOARD=rpi4 size`), against 32 MB
 * budgeted, so that even a 1 GiB Pi keeps most of its memory for the GPU
 * and the page cache. */
#ifndef BOARD_LIMITS_H
#define BOARD_LIMITS_H

#define SKP_MAX_BONES      128  /* bones including the root */
#define SKP_MAX_NAME        48  /* bone / skeleton name, with NUL */
#define SKP_MAX_LINE     16384  /* longest text line of ASF/AMC/BVH/OBJ/INI, bytes: a BVH frame is one line */
#define SKP_MAX_TOKENS      32  /* tokens on one line */
#define SKP_READ_CHUNK    4096  /* bytes a text reader pulls per callback */

#define SKP_MAX_VERTS    32768  /* mesh vertices: 2.5x the generated body (11,702), */
#define SKP_MAX_TRIS     65536  /* 2.4x the MakeHuman body (13,380); 396 B each */
#define SKP_MAX_INFLUENCES   4  /* bones per vertex */

/* The largest side of a body's base colour texture (a power of two): the
 * tool scales a larger one down to it, and the device keeps its ETC1 mip
 * chain (side * side / 2 * 4 / 3 bytes) and, for a GPU without ETC1, one
 * level decoded to RGB565 (side * side * 2 bytes) in static RAM. */
#define SKP_MAX_TEXTURE_SIDE 1024

/* The largest frame rendered headless or read back for --out (W * H * 4
 * bytes); the screen's own mode on kms may be larger. */
#define SKP_DISPLAY_MAX_W 1920
#define SKP_DISPLAY_MAX_H 1080

/* Each bone has at most 7 dof (rx ry rz tx ty tz l); the root has 6. */
#define SKP_MAX_DOF (7 * SKP_MAX_BONES)

/* Packed flash images (app/image/image_format.h): see board/host/board_limits.h.
 * SD cards read 4 KiB pages well. */
#define SKP_IMAGE_BLOCK_SIZE  4096
#define SKP_IMAGE_RING_BLOCKS    4
#define SKP_IMAGE_CACHE_BLOCKS   4   /* blocks rebuilt from parity, kept for the next passes */
#define SKP_IMAGE_MAX_CLIPS     64
#define SKP_IMAGE_MAX_DIGEST_BLOCKS 1024 /* each digest block covers 254 blocks: images to 1 GB */

/* board.ini (app/kiosk/board_config.h): path length; image slots (A, B, the demo). */
#define SKP_MAX_PATH  256
#define SKP_MAX_SLOTS   3

#endif
