/* skintool skin SKELETON.asf MOTION.amc MESH.obj --frame N --algo A
 *               [bind options] -o OUT.obj
 * The mesh deformed for frame N (the number written in the AMC): the same
 * vertices in the same order, skinned normals, the same faces. */
#include <stdio.h>
#include <string.h>

#include "cli_bind_args.h"
#include "cli_common.h"
#include "cli_mesh_io.h"
#include "cli_skin.h"
#include "skintool_cmds.h"

#define CMD "skintool skin"
#define SKIN_USAGE "usage: skintool skin SKELETON.asf MOTION.amc MESH.obj --frame N " \
	"--algo lbs|dqbs|dqbs-fixed " BIND_ARGS_USAGE " -o OUT.obj\n"

typedef struct skin_args {
	bind_args bind;
	const char *asf, *amc, *obj, *out;
	long frame;
	int have_frame;
	int algo;
} skin_args;

static int parse_algo(const char *name, int *algo)
{
	*algo = skin_algo_parse(name);
	if (*algo < 0 || *algo >= SKIN_ALGO_COUNT) {
		fprintf(stderr, "skintool skin: unknown --algo '%s' (lbs, dqbs or dqbs-fixed)\n", name);
		return -1;
	}
	return 0;
}

static int parse_one(skin_args *a, int argc, char **argv, int *i)
{
	const char *opt = argv[*i], *val;
	int r = bind_args_parse(&a->bind, argc, argv, i);
	if (r != 0)
		return r < 0 ? -1 : 0;
	if (strcmp(opt, "--frame") == 0) {
		a->have_frame = 1;
		return (val = cli_option_value(CMD, opt, argc, argv, i)) ? cli_parse_long(opt, val, &a->frame) : -1;
	}
	if (strcmp(opt, "--algo") == 0)
		return (val = cli_option_value(CMD, opt, argc, argv, i)) ? parse_algo(val, &a->algo) : -1;
	if (strcmp(opt, "-o") == 0)
		return (a->out = cli_option_value(CMD, opt, argc, argv, i)) ? 0 : -1;
	if (opt[0] == '-' && opt[1]) {
		fprintf(stderr, "skintool skin: unknown option '%s'\n", opt);
		return -1;
	}
	const char **const slots[] = { &a->asf, &a->amc, &a->obj };
	return cli_take_positional(CMD, slots, 3, opt);
}

static int parse_args(skin_args *a, int argc, char **argv)
{
	memset(a, 0, sizeof *a);
	bind_args_init(&a->bind);
	a->algo = -1;
	for (int i = 0; i < argc; i++)
		if (parse_one(a, argc, argv, &i) < 0)
			return -1;
	cli_bvh_slots(&a->asf, &a->amc, &a->obj);
	if (!a->asf || !a->amc || !a->obj || !a->out || !a->have_frame || a->algo < 0) {
		fputs(SKIN_USAGE, stderr);
		return -1;
	}
	return 0;
}

/* Replaces the bound mesh's positions and normals by the skinned ones. */
static void store(mesh *m, const float *pos, const float *nrm)
{
	for (int v = 0; v < m->vert_count; v++) {
		m->pos[v] = vec3_make(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
		m->normal[v] = vec3_make(nrm[3 * v], nrm[3 * v + 1], nrm[3 * v + 2]);
	}
}

int cmd_skin(int argc, char **argv)
{
	static skin_args a;
	static bound_body body;
	static cli_skin sk;
	static amc_frame f;
	static float pos[3 * SKP_MAX_VERTS], nrm[3 * SKP_MAX_VERTS];

	if (parse_args(&a, argc, argv) < 0)
		return 1;
	if (bind_args_load(&a.bind, a.asf, a.obj, &body) < 0)
		return 1;
	if (cli_read_frame(a.amc, &body.skel, a.frame, &f) < 0)
		return 1;
	if (cli_skin_init(&sk, &body.skel, &body.pose, &body.mesh, &body.weights, a.obj) < 0)
		return 1;
	cli_skin_frame(&sk, f.value);
	cli_skin_run(&sk, (skin_algo)a.algo, pos, nrm);
	store(&body.mesh, pos, nrm);
	return mesh_write_obj(a.out, &body.mesh, NULL) < 0 ? 1 : 0;
}
