/* skintool mannequin SKELETON.asf -o body.obj [--detail N]: a closed body
 * mesh generated around the skeleton's rest pose. */
#include <stdio.h>
#include <string.h>

#include "cli_args.h"
#include "cli_error.h"
#include "motion_file.h"
#include "setup_mesh_io.h"
#include "cli_opts.h"
#include "cli_quiet.h"
#include "mannequin.h"
#include "skintool_cmds.h"
#include "tool_body_out.h"
#include "tool_state.h"

typedef struct manq_args {
	const char *asf, *out;
	long detail;
} manq_args;

enum { OPT_SKELETON = 1, OPT_OUTPUT, OPT_DETAIL };

static const cli_opt manq_opts[] = {
	{ "skeleton", 0, "S.asf", OPT_SKELETON, "the skeleton, ASF or BVH (or the file named)" },
	{ "output", 'o', "BODY.obj", OPT_OUTPUT, "the OBJ to write (under a temporary name first)" },
	{ "detail", 0, "N", OPT_DETAIL, "grid cells across the body's largest extent (default 72, 8 to the board limit)" },
	{ NULL, 0, NULL, 0, NULL },
};

static int manq_take(void *ctx, int id, const char *v)
{
	manq_args *a = ctx;
	if (id == OPT_SKELETON)
		a->asf = v;
	else if (id == OPT_OUTPUT)
		a->out = v;
	else
		return cli_parse_long("--detail", v, &a->detail);
	return 0;
}

static int manq_file(void *ctx, const char *arg)
{
	manq_args *a = ctx;
	const char **slots[] = { &a->asf };
	return cli_take_positional("skintool mannequin", slots, 1, arg);
}

static const cli_command manq_command = {
	.prog = "skintool mannequin",
	.usage = "SKELETON -o BODY.obj [--detail=N]",
	.about = "Writes a closed, outward-facing body mesh around the skeleton's rest pose (arms that hang are\n"
		 "raised sideways first): the body skinplay shows when no mesh is given.",
	.opts = { manq_opts },
	.take = manq_take,
	.positional = manq_file,
	.examples = (const cli_example[]){
		{ "The generated body of a CMU skeleton",
		  "skintool mannequin 02.asf -o body.obj" },
		{ NULL, NULL },
	},
};

static int parse_args(int argc, char **argv, manq_args *a)
{
	a->asf = a->out = NULL;
	a->detail = MANQ_DEFAULT_DETAIL;
	int rc = cli_parse(&manq_command, a, argc, argv, 0);
	if (rc != 0)
		return rc;
	if (!a->asf || !a->out) {
		return cli_missing(manq_command.prog, "SKELETON and -o BODY.obj");
	}
	if (a->detail < MANQ_MIN_DETAIL || a->detail > MANQ_MAX_DETAIL) {
		fprintf(stderr, "skintool mannequin: --detail must be %d..%d, got %ld\n",
			MANQ_MIN_DETAIL, MANQ_MAX_DETAIL, a->detail);
		return -1;
	}
	return 0;
}

int cmd_mannequin(int argc, char **argv)
{
	static skel s;
	TOOL_STATE(manq_work, work);
	TOOL_STATE(mesh, body);
	manq_args a;
	skp_error err;

	int rc = parse_args(argc, argv, &a);
	if (rc != 0)
		return rc < 0;
	if (motion_load_skel(a.asf, &s) < 0)
		return 1;
	if (manq_build(&s, (int)a.detail, work, body, &err) != SKP_OK) {
		cli_error(a.asf, &err);
		return 1;
	}
	if (tool_write_obj(a.out, body, TOOL_GENERATED_BODY) < 0)
		return 1;
	fprintf(cli_summary(), "%s: %d vertices, %d triangles", a.out, body->vert_count, body->tri_count);
	if (work->arms_raised)
		fprintf(cli_summary(), ", around the rest pose with %d hanging arm%s raised sideways (the pose it binds in)",
		       work->arms_raised, work->arms_raised == 1 ? "" : "s");
	fprintf(cli_summary(), "\n");
	return 0;
}
