#include "cli_bind_args.h"

#include <stdio.h>
#include <string.h>

#include "cli_bind_gate.h"
#include "cli_common.h"
#include "cli_mesh_format.h"
#include "cli_mesh_io.h"
#include "cli_mesh_pick.h"
#include "cli_mesh_place.h"
#include "cli_progress.h"
#include "cli_scratch.h"
#include "cli_weights.h"
#include "clock.h"
#include "mannequin.h"
#include "text_tokens.h"

void bind_args_init(bind_args *a)
{
	memset(a, 0, sizeof *a);
	a->pose_frame = -1;
	a->balance = -1;
}

enum { OPT_GROUP = BIND_OPT_FIRST, OPT_FIT, OPT_NO_FIT, OPT_BIND_POSE, OPT_WEIGHTS, OPT_JOINT_MAP, OPT_RIG, OPT_BALANCE,
       OPT_FORCE };

const cli_opt bind_opts[] = {
	{ "group", 0, "NAME", OPT_GROUP, "bind only the OBJ group/object or glTF mesh NAME (default: the body)" },
	{ "fit", 0, NULL, OPT_FIT, "always scale and move the mesh onto the skeleton" },
	{ "no-fit", 0, NULL, OPT_NO_FIT, "keep the mesh's size and place (default: fit when they differ)" },
	{ "bind-pose", 0, "P.amc[:F]|rest", OPT_BIND_POSE, "bind in frame F of P (its first without :F) or the rest pose (default: the mesh's own pose)" },
	{ "weights", 0, "W.csv|mesh", OPT_WEIGHTS, "read the weights, or keep a rigged mesh's own (default: computed)" },
	{ "joint-map", 0, "FILE", OPT_JOINT_MAP, "a rigged mesh's joints onto skeleton bones (JOINT = BONE lines)" },
	{ "rig", 0, "FILE.mhskel", OPT_RIG, "the OBJ's MakeHuman skeleton, with the weights file it names" },
	{ "balance", 0, "on|off", OPT_BALANCE, "volume-balance computed weights (default: on for the generated body)" },
	{ "force", 0, NULL, OPT_FORCE, "bind even when the quality check fails (torn skin, parts off their bones)" },
	{ NULL, 0, NULL, 0, NULL },
};

/* P.amc:F -> path P.amc, frame F. A colon not followed by digits only is
 * part of the path. */
static int split_pose(bind_args *a, const char *spec)
{
	size_t n = strlen(spec);
	if (n == 0 || n >= sizeof a->pose_buf) {
		fprintf(stderr, "%s: --bind-pose: bad file name '%s'\n", cli_program(), spec);
		return -1;
	}
	memcpy(a->pose_buf, spec, n + 1);
	a->rest_pose = strcmp(spec, "rest") == 0;
	a->pose_path = a->rest_pose ? NULL : a->pose_buf;
	a->pose_frame = -1;
	char *colon = strrchr(a->pose_buf, ':');
	if (!colon || colon == a->pose_buf || !colon[1])
		return 0;
	for (const char *c = colon + 1; *c; c++)
		if (*c < '0' || *c > '9')
			return 0;
	*colon = '\0';
	return cli_parse_long("--bind-pose", colon + 1, &a->pose_frame);
}

int bind_args_take(bind_args *a, const char *prog, int id, const char *value)
{
	static const char *const onoff[] = { "off", "on" };
	int k;
	switch (id) {
	case OPT_GROUP: a->group = value; return 0;
	case OPT_FIT: a->fit = 1; a->no_fit = 0; return 0;
	case OPT_NO_FIT: a->no_fit = 1; a->fit = 0; return 0;
	case OPT_BIND_POSE: return split_pose(a, value);
	case OPT_WEIGHTS:
		a->weights_mesh = strcmp(value, "mesh") == 0;
		a->weights_path = a->weights_mesh ? NULL : value;
		return 0;
	case OPT_JOINT_MAP: a->joint_map = value; return 0;
	case OPT_RIG: a->rig = value; return 0;
	case OPT_FORCE: a->force = 1; return 0;
	case OPT_BALANCE:
		if ((k = cli_choice(prog, "balance", value, onoff, 2)) < 0)
			return -1;
		a->balance = k;
		return 0;
	}
	return -1;
}

/* Poses body->skel in the requested frame, or the rest pose. */
static int load_pose(const bind_args *a, bound_body *body)
{
	static amc_frame f;

	body->pose_frame = -1;
	body->arms_raised = 0;
	memset(&body->guess, 0, sizeof body->guess);
	memset(body->pose_value, 0, sizeof body->pose_value);
	if (!a->pose_path) {
		fk_pose(&body->skel, NULL, &body->pose);
		return 0;
	}
	if (cli_read_frame(a->pose_path, &body->skel, a->pose_frame, &f) < 0)
		return -1;
	memcpy(body->pose_value, f.value, sizeof body->pose_value);
	fk_pose(&body->skel, f.value, &body->pose);
	body->pose_frame = f.number;
	return 0;
}

static bind_mesh_importer mesh_importer;

void bind_args_set_importer(bind_mesh_importer importer)
{
	mesh_importer = importer;
}

int bind_args_is_interchange(const char *path)
{
	return cli_mesh_is_interchange(path);
}

static void balance_step(void *ctx, int done, int total)
{
	cli_progress *p = ctx;
	p->total = total;
	cli_progress_step(p, done);
}

/* Balancing a large mesh takes seconds: progress on a terminal. */
static skp_status balance_watched(bound_body *body, bind_balance_work *work, skp_error *err)
{
	static cli_progress pr;
	const mesh *m = &body->mesh;
	bind_progress watch = { balance_step, &pr };
	cli_progress_start(&pr, "balance", "joints", body->skel.count - 1);
	skp_status rc = bind_balance_watched(&body->skel, &body->pose, m->pos, m->vert_count,
					     (const uint32_t (*)[3])m->tri, m->tri_count, &body->weights, work,
					     &body->balance, &watch, err);
	cli_progress_clear(&pr);
	return rc;
}

/* generated: the body is the generated one, where balancing is measured */
int bind_args_auto_weights(const bind_args *a, int generated, const char *obj, bound_body *body)
{
	bind_balance_work *work = &cli_scratch_area()->balance;
	skp_error err;
	const mesh *m = &body->mesh;
	uint64_t t0 = clock_now_ns();
	bind_prepare(&body->rig, &body->skel, &body->pose, NULL);
	skp_status rc = bind_weights(&body->rig, m->pos, m->vert_count, &body->weights, &body->info, &err);
	body->balanced = rc == SKP_OK && (a->balance < 0 ? generated : a->balance);
	if (body->balanced)
		rc = balance_watched(body, work, &err);
	body->bind_ns = clock_now_ns() - t0;
	if (rc != SKP_OK) {
		fprintf(stderr, "%s: bind: %s\n", obj, err.msg);
		return -1;
	}
	body->automatic = 1;
	return 0;
}

/* No mesh given: the generated body around the rest pose with the arms
 * out, which is then also the bind pose. */
static int generate_body(const bind_args *a, const char *asf, bound_body *body)
{
	manq_work *work = &cli_scratch_area()->manq;
	skp_error err;
	if (a->pose_path || a->fit || a->group || a->weights_path || a->weights_mesh || a->joint_map || a->rig) {
		fprintf(stderr, "%s: --bind-pose, --fit, --group, --weights, --joint-map and --rig need a mesh\n", asf);
		return -1;
	}
	if (manq_build(&body->skel, 0, work, &body->mesh, &err) != SKP_OK) {
		fprintf(stderr, "%s: generated body: %s\n", asf, err.msg);
		return -1;
	}
	memcpy(body->pose_value, work->pose_value, sizeof body->pose_value);
	body->pose = work->rest;
	body->arms_raised = work->arms_raised;
	return 0;
}

const float *bound_pose_values(const bound_body *body)
{
	if (body->pose_frame >= 0)
		return body->pose_value;
	/* a derived pose (arms raised, the mesh's own) differs from the rest's zeros */
	for (int i = 0; i < body->skel.dof_count; i++)
		if (body->pose_value[i] != 0.0f)
			return body->pose_value;
	return NULL;
}

static int load_body(const bind_args *a, const char *asf, const char *obj, bound_body *body)
{
	body->fitted = 0;
	body->automatic = 0;
	body->rigged = 0;
	body->has_orphans = 0;
	if (cli_load_skel(asf, &body->skel) < 0 || load_pose(a, body) < 0)
		return -1;
	if (!obj)
		return generate_body(a, asf, body) < 0 ? -1 : bind_args_auto_weights(a, 1, asf, body);
	if (bind_args_is_interchange(obj) || a->rig) {
		if (mesh_importer)
			return mesh_importer(a, obj, body);
		fprintf(stderr, "%s: this program reads OBJ meshes and packed images: pack the rigged mesh into an "
			"image first (skintool pack SKELETON MOTION --mesh %s%s%s -o SHOW.skn), then play that\n", obj,
			obj, a->rig ? " --rig " : "", a->rig ? a->rig : "");
		return -1;
	}
	if (a->weights_mesh || a->joint_map) {
		fprintf(stderr, "%s: an OBJ has no joints or weights of its own: --weights mesh and --joint-map need "
			"a rigged mesh (glTF 2.0, FBX, COLLADA) or the OBJ's MakeHuman rig (--rig FILE.mhskel)\n", obj);
		return -1;
	}
	if (cli_mesh_check_obj(obj) < 0 || cli_pick_mesh(obj, a->group, &body->mesh) < 0)
		return -1;
	if (body->mesh.vert_count == 0) {
		fprintf(stderr, "%s: no vertices%s%s\n", obj, a->group ? " in group " : "",
			a->group ? a->group : "");
		return -1;
	}
	if (cli_place_mesh(a, obj, body) < 0)
		return -1;
	return bind_args_weights(a, cli_obj_is_generated(obj), obj, body);
}

int bind_args_load(const bind_args *a, const char *asf, const char *obj, bound_body *body)
{
	if (obj && !strcmp(obj, BIND_MESH_GENERATED))
		obj = NULL;
	if (load_body(a, asf, obj, body) < 0)
		return -1;
	return cli_bind_gate(a, obj ? obj : asf, body);
}

int bind_args_weights(const bind_args *a, int generated, const char *name, bound_body *body)
{
	if (a->weights_path)
		return cli_load_weights(a->weights_path, &body->skel, body->mesh.vert_count, &body->weights);
	return bind_args_auto_weights(a, generated, name, body);
}
