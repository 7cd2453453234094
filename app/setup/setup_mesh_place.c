#include "setup_mesh_place.h"

#include <math.h>
#include <string.h>

#include "bind_shape.h"
#include "runtime_body.h"
#include "setup_mesh_io.h"
#include "cli_say.h"
#include "setup_scratch.h"
#include "skel_roles.h"
#include "skel_tpose.h"

/* Sizes within 3% and places within 3% of the height are left alone. */
#define PLACE_TOLERANCE 0.03f

static int fit_mesh(const char *obj, bound_body *body)
{
	skp_error err;
	mesh *m = &body->mesh;
	if (bind_fit(m->pos, m->vert_count, &body->skel, &body->pose, &body->fit, &err) != SKP_OK) {
		cli_warn("%s: fit: %s\n", obj, err.msg);
		return -1;
	}
	body->fitted = 1;
	return 1;
}

static int auto_fit(const char *obj, bound_body *body)
{
	mesh *m = &body->mesh;
	skp_error err;
	const bind_fit_result *f = &body->fit;
	/* a flat skeleton or mesh has nothing to fit to: keep the mesh */
	if (bind_fit_measure(m->pos, m->vert_count, &body->skel, &body->pose, &body->fit, &err) != SKP_OK ||
	    (fabsf(f->scale - 1.0f) <= PLACE_TOLERANCE &&
	     vec3_length(f->offset) <= PLACE_TOLERANCE * f->skel_height))
		return 0;
	bind_fit_apply(m->pos, m->vert_count, f);
	body->fitted = 1;
	cli_say("%s: the mesh is %.4g units tall, the skeleton %.4g: fitted (scale %.4g, then moved by "
		"%.4g %.4g %.4g); --no-fit keeps it as it is\n", obj, (double)f->mesh_height,
		(double)f->skel_height, (double)f->scale, (double)f->offset.x, (double)f->offset.y,
		(double)f->offset.z);
	return 1;
}

static void say_guess(const char *obj, const bound_body *body, const bind_guess_result *g, float refit)
{
	int ends = 0;
	cli_say("%s: bound in the mesh's own pose:", obj);
	for (int i = 0, n = 0; i < g->arm_count; i++) {
		const bind_guess_arm *a = &g->arm[i];
		if (a->to_deg != a->from_deg)
			cli_say("%s '%s' from %.0f to %.0f degrees of elevation", n++ ? "," : "",
				body->skel.bone[a->bone].name, (double)a->from_deg, (double)a->to_deg);
		if (a->lower_turn_deg != 0.0f)
			cli_say("%s '%s' turned %.0f degrees", n++ ? "," : "",
				body->skel.bone[a->lower].name, (double)a->lower_turn_deg);
		ends += a->ends;
	}
	if (ends)
		cli_say("; %d turns of limbs, hands, thumbs, feet and toes to the mesh's cross-sections and "
			"ends", ends);
	if (refit != 1.0f)
		cli_say("; the mesh fitted again to that pose (scale %.4g more) and the guess carried on",
			(double)refit);
	cli_say(" (--bind-pose P.amc[:F] or --bind-pose rest chooses)\n");
}

static void set_pose(bound_body *body, const float *values)
{
	memcpy(body->pose_value, values, sizeof body->pose_value);
	fk_pose(&body->skel, body->pose_value, &body->pose);
}

int setup_skel_is_biped(const skel *s, const skel_pose *pose)
{
	static skel_roles r;
	if (s->count < 2)
		return 0;
	skel_find_roles(s, pose, &r);
	return skel_roles_biped(s, &r);
}

/* A mesh without a rig is judged by its shape (bind_shape.h): 0 when it
 * stands like a biped or --force binds it anyway, -1 after refusing. */
static int check_shape(const bind_args *a, const char *obj, const bound_body *body)
{
	bind_shape sh;
	if (!setup_skel_is_biped(&body->skel, &body->pose))
		return 0;   /* a test arm, a robot arm: any shape goes */
	bind_shape_measure(body->mesh.pos, body->mesh.vert_count, &sh);
	if (sh.biped || !(sh.height > 0.0f))
		return 0;
	float wide = fmaxf(sh.foot_x, sh.foot_z) / sh.height, narrow = fminf(sh.foot_x, sh.foot_z) / sh.height;
	if (wide > BIND_SHAPE_SPAN || narrow > BIND_SHAPE_FEET)
		cli_warn("%s: not a biped: what touches the ground spans %.0f%% by %.0f%% of its height (two "
			"feet %.0f%% by %.0f%% at most): a quadruped, a prop, or a figure lying down", obj,
			100.0 * (double)wide, 100.0 * (double)narrow, 100.0 * (double)BIND_SHAPE_SPAN,
			100.0 * (double)BIND_SHAPE_FEET);
	else
		cli_warn("%s: not a biped: it is %.0f%% as wide as it is tall (a body %.0f%% or more): a pole or "
			"a prop", obj, 100.0 * (double)(sh.width / sh.height), 100.0 * (double)BIND_SHAPE_WIDE);
	cli_warn("; skintool plays human motion on standing bipeds, Y up%s\n",
		a->force ? " (--force: bound anyway)" : " (--force binds it anyway)");
	return a->force ? 0 : -1;
}

/* The mesh was fitted to the skeleton as it stood before the guess; the
 * guessed pose stands otherwise (legs closer together stand taller), so
 * the mesh is fitted again to that pose and the guess carried on from
 * where it was, its turns said from where they started. Returns the
 * second fit's scale. */
static float refit_to_guess(bound_body *body, float *values, bind_guess_work *w)
{
	bind_fit_result f;
	skp_error err;
	set_pose(body, values);
	if (bind_fit_measure(body->mesh.pos, body->mesh.vert_count, &body->skel, &body->pose, &f, &err) != SKP_OK)
		return 1.0f;
	bind_fit_apply(body->mesh.pos, body->mesh.vert_count, &f);
	body->fit.scale *= f.scale;
	body->fit.offset = vec3_add(vec3_scale(body->fit.offset, f.scale), f.offset);
	body->fit.skel_height = f.skel_height;
	static bind_guess_result first;
	first = body->guess;
	bind_guess_pose(&body->skel, &body->mesh, values, w, &body->guess);
	for (int i = 0; i < body->guess.arm_count && i < first.arm_count; i++) {
		bind_guess_arm *a = &body->guess.arm[i];
		a->from_deg = first.arm[i].from_deg;
		a->lower_turn_deg = first.arm[i].lower_turn_deg;
		a->ends += first.arm[i].ends;
	}
	body->guess.turned = first.turned;
	return f.scale;
}

int setup_place_mesh(const bind_args *a, const char *obj, bound_body *body)
{
	int generated = setup_obj_is_generated(obj), fitted = 0;
	if (!generated && check_shape(a, obj, body) < 0)
		return -1;
	if (a->fit)
		fitted = fit_mesh(obj, body);
	else if (!a->no_fit && !generated)
		fitted = auto_fit(obj, body);
	if (fitted < 0)
		return -1;
	if (a->pose_path || a->rest_pose)
		return 0;
	static float values[SKP_MAX_DOF];
	bind_guess_work *w = &setup_scratch_area()->guess;
	if (generated) {
		body->arms_raised = skel_tpose(&body->skel, values, &w->pose);
		set_pose(body, values);
		return 0;
	}
	static float start[SKP_MAX_DOF];
	memcpy(start, body->pose_value, sizeof start);
	memcpy(values, start, sizeof values);
	bind_guess_pose(&body->skel, &body->mesh, values, w, &body->guess);
	if (body->guess.turned) {
		float refit = fitted ? refit_to_guess(body, values, w) : 1.0f;
		set_pose(body, values);
		say_guess(obj, body, &body->guess, refit);
	}
	return 0;
}
