#include "cli_image_out.h"

#include <stdio.h>
#include <string.h>

#include "cli_error.h"
#include "cli_inputs.h"

int cli_image_out_replace(cli_image_out *o, const char *path, uint32_t block_size)
{
	if (cli_output_file_check(path, 1) < 0)
		return -1;
	int rc = atomic_file_open(&o->af, path);
	if (rc == 0 && (rc = storage_file_use_fd(&o->sf, o->af.fd, block_size)) < 0)
		atomic_file_abort(&o->af);
	if (rc < 0) {
		cli_error_errno(path, "create", rc);
		return -1;
	}
	return 0;
}

int cli_image_out_open(cli_image_out *o, const char *path, uint32_t block_size)
{
	return cli_output_check(path) < 0 ? -1 : cli_image_out_replace(o, path, block_size);
}

int cli_image_out_commit(cli_image_out *o)
{
	int rc = atomic_file_commit(&o->af);
	if (rc < 0) {
		cli_error_errno(o->af.path, "write", rc);
		cli_image_out_abort(o);
		return -1;
	}
	storage_file_close(&o->sf);
	return 0;
}

void cli_image_out_abort(cli_image_out *o)
{
	atomic_file_abort(&o->af);
	storage_file_close(&o->sf);
}
