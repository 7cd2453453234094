#include "cli_bind_args.h"

#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cli_mesh_io.h"
#include "cli_weights.h"
#include "clock.h"
#include "text_tokens.h"

void bind_args_init(bind_args *a)
{
	memset(a, 0, sizeof *a);
	a->pose_frame = -1;
}

/* P.amc:F -> path P.amc, frame F. A colon not followed by digits only is
 * part of the path. */
static int split_pose(bind_args *a, const char *spec)
{
	size_t n = strlen(spec);
	if (n == 0 || n >= sizeof a->pose_buf) {
		fprintf(stderr, "skintool: --bind-pose: bad file name '%s'\n", spec);
		return -1;
	}
	memcpy(a->pose_buf, spec, n + 1);
	a->pose_path = a->pose_buf;
	a->pose_frame = -1;
	char *colon = strrchr(a->pose_buf, ':');
	if (!colon || colon == a->pose_buf || !colon[1])
		return 0;
	for (const char *c = colon + 1; *c; c++)
		if (*c < '0' || *c > '9')
			return 0;
	*colon = '\0';
	return tool_parse_long("--bind-pose", colon + 1, &a->pose_frame);
}

static const char *value_of(const char *opt, int argc, char **argv, int *i)
{
	if (*i + 1 >= argc) {
		fprintf(stderr, "skintool: %s needs a value\n", opt);
		return NULL;
	}
	return argv[++*i];
}

int bind_args_parse(bind_args *a, int argc, char **argv, int *i)
{
	const char *opt = argv[*i], *val;
	if (strcmp(opt, "--fit") == 0) {
		a->fit = 1;
		return 1;
	}
	if (strcmp(opt, "--group") == 0) {
		if (!(val = value_of(opt, argc, argv, i)))
			return -1;
		a->group = val;
		return 1;
	}
	if (strcmp(opt, "--weights") == 0) {
		if (!(val = value_of(opt, argc, argv, i)))
			return -1;
		a->weights_path = val;
		return 1;
	}
	if (strcmp(opt, "--bind-pose") == 0) {
		if (!(val = value_of(opt, argc, argv, i)))
			return -1;
		return split_pose(a, val) < 0 ? -1 : 1;
	}
	return 0;
}

/* Poses body->skel in the requested frame, or the rest pose. */
static int load_pose(const bind_args *a, bound_body *body)
{
	static tool_motion m;
	static amc_frame f;

	body->pose_frame = -1;
	if (!a->pose_path) {
		fk_pose(&body->skel, NULL, &body->pose);
		return 0;
	}
	if (tool_motion_open(&m, a->pose_path, &body->skel) < 0)
		return -1;
	int r, found = 0;
	long first = -1, last = -1;
	while ((r = tool_motion_next(&m, &f)) > 0) {
		if (first < 0)
			first = f.number;
		last = f.number;
		if (a->pose_frame < 0 || f.number == a->pose_frame) {
			found = 1;
			break;
		}
	}
	tool_motion_close(&m);
	if (r < 0)
		return -1;
	if (!found) {
		if (first < 0)
			fprintf(stderr, "%s: no frames\n", a->pose_path);
		else
			fprintf(stderr, "%s: no frame %ld (the file has frames %ld..%ld)\n",
				a->pose_path, a->pose_frame, first, last);
		return -1;
	}
	fk_pose(&body->skel, f.value, &body->pose);
	body->pose_frame = f.number;
	return 0;
}

static int fit_mesh(const char *obj, bound_body *body)
{
	skp_error err;
	mesh *m = &body->mesh;
	if (bind_fit(m->pos, m->vert_count, &body->skel, &body->pose, &body->fit, &err) != SKP_OK) {
		fprintf(stderr, "%s: --fit: %s\n", obj, err.msg);
		return -1;
	}
	body->fitted = 1;
	return 0;
}

static int auto_weights(const char *obj, bound_body *body)
{
	skp_error err;
	uint64_t t0 = clock_now_ns();
	bind_prepare(&body->rig, &body->skel, &body->pose, NULL);
	skp_status rc = bind_weights(&body->rig, body->mesh.pos, body->mesh.vert_count,
				     &body->weights, &body->info, &err);
	body->bind_ns = clock_now_ns() - t0;
	if (rc != SKP_OK) {
		fprintf(stderr, "%s: bind: %s\n", obj, err.msg);
		return -1;
	}
	body->automatic = 1;
	return 0;
}

int bind_args_load(const bind_args *a, const char *asf, const char *obj, bound_body *body)
{
	body->fitted = 0;
	body->automatic = 0;
	if (tool_load_skel(asf, &body->skel) < 0 || load_pose(a, body) < 0)
		return -1;
	if (!tool_load_obj(obj, a->group, &body->mesh))
		return -1;
	if (body->mesh.vert_count == 0) {
		fprintf(stderr, "%s: no vertices%s%s\n", obj, a->group ? " in group " : "",
			a->group ? a->group : "");
		return -1;
	}
	if (a->fit && fit_mesh(obj, body) < 0)
		return -1;
	if (a->weights_path)
		return tool_load_weights(a->weights_path, &body->skel, body->mesh.vert_count,
					 &body->weights);
	return auto_weights(obj, body);
}
