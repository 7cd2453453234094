/* skintool bind SKELETON.asf MESH.obj [--group G] [--fit|--no-fit] [--bind-pose P.amc[:F]|rest]
 *               [--weights IN.csv] [--balance on|off] [--report] -o weights.csv
 * Binds the mesh to the skeleton (automatic weights, bind.h, balanced by
 * bind_balance.h with --balance on (the default for the generated body);
 * the given CSV after validation; or a rigged mesh's own) and writes the
 * weights CSV (-o - for stdout). The report always goes to stderr, so it
 * never mixes with a CSV on stdout. */
#include <stdio.h>
#include <string.h>

#include "cli_bind_args.h"
#include "runtime_body.h"
#include "rig_load.h"
#include "setup_bind.h"
#include "setup_weights.h"
#include "skintool_cmds.h"
#include "tool_args.h"
#include "tool_body_out.h"
#include "tool_state.h"


static void report_pose(FILE *to, const bind_args *a, const bound_body *b)
{
	if (b->rigged) {
		/* the importer said each step (turn, scale, proportions, pose) above */
		if (!a->pose_path && !a->rest_pose)
			fprintf(to, "bind pose: the skeleton posed as the mesh stands, by its joints\n");
		if (b->fitted)
			fprintf(to, "fit: the mesh put on the skeleton by its joints, the skeleton given its "
				"proportions\n");
		if (!a->pose_path && !a->rest_pose)
			return;
	}
	if (b->guess.turned)
		fprintf(to, "bind pose: the mesh's own, found from its shape (%d limb%s turned)\n", b->guess.turned,
			b->guess.turned == 1 ? "" : "s");
	else if (b->arms_raised)
		fprintf(to, "bind pose: the rest pose with %d hanging arm%s raised to point sideways\n",
			b->arms_raised, b->arms_raised == 1 ? "" : "s");
	else if (b->pose_frame < 0)
		fprintf(to, "bind pose: rest pose\n");
	else
		fprintf(to, "bind pose: %s frame %ld\n", a->pose_path, b->pose_frame);
	if (b->fitted && !b->rigged)
		fprintf(to, "fit: scale %.6g, offset %.6g %.6g %.6g (mesh height %.6g -> skeleton height %.6g)\n",
			(double)b->fit.scale, (double)b->fit.offset.x, (double)b->fit.offset.y,
			(double)b->fit.offset.z, (double)b->fit.mesh_height, (double)b->fit.skel_height);
}

static const char *const outcome_name[] = {
	[BIND_BALANCE_NEEDLESS] = "needless",
	[BIND_BALANCE_DONE] = "balanced",
	[BIND_BALANCE_PARTLY] = "in part: change capped",
};

/* Per joint with a cross-fade: the first-order volume change of a 30
 * degree bend before and after, the largest weight change, the rings. */
static void report_balance(FILE *to, const bound_body *b)
{
	const bind_balance_info *in = &b->balance;
	if (!b->balanced) {
		fprintf(to, "volume balancing: off\n");
		return;
	}
	fprintf(to, "volume balancing (volume %.6g; %% of it per 30 degrees):\n", in->volume);
	fprintf(to, "joint,moment_before,moment_after,largest_change,rings,outcome\n");
	for (int i = 1; i < b->skel.count; i++)
		if (in->outcome[i] != BIND_BALANCE_NONE)
			fprintf(to, "%s,%.4f,%.4f,%.3f,%d,%s\n", b->skel.bone[i].name,
				100.0 * in->moment[i], 100.0 * in->moment_after[i],
				(double)in->change[i], in->rings[i], outcome_name[in->outcome[i]]);
}

static void report(FILE *to, const bind_args *a, const bound_body *b)
{
	static skin_weights_stats st;
	const skel *s = &b->skel;
	skin_weights_stats_compute(&b->weights, s->count,
				   (const uint32_t (*)[3])b->mesh.tri, b->mesh.tri_count, &st);
	fprintf(to, "vertices: %d, triangles: %d, bones: %d\n", b->mesh.vert_count,
		b->mesh.tri_count, s->count);
	report_pose(to, a, b);
	if (b->automatic) {
		fprintf(to, "weights: automatic, %.3f ms\n", (double)b->bind_ns / 1e6);
		fprintf(to, "fallback to nearest bone: %d vertices\n", b->info.fallback);
		report_balance(to, b);
	} else if (a->weights_path) {
		fprintf(to, "weights: read from %s\n", a->weights_path);
	} else {
		fprintf(to, "weights: the mesh's own\n");
	}
	fprintf(to, "largest influence count: %d\n", st.max_influences);
	fprintf(to, "smoothness (mean weight difference across %ld triangle edges): %.6g\n",
		st.edge_count, st.edge_diff_mean);
	fprintf(to, "bone,vertices\n");
	for (int i = 0; i < s->count; i++)
		fprintf(to, "%s,%d\n", s->bone[i].name, st.bone_verts[i]);
}

#define BIND_MAX_MOTIONS 8

typedef struct bind_cmd {
	tool_common c;
	int want_report;
	const char *motion[BIND_MAX_MOTIONS];
	int motion_count;
} bind_cmd;

enum { OPT_REPORT = 1 };

static const cli_opt bind_cmd_opts[] = {
	{ "motion", 0, "M.amc", TOOL_OPT_MOTION, "a clip (AMC or BVH) the quality check plays too (repeat for more)" },
	{ "report", 0, NULL, OPT_REPORT, "also print how the body was bound (pose, fit, balancing, the quality gate's figures) on stderr" },
	{ NULL, 0, NULL, 0, NULL },
};

static int bind_take(void *ctx, int id, const char *v)
{
	bind_cmd *b = ctx;
	if (id == TOOL_OPT_MOTION) {
		if (b->motion_count == BIND_MAX_MOTIONS) {
			fprintf(stderr, "skintool bind: at most %d --motion files\n", BIND_MAX_MOTIONS);
			return -1;
		}
		b->motion[b->motion_count++] = v;
		return 0;
	}
	int r = tool_common_take(&b->c, id, v);
	if (r <= 0)
		return r;
	b->want_report = 1;
	return 0;
}

static const cli_command bind_command = {
	.prog = "skintool bind",
	.usage = "SKELETON MESH [OPTION]... -o W.csv",
	.about = "Binds a mesh to a skeleton (ASF or BVH) and writes its skin weights as CSV rows\n"
		 "vertex,bone,weight (at most 4 per vertex; -o - writes to stdout). The weights are computed\n"
		 "(the paper's rule, volume-balanced by default for the generated body), read from a CSV, or\n"
		 "a rigged mesh's own (glTF, FBX, COLLADA, or an OBJ with its MakeHuman rig, coloured by its\n"
		 "mtllib's Kd and map_Kd). Every choice\n"
		 "made for the mesh is said on stderr. Before anything is written the bind is checked on a\n"
		 "range of motion built from the skeleton (and on each --motion clip): torn skin, parts\n"
		 "leaving their bones, parts left to the root or rigid are refused (exit 1) naming the part,\n"
		 "the figure and the fix; --force writes the weights anyway.",
	.opts = { tool_opt_skeleton, tool_opt_mesh, tool_opt_output, bind_cmd_opts, bind_opts },
	.take = bind_take,
	.positional = tool_files_skel_mesh,
	.examples = (const cli_example[]){
		{ "The paper's weights on an OBJ, every choice said on stderr",
		  "skintool bind 02.asf base.obj -o w.csv" },
		{ "A rigged glTF body with the artist's weights",
		  "skintool bind 02.asf male_base_mesh.glb --weights=mesh -o w.csv" },
		{ "A MakeHuman export with its own rig",
		  "skintool bind 02.asf base.obj --rig=default.mhskel --weights=mesh -o w.csv" },
		{ NULL, NULL },
	},
};

int cmd_bind(int argc, char **argv)
{
	static bind_cmd b;
	TOOL_STATE(bound_body, body);
	tool_common_init(&b.c, bind_command.prog);
	b.want_report = 0;
	b.motion_count = 0;
	int rc = cli_parse(&bind_command, &b, argc, argv, 0);
	if (rc != 0)
		return rc < 0;
	if (!b.c.asf || !b.c.mesh || !b.c.out)
		return tool_missing(&b.c, "SKELETON, MESH and -o W.csv");
	b.c.bind.gate_motion = b.motion;
	b.c.bind.gate_motion_count = b.motion_count;
	b.c.bind.gate_report = b.want_report;
	if (rig_bind_load(&b.c.bind, b.c.asf, b.c.mesh, body) < 0)
		return 1;
	if (tool_write_weights(b.c.out, &body->skel, &body->weights) < 0)
		return 1;
	if (b.want_report)
		report(stderr, &b.c.bind, body);
	return 0;
}
