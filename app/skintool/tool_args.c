#include "tool_args.h"

#include <string.h>

#include "cli_args.h"

const cli_opt tool_opt_skeleton[] = {
	{ "skeleton", 0, "S.asf", TOOL_OPT_SKELETON, "the skeleton, ASF or BVH (or the first file named)" },
	{ NULL, 0, NULL, 0, NULL },
};
const cli_opt tool_opt_motion[] = {
	{ "motion", 0, "M.amc", TOOL_OPT_MOTION, "the motion, AMC or BVH (or the file after the skeleton)" },
	{ NULL, 0, NULL, 0, NULL },
};
const cli_opt tool_opt_mesh[] = {
	{ "mesh", 0, "MESH", TOOL_OPT_MESH, "the body: OBJ, a rigged glTF/FBX/COLLADA, or 'generated': the mannequin "
	  "made around the skeleton (the default)" },
	{ NULL, 0, NULL, 0, NULL },
};
const cli_opt tool_opt_output[] = {
	{ "output", 'o', "FILE", TOOL_OPT_OUTPUT, "write the result to FILE (written under a temporary name first)" },
	{ NULL, 0, NULL, 0, NULL },
};

void tool_common_init(tool_common *c, const char *prog)
{
	memset(c, 0, sizeof *c);
	c->prog = prog;
	bind_args_init(&c->bind);
}

int tool_common_take(tool_common *c, int id, const char *value)
{
	if (BIND_OPT_ID(id))
		return bind_args_take(&c->bind, c->prog, id, value);
	switch (id) {
	case TOOL_OPT_SKELETON: c->asf = value; return 0;
	case TOOL_OPT_MOTION: c->amc = value; return 0;
	case TOOL_OPT_MESH: c->mesh = value; return 0;
	case TOOL_OPT_OUTPUT: c->out = value; return 0;
	}
	return 1;
}

int tool_files_skel_mesh(void *ctx, const char *arg)
{
	tool_common *c = ctx;
	const char **slots[] = { &c->asf, &c->mesh };
	return cli_take_positional(c->prog, slots, 2, arg);
}

int tool_files_skel_motion_mesh(void *ctx, const char *arg)
{
	tool_common *c = ctx;
	const char **slots[] = { &c->asf, &c->amc, &c->mesh };
	return cli_take_positional(c->prog, slots, 3, arg);
}

static int no_option(void *ctx, int id, const char *value)
{
	(void)ctx, (void)id, (void)value;
	return -1;
}

static int one_file(void *ctx, const char *arg)
{
	const char **path = ctx;
	if (*path) {
		fprintf(stderr, "skintool: one image at a time: '%s' and '%s'\n", *path, arg);
		return -1;
	}
	*path = arg;
	return 0;
}

int tool_one_file(const cli_command *c, int argc, char **argv, const char **path)
{
	cli_command cmd = *c;
	cmd.take = no_option;
	cmd.positional = one_file;
	*path = NULL;
	int rc = cli_parse(&cmd, (void *)path, argc, argv, 0);
	if (rc == 0 && !*path)
		return cli_missing(c->prog, "the image file");
	return rc;
}

int tool_missing(const tool_common *c, const char *what)
{
	return -cli_missing(c->prog, what);
}
