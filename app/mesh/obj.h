/* Wavefront OBJ import into a mesh: v, vn, vt (checked, not stored), f with
 * any polygon (quads split along the shorter diagonal, larger polygons
 * fanned), the v, v/vt, v/vt/vn and v//vn corner forms, negative (relative)
 * indices, and an optional group filter on o/g names. vt coordinates,
 * each kept triangle's corners' vt and its usemtl material, and the first
 * mtllib's name are recorded for the host's importer (app/import's
 * rig_obj_colour.h reads the .mtl); s, l, p, comments and the other OBJ
 * statements are ignored.
 *
 * Kept vertices are numbered in ascending file order. Without a group
 * filter every `v` is kept, so mesh vertex i is the file's i-th `v`; with a
 * filter only the vertices the kept faces use are, and work->source maps
 * them back (weights files index the mesh order). */
#ifndef OBJ_H
#define OBJ_H

#include <stdint.h>

#include "mesh.h"
#include "skp_error.h"
#include "text_lines.h"

/* Positions are stored before the faces tell which vertices are kept, so
 * the file (not only the kept part) must fit these. */
#define OBJ_MAX_FILE_VERTS   (2 * SKP_MAX_VERTS)  /* `v` lines in one file */
#define OBJ_MAX_FILE_NORMALS (2 * SKP_MAX_VERTS)  /* `vn` lines in one file */
/* `vt` lines kept (more are counted, and their faces lose their UVs) */
#define OBJ_MAX_FILE_TEXCOORDS (2 * SKP_MAX_VERTS)
/* Material names (`usemtl`) told apart; faces of further ones have none. */
#define OBJ_MAX_MATERIALS    64
/* Groups and objects (`g`, `o`) whose names and face counts are listed. */
#define OBJ_MAX_GROUPS       256
/* A corner takes at least two bytes of a line ("1 "). */
#define OBJ_MAX_CORNERS      (SKP_MAX_LINE / 2)

typedef struct obj_options {
	const char *group;  /* keep faces of the o/g of that name; NULL: all */
	int max_verts;      /* 0: SKP_MAX_VERTS (lower values test the check) */
	int max_tris;       /* 0: SKP_MAX_TRIS */
} obj_options;

typedef struct obj_corner {
	uint32_t v;         /* 0-based file vertex */
	int32_t vn;         /* 0-based file normal, -1 when absent */
	int32_t vt;         /* 0-based file texture coordinate, -1 when absent */
} obj_corner;

/* A `g` or `o` name and the faces that follow it (until the next one). */
typedef struct obj_group {
	char name[SKP_MAX_NAME];
	long faces;
} obj_group;

/* Working memory of obj_parse (several MB: callers keep it static). After
 * a successful parse, source and the counts describe the import. */
typedef struct obj_work {
	vec3 pos[OBJ_MAX_FILE_VERTS];
	vec3 nsum[OBJ_MAX_FILE_VERTS];      /* sum of the kept corners' vn */
	int32_t kept[OBJ_MAX_FILE_VERTS];   /* file vertex -> mesh vertex or -1 */
	vec3 vn[OBJ_MAX_FILE_NORMALS];
	obj_corner corner[OBJ_MAX_CORNERS];
	char *tok[OBJ_MAX_CORNERS + 1];
	uint32_t source[SKP_MAX_VERTS];     /* mesh vertex -> 0-based file `v` */
	long file_verts, file_normals, file_texcoords;
	long file_faces, kept_faces;
	int normals_from_file;              /* 1: every kept corner had a vn */
	obj_group group[OBJ_MAX_GROUPS];    /* in the file's order, with or without a filter */
	int group_count;
	int group_overflow;                 /* more names than OBJ_MAX_GROUPS (not listed) */
	int current_group;                  /* index of the faces' group, -1 none */
	/* materials: the texture coordinates (u, v as written; the first
	 * OBJ_MAX_FILE_TEXCOORDS), each kept triangle's corners' vt (-1 none)
	 * and usemtl (an index into mtl_name, -1 none), the first mtllib's
	 * file name ("" none), all as in the file (raw bytes) */
	float vt[OBJ_MAX_FILE_TEXCOORDS][2];
	int32_t tri_vt[SKP_MAX_TRIS][3];
	int16_t tri_mtl[SKP_MAX_TRIS];
	char mtl_name[OBJ_MAX_MATERIALS][SKP_MAX_NAME];
	int mtl_count;
	int current_mtl;
	char mtllib[SKP_MAX_NAME];
} obj_work;

/* Parses the OBJ text from tl (initialised by the caller) into out.
 * opt may be NULL (no filter, board limits). On error returns the status
 * and err names the line. */
skp_status obj_parse(mesh *out, obj_work *work, text_lines *tl,
		     const obj_options *opt, skp_error *err);

#endif
