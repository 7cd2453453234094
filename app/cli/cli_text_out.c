#include "cli_text_out.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

#include "cli_error.h"
#include "cli_inputs.h"

int cli_text_out_open(cli_text_out *o, const char *path)
{
	o->f = NULL;
	if (cli_output_check(path) < 0 || cli_output_file_check(path, 0) < 0)
		return -1;
	int rc = atomic_file_open(&o->af, path);
	if (rc == 0 && !(o->f = fdopen(o->af.fd, "w"))) {
		rc = -errno;
		close(o->af.fd);
		atomic_file_abort(&o->af);
	}
	if (rc < 0) {
		cli_error_errno(path, "create", rc);
		return -1;
	}
	return 0;
}

int cli_text_out_commit(cli_text_out *o)
{
	int rc = fflush(o->f) == 0 && !ferror(o->f) ? 0 : -(errno ? errno : EIO);
	if (rc == 0)
		rc = atomic_file_commit(&o->af);
	if (rc < 0) {
		cli_error_errno(o->af.path, "write", rc);
		cli_text_out_abort(o);
		return -1;
	}
	fclose(o->f);
	return 0;
}

void cli_text_out_abort(cli_text_out *o)
{
	atomic_file_abort(&o->af);
	fclose(o->f);
}
