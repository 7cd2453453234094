/* Which reader a mesh file goes to, by its content (mesh_format.h): an OBJ
 * to the OBJ parser, a glb, glTF, FBX, COLLADA, zipped COLLADA (.zae),
 * Blender file, ... to the importer, whatever the file is called. Files
 * whose content says nothing go by their extension. */
#ifndef SETUP_MESH_FORMAT_H
#define SETUP_MESH_FORMAT_H

#include "mesh_format.h"

/* The format of the file at path; MESH_FMT_EMPTY also when it cannot be
 * read (the reader then says why). */
mesh_format setup_mesh_format(const char *path);

/* 1 when path goes to the importer: its content is an interchange format,
 * or says nothing (or looks like an OBJ, whose statements are common
 * words) and its extension is one the importer reads (.3ds, .nff, ...). */
int setup_mesh_is_interchange(const char *path);

/* 1 when the file's extension is one the format goes by (or the content
 * says too little to tell). */
int setup_mesh_format_named(const char *path, mesh_format f);

/* When the extension names another format than the content has, one line
 * on stderr saying what the file is and how it is read. */
void setup_mesh_format_note(const char *path, mesh_format f);

/* For a file that is to be read as an OBJ: 0 when its content is one (or
 * it cannot be read: the OBJ reader says why); -1 after saying what the
 * file is and what skintool reads instead. */
int setup_mesh_check_obj(const char *path);

#endif
