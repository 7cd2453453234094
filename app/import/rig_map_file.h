/* A joint map for a rig the built-in names do not cover (rig_map.h): one
 * pair per line,
 *     MESH_JOINT = SKELETON_BONE
 * with `-` as the bone to leave a joint unmapped (it then moves with its
 * nearest mapped ancestor). Names are taken as written, spaces inside
 * them included, around them trimmed; `#` starts a comment; blank lines
 * are fine. Pairs override the automatic mapping joint by joint. */
#ifndef RIG_MAP_FILE_H
#define RIG_MAP_FILE_H

#include <stddef.h>

#include "rig_map.h"

/* Parses len bytes of text (not NUL-terminated). Errors carry the line. */
skp_status rig_map_file_parse(const char *text, size_t len, rig_map_file *out, skp_error *err);

/* Reads and parses a file (up to 1 MiB). */
skp_status rig_map_file_read(const char *path, rig_map_file *out, skp_error *err);

#endif
