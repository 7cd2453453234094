#include "setup_mesh_io.h"

#include <string.h>

#include "cli_error.h"
#include "setup_scratch.h"
#include "file_reader.h"

const obj_work *setup_load_obj(const char *path, const char *group, mesh *out, int *group_missing)
{
	obj_work *work = &setup_scratch_area()->obj;
	static file_reader fr;
	static text_lines tl;
	obj_options opt = { group, 0, 0 };
	skp_error err;

	if (group_missing)
		*group_missing = 0;
	int rc = file_reader_open(&fr, path);
	if (rc < 0) {
		cli_error_errno(path, "open", rc);
		return NULL;
	}
	text_lines_init(&tl, file_reader_as_reader(&fr));
	skp_status st = obj_parse(out, work, &tl, &opt, &err);
	file_reader_close(&fr);
	if (st != SKP_OK) {
		cli_error(path, &err);
		if (group_missing)
			*group_missing = group && st == SKP_ERR_RANGE && work->kept_faces == 0 && err.line == 0;
		return NULL;
	}
	return work;
}

int setup_obj_is_generated(const char *path)
{
	static const char head[] = "# " TOOL_GENERATED_BODY ":";
	char got[sizeof head - 1];
	return file_reader_head(path, got, sizeof got) == (long)sizeof got && memcmp(got, head, sizeof got) == 0;
}
