/* An OBJ's materials (its `mtllib` .mtl, rig_mtl.h) on the mesh the OBJ
 * reader made of it, packed as the glTF path packs a file's (rig_colour.h):
 * per `usemtl` group its Kd as the base colour (linear, stored sRGB in
 * mesh.colour) times its map_Kd texture (PNG or JPEG, through rig_colour's
 * decoders and limits) at the corner's `vt`. The texture on the most
 * triangles goes to the GPU (the scene's texture_rgba, mesh.textured),
 * the others are baked at each vertex's first corner.
 *
 * The OBJ's vertices keep their numbers (a MakeHuman .mhw indexes them): a
 * vertex whose corners show different texels of the GPU's texture (a UV
 * seam) gets a twin appended after the file's vertices, with its place,
 * normal and weights, noted in the scene's seam_lead (rig_seam.h) so the
 * two move and shade as one. A library, material or texture that cannot be
 * read is a warning in the report; its vertices keep the material's Kd, or
 * the skin colour. An OBJ without mtllib is left exactly as it was. */
#ifndef RIG_OBJ_COLOUR_H
#define RIG_OBJ_COLOUR_H

#include "obj.h"
#include "rig_scene.h"

#define RIG_OBJ_WARNINGS 8

typedef struct rig_obj_colour_report {
	char library[1024];     /* the .mtl's path ("" none named) */
	int materials;          /* usemtl materials the library has */
	int textures;           /* their textures read */
	int twins;              /* vertices added at UV seams */
	int warnings;           /* problems (the first RIG_OBJ_WARNINGS kept) */
	char warning[RIG_OBJ_WARNINGS][400]; /* sentences, input bytes escaped */
} rig_obj_colour_report;

/* Colours r's mesh (the OBJ at obj_path as w parsed it, its weights in r)
 * from the OBJ's materials. */
void rig_obj_colour(const char *obj_path, const obj_work *w, rig_scene *r, rig_obj_colour_report *rep);

#endif
