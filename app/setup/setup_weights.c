#include "setup_weights.h"

#include <string.h>

#include "cli_error.h"
#include "file_reader.h"
#include "weights_csv.h"

int setup_load_weights(const char *path, const skel *s, int vert_count, skin_weights *out)
{
	static file_reader fr;
	static text_lines tl;
	skp_error err;

	int rc = file_reader_open(&fr, path);
	if (rc < 0) {
		cli_error_errno(path, "open", rc);
		return -1;
	}
	text_lines_init(&tl, file_reader_as_reader(&fr));
	skp_status st = weights_csv_read(&tl, s, vert_count, out, &err);
	file_reader_close(&fr);
	if (st != SKP_OK) {
		cli_error(path, &err);
		return -1;
	}
	return 0;
}
