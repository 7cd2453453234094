#include "cli_bind_args.h"

#include <stdio.h>
#include <string.h>

#include "cli_args.h"
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
	{ "rig", 0, "FILE.mhskel", OPT_RIG, "the OBJ's MakeHuman skeleton, with the weights file it names (the OBJ's mtllib colours it)" },
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
