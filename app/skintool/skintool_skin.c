/* skintool skin SKELETON.asf MOTION.amc MESH.obj --frame N --algo A
 *               [bind options] -o OUT.obj
 * The mesh deformed for frame N (the number written in the AMC): the same
 * vertices in the same order, skinned normals, the same faces. */
#include <stdio.h>
#include <string.h>

#include "cli_bind_args.h"
#include "cli_args.h"
#include "motion_file.h"
#include "runtime_body.h"
#include "rig_load.h"
#include "setup_bind.h"
#include "setup_mesh_io.h"
#include "runtime_skin.h"
#include "skintool_cmds.h"
#include "tool_args.h"
#include "tool_body_out.h"
#include "tool_state.h"

typedef struct skin_args {
	tool_common c;
	long frame;
	int have_frame;
	int algo;
} skin_args;

enum { OPT_FRAME = 1, OPT_ALGO };

static const cli_opt skin_cmd_opts[] = {
	{ "frame", 0, "N", OPT_FRAME, "the frame numbered N in the motion file (required)" },
	{ "algo", 0, "ALGO", OPT_ALGO, "lbs, dqbs or dqbs-fixed (required)" },
	{ NULL, 0, NULL, 0, NULL },
};

static int skin_take(void *ctx, int id, const char *v)
{
	static const char *const algos[] = { "lbs", "dqbs", "dqbs-fixed" };
	skin_args *a = ctx;
	int r = tool_common_take(&a->c, id, v);
	if (r <= 0)
		return r;
	if (id == OPT_FRAME) {
		a->have_frame = 1;
		return cli_parse_long("--frame", v, &a->frame);
	}
	return (a->algo = cli_choice(a->c.prog, "algo", v, algos, SKIN_ALGO_COUNT)) < 0 ? -1 : 0;
}

static const cli_command skin_command = {
	.prog = "skintool skin",
	.usage = "SKELETON MOTION MESH --frame=N --algo=ALGO [OPTION]... -o OUT.obj",
	.about = "Writes the mesh deformed for one frame of the motion as OBJ: the same vertices in the same\n"
		 "order, skinned normals, the same faces. MOTION.bvh alone stands for SKELETON MOTION.",
	.opts = { tool_opt_skeleton, tool_opt_motion, tool_opt_mesh, tool_opt_output, skin_cmd_opts, bind_opts },
	.take = skin_take,
	.positional = tool_files_skel_motion_mesh,
	.examples = (const cli_example[]){
		{ "Frame 100 of a walk skinned with DQBS, as OBJ",
		  "skintool skin 02.asf 02_01.amc body.obj --frame=100 --algo=dqbs -o pose.obj" },
		{ NULL, NULL },
	},
};

static int parse_args(skin_args *a, int argc, char **argv)
{
	tool_common_init(&a->c, skin_command.prog);
	a->have_frame = 0;
	a->algo = -1;
	int rc = cli_parse(&skin_command, a, argc, argv, 0);
	if (rc != 0)
		return rc;
	motion_bvh_slots(&a->c.asf, &a->c.amc, &a->c.mesh);
	if (!a->c.asf || !a->c.amc || !a->c.mesh || !a->c.out || !a->have_frame || a->algo < 0)
		return -tool_missing(&a->c, "SKELETON MOTION MESH, --frame, --algo and -o OUT.obj");
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
	TOOL_STATE(bound_body, body);
	static runtime_skin sk;
	static amc_frame f;
	static float pos[3 * SKP_MAX_VERTS], nrm[3 * SKP_MAX_VERTS];

	int rc = parse_args(&a, argc, argv);
	if (rc != 0)
		return rc < 0;
	a.c.bind.gate_motion = &a.c.amc;
	a.c.bind.gate_motion_count = 1;
	if (rig_bind_load(&a.c.bind, a.c.asf, a.c.mesh, body) < 0)
		return 1;
	if (motion_read_frame(a.c.amc, &body->skel, a.frame, &f) < 0)
		return 1;
	if (runtime_skin_init(&sk, &body->skel, &body->pose, &body->mesh, &body->weights, a.c.mesh) < 0)
		return 1;
	runtime_skin_frame(&sk, f.value);
	runtime_skin_run(&sk, (skin_algo)a.algo, pos, nrm);
	store(&body->mesh, pos, nrm);
	return tool_write_obj(a.c.out, &body->mesh, NULL) < 0 ? 1 : 0;
}
