/* A Wavefront material library (.mtl), the file an OBJ's `mtllib` names:
 * each `newmtl NAME`'s diffuse colour (`Kd r g b`, or `Kd r` for a grey)
 * and diffuse texture (`map_Kd [options] FILE`; a Windows `.\x.jpg`
 * read as `./x.jpg`). Every other statement (Ka, Ks, Ns, d, illum, bump,
 * ...) is skipped. Host code (stdio): a line it cannot read is a warning
 * naming the file and line, never the end of the import. */
#ifndef RIG_MTL_H
#define RIG_MTL_H

#include <stdio.h>

#include "board_limits.h"

#define RIG_MTL_MAX 64          /* materials kept (the rest are counted) */
#define RIG_MTL_WARNINGS 8      /* warnings kept (the rest are counted) */
#define RIG_MTL_PATH 512

typedef struct rig_mtl_material {
	char name[SKP_MAX_NAME];   /* as written, words one space apart */
	int has_kd;
	float kd[3];               /* 0..1, as written (linear, as the glTF path takes Kd) */
	char map_kd[RIG_MTL_PATH]; /* "" none; relative to the .mtl's directory */
} rig_mtl_material;

typedef struct rig_mtl {
	int count;
	rig_mtl_material mat[RIG_MTL_MAX];
	int warnings;              /* lines it could not read */
	char warning[RIG_MTL_WARNINGS][300]; /* the first, "LINE: what" (names escaped) */
} rig_mtl;

/* Reads the library at path into out; 0 with *why ("is missing",
 * "cannot be read", "is not a text file") when it cannot be read at all. */
int rig_mtl_read(const char *path, rig_mtl *out, const char **why);

/* The same from an open stream (the fuzzer's, in memory), read from its
 * start; the caller closes it. */
int rig_mtl_read_stream(FILE *f, rig_mtl *out, const char **why);

/* The material named name, or NULL. */
const rig_mtl_material *rig_mtl_find(const rig_mtl *m, const char *name);

#endif
