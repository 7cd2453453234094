/* skintool bind SKELETON.asf MESH.obj [--group G] [--fit|--no-fit] [--bind-pose P.amc[:F]|rest]
 *               [--weights IN.csv] [--balance on|off] [--report] -o weights.csv
 * Binds the mesh to the skeleton (automatic weights, bind.h, balanced by
 * bind_balance.h with --balance on (the default for the generated body), or the given CSV after validation) and writes the weights CSV (-o - for stdout). The
 * report always goes to stderr, so it never mixes with a CSV on stdout. */
#include <stdio.h>
#include <string.h>

#include "cli_bind_args.h"
#include "cli_weights.h"
#include "skintool_cmds.h"

#define BIND_USAGE "usage: skintool bind SKELETON.asf MESH.obj " BIND_ARGS_USAGE \
	" [--report] -o weights.csv\n"

static void report_pose(FILE *to, const bind_args *a, const bound_body *b)
{
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
	if (b->fitted)
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
	} else {
		fprintf(to, "weights: read from %s\n", a->weights_path);
	}
	fprintf(to, "largest influence count: %d\n", st.max_influences);
	fprintf(to, "smoothness (mean weight difference across %ld triangle edges): %.6g\n",
		st.edge_count, st.edge_diff_mean);
	fprintf(to, "bone,vertices\n");
	for (int i = 0; i < s->count; i++)
		fprintf(to, "%s,%d\n", s->bone[i].name, st.bone_verts[i]);
}

int cmd_bind(int argc, char **argv)
{
	static bind_args a;
	static bound_body body;
	const char *asf = NULL, *obj = NULL, *out = NULL;
	int want_report = 0;

	bind_args_init(&a);
	for (int i = 0; i < argc; i++) {
		int r = bind_args_parse(&a, argc, argv, &i);
		if (r < 0)
			return 1;
		if (r > 0)
			continue;
		if (strcmp(argv[i], "--report") == 0) {
			want_report = 1;
		} else if (strcmp(argv[i], "-o") == 0) {
			if (i + 1 >= argc) {
				fprintf(stderr, "skintool bind: -o needs a file name\n");
				return 1;
			}
			out = argv[++i];
		} else if (argv[i][0] == '-' && argv[i][1]) {
			fprintf(stderr, "skintool bind: unknown option '%s'\n", argv[i]);
			return 1;
		} else if (!asf) {
			asf = argv[i];
		} else if (!obj) {
			obj = argv[i];
		} else {
			fprintf(stderr, "skintool bind: unexpected argument '%s'\n", argv[i]);
			return 1;
		}
	}
	if (!asf || !obj || !out) {
		fprintf(stderr, BIND_USAGE);
		return 1;
	}
	if (bind_args_load(&a, asf, obj, &body) < 0)
		return 1;
	if (cli_write_weights(out, &body.skel, &body.weights) < 0)
		return 1;
	if (want_report)
		report(stderr, &a, &body);
	return 0;
}
