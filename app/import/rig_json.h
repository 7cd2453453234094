/* JSON files for the rig readers (MakeHuman's .mhskel and .mhw), parsed by
 * json-c: the whole file at once, a syntax error named by its line. */
#ifndef RIG_JSON_H
#define RIG_JSON_H

#include <json-c/json.h>

#include "skp_error.h"

/* Largest file read: MakeHuman's weights are under 1 MB. */
#define RIG_JSON_MAX_BYTES (64L << 20)

/* The value the text holds (len bytes), or NULL with err naming the line
 * and what json-c expected; text after the value is an error too. The
 * caller frees the value with json_object_put. */
json_object *rig_json_parse(const char *text, size_t len, skp_error *err);

/* rig_json_parse on the file at path (errors: it cannot be read, it is
 * larger than RIG_JSON_MAX_BYTES). */
json_object *rig_json_load(const char *path, skp_error *err);

/* Member key of o when it has the type (json_type_double also takes an
 * integer: 1 is a number as much as 1.0), else NULL. */
json_object *rig_json_get(json_object *o, const char *key, json_type type);

#endif
