#include "setup_bind.h"

#include <string.h>

#include "cli_progress.h"
#include "cli_say.h"
#include "clock.h"
#include "mannequin.h"
#include "motion_file.h"
#include "setup_gate.h"
#include "setup_mesh_format.h"
#include "setup_mesh_io.h"
#include "setup_mesh_pick.h"
#include "setup_mesh_place.h"
#include "setup_scratch.h"
#include "setup_weights.h"

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
	if (motion_read_frame(a->pose_path, &body->skel, a->pose_frame, &f) < 0)
		return -1;
	memcpy(body->pose_value, f.value, sizeof body->pose_value);
	fk_pose(&body->skel, f.value, &body->pose);
	body->pose_frame = f.number;
	return 0;
}

int setup_bind_is_interchange(const char *path)
{
	return setup_mesh_is_interchange(path);
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
int setup_bind_auto_weights(const bind_args *a, int generated, const char *obj, bound_body *body)
{
	bind_balance_work *work = &setup_scratch_area()->balance;
	skp_error err;
	const mesh *m = &body->mesh;
	uint64_t t0 = clock_now_ns();
	bind_prepare(&body->rig, &body->skel, &body->pose, NULL);
	skp_status rc = bind_weights(&body->rig, m->pos, m->vert_count, &body->weights, &body->info, &err);
	/* a user's mesh: the generated body is built round its bones, its
	 * weights smooth by construction (and balanced after) */
	body->smooth_passes = 0;
	if (rc == SKP_OK && !generated)
		body->smooth_passes = bind_smooth(&setup_scratch_area()->smooth, m, &body->weights);
	body->balanced = rc == SKP_OK && (a->balance < 0 ? generated : a->balance);
	if (body->balanced)
		rc = balance_watched(body, work, &err);
	body->bind_ns = clock_now_ns() - t0;
	if (rc != SKP_OK) {
		cli_warn("%s: bind: %s\n", obj, err.msg);
		return -1;
	}
	body->automatic = 1;
	return 0;
}

/* No mesh given: the generated body around the rest pose with the arms
 * out, which is then also the bind pose. */
static int generate_body(const bind_args *a, const char *asf, bound_body *body)
{
	manq_work *work = &setup_scratch_area()->manq;
	skp_error err;
	if (a->pose_path || a->fit || a->group || a->weights_path || a->weights_mesh || a->joint_map || a->rig) {
		cli_warn("%s: --bind-pose, --fit, --group, --weights, --joint-map and --rig need a mesh\n", asf);
		return -1;
	}
	if (manq_build(&body->skel, 0, work, &body->mesh, &err) != SKP_OK) {
		cli_warn("%s: generated body: %s\n", asf, err.msg);
		return -1;
	}
	memcpy(body->pose_value, work->pose_value, sizeof body->pose_value);
	body->pose = work->rest;
	body->arms_raised = work->arms_raised;
	return 0;
}


int setup_bind_begin(const bind_args *a, const char *asf, bound_body *body)
{
	body->fitted = 0;
	body->automatic = 0;
	body->rigged = 0;
	body->has_orphans = 0;
	body->has_held = 0;
	return motion_load_skel(asf, &body->skel) < 0 || load_pose(a, body) < 0 ? -1 : 0;
}

int setup_bind_rigged(const bind_args *a, const char *obj)
{
	return obj && strcmp(obj, BIND_MESH_GENERATED) && (setup_bind_is_interchange(obj) || a->rig);
}

static int load_body(const bind_args *a, const char *asf, const char *obj, bound_body *body)
{
	if (setup_bind_begin(a, asf, body) < 0)
		return -1;
	if (!obj)
		return generate_body(a, asf, body) < 0 ? -1 : setup_bind_auto_weights(a, 1, asf, body);
	if (setup_bind_rigged(a, obj)) {
		cli_warn("%s: this program reads OBJ meshes and packed images: pack the rigged mesh into an "
			"image first (skintool pack SKELETON MOTION --mesh %s%s%s -o SHOW.skn), then play that\n", obj,
			obj, a->rig ? " --rig " : "", a->rig ? a->rig : "");
		return -1;
	}
	if (a->weights_mesh || a->joint_map) {
		cli_warn("%s: an OBJ has no joints or weights of its own: --weights mesh and --joint-map need "
			"a rigged mesh (glTF 2.0, FBX, COLLADA) or the OBJ's MakeHuman rig (--rig FILE.mhskel)\n", obj);
		return -1;
	}
	if (setup_mesh_check_obj(obj) < 0 || setup_pick_mesh(obj, a->group, &body->mesh) < 0)
		return -1;
	if (body->mesh.vert_count == 0) {
		cli_warn("%s: no vertices%s%s\n", obj, a->group ? " in group " : "",
			a->group ? a->group : "");
		return -1;
	}
	if (setup_place_mesh(a, obj, body) < 0)
		return -1;
	return setup_bind_weights(a, setup_obj_is_generated(obj), obj, body);
}

int setup_bind_load(const bind_args *a, const char *asf, const char *obj, bound_body *body)
{
	if (obj && !strcmp(obj, BIND_MESH_GENERATED))
		obj = NULL;
	if (load_body(a, asf, obj, body) < 0)
		return -1;
	return setup_gate(a, obj ? obj : asf, body);
}

int setup_bind_weights(const bind_args *a, int generated, const char *name, bound_body *body)
{
	if (a->weights_path)
		return setup_load_weights(a->weights_path, &body->skel, body->mesh.vert_count, &body->weights);
	return setup_bind_auto_weights(a, generated, name, body);
}
