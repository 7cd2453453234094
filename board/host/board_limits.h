/* Compile-time limits of the host board: every fixed array in app/ is sized
 * from these, so `make size` shows the whole static memory the device needs. */
#ifndef BOARD_LIMITS_H
#define BOARD_LIMITS_H

#define SKP_MAX_BONES      128  /* bones including the root */
#define SKP_MAX_NAME        48  /* bone / skeleton name, with NUL */
#define SKP_MAX_LINE      1024  /* longest text line of ASF/AMC/OBJ, bytes */
#define SKP_MAX_TOKENS      32  /* tokens on one line */
#define SKP_READ_CHUNK    4096  /* bytes a text reader pulls per callback */

#define SKP_MAX_VERTS    65536  /* mesh vertices (MakeHuman body: 13380) */
#define SKP_MAX_TRIS    131072  /* mesh triangles after triangulation */
#define SKP_MAX_INFLUENCES   4  /* bones per vertex */

/* Each bone has at most 7 dof (rx ry rz tx ty tz l); the root has 6. */
#define SKP_MAX_DOF (7 * SKP_MAX_BONES)

#endif
