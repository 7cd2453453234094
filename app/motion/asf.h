/* Acclaim ASF skeleton parser (the whole spec, not only the CMU subset). */
#ifndef ASF_H
#define ASF_H

#include "skel.h"
#include "skp_error.h"
#include "text_lines.h"

/* Parses the ASF text from tl (initialised by the caller, which owns its
 * buffers) into out. On error returns the status and err names the line. */
skp_status asf_parse(skel *out, text_lines *tl, skp_error *err);

/* Rotation C of an `axis` line: angles in radians, order[0] applied first. */
quat asf_axis_rotation(vec3 angles_rad, const uint8_t order[3]);

#endif
