/* What a mesh file is, by its content rather than its name: a glb, a
 * zipped COLLADA (.zae) or a Blender file named .obj is still what its
 * bytes say, and an OBJ is recognised by its statements. Only the first
 * bytes are looked at (MESH_FORMAT_HEAD); the result picks the reader
 * (OBJ parser or the asset importer) and names the format in messages. */
#ifndef MESH_FORMAT_H
#define MESH_FORMAT_H

#include <stddef.h>

/* Bytes of the file's start mesh_format_sniff needs to see. */
#define MESH_FORMAT_HEAD 4096

typedef enum mesh_format {
	MESH_FMT_UNKNOWN_BINARY, /* bytes no rule below knows */
	MESH_FMT_UNKNOWN_TEXT,   /* text, but none of the text formats */
	MESH_FMT_EMPTY,
	MESH_FMT_OBJ,
	MESH_FMT_GLB,            /* binary glTF 2.0 */
	MESH_FMT_GLTF,           /* glTF JSON */
	MESH_FMT_JSON,           /* JSON that is not glTF (a MakeHuman .mhskel, ...) */
	MESH_FMT_FBX,            /* binary or ASCII */
	MESH_FMT_COLLADA,
	MESH_FMT_XML,            /* other XML (X3D, Ogre, AMF, ...) */
	MESH_FMT_ZIP,            /* a zip archive: a zipped COLLADA (.zae) or 3MF, or any other */
	MESH_FMT_BLEND,
	MESH_FMT_X,              /* DirectX */
	MESH_FMT_PLY,
	MESH_FMT_STL,            /* ASCII STL (binary STL has no signature) */
	MESH_FMT_OTHER_MODEL,    /* a signature of another model format the importer reads */
	MESH_FMT_COUNT
} mesh_format;

/* The format of a file starting with the n bytes at head (n may be less
 * than MESH_FORMAT_HEAD for a short file). */
mesh_format mesh_format_sniff(const unsigned char *head, size_t n);

/* "a binary glTF (.glb)", "a zip archive", ... for messages. */
const char *mesh_format_name(mesh_format f);

/* The extension files of the format usually have, without the dot
 * ("glb", "zae", ...), or NULL when there is no single one. */
const char *mesh_format_extension(mesh_format f);

/* 1 when the asset importer reads it (everything but OBJ, empty and
 * unknown files). */
int mesh_format_is_interchange(mesh_format f);

#endif
