/* skintool fk SKELETON.asf MOTION.amc [--frame N]: joint positions as CSV. */
#include <stdio.h>
#include <string.h>

#include "fk.h"
#include "skintool_cmds.h"
#include "cli_common.h"
#include "cli_opts.h"

static void print_pose(const skel *s, long frame, const skel_pose *p)
{
	for (int b = 0; b < s->count; b++) {
		quat q = p->rot[b];
		if (q.w < 0.0f)
			q = (quat){ -q.w, -q.x, -q.y, -q.z };
		printf("%ld,%s,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g,%.7g\n", frame, s->bone[b].name,
		       p->tip[b].x, p->tip[b].y, p->tip[b].z, q.w, q.x, q.y, q.z);
	}
}

typedef struct fk_args {
	const char *asf, *amc;
	long only;
} fk_args;

enum { OPT_SKELETON = 1, OPT_MOTION, OPT_FRAME };

static const cli_opt fk_opts[] = {
	{ "skeleton", 0, "S.asf", OPT_SKELETON, "the skeleton (or the first file named)" },
	{ "motion", 0, "M.amc", OPT_MOTION, "the motion (or the second file; a BVH alone is both)" },
	{ "frame", 0, "N", OPT_FRAME, "only the frame numbered N in the file (default: every frame)" },
	{ NULL, 0, NULL, 0, NULL },
};

static int fk_take(void *ctx, int id, const char *v)
{
	fk_args *a = ctx;
	if (id == OPT_SKELETON)
		a->asf = v;
	else if (id == OPT_MOTION)
		a->amc = v;
	else if (cli_parse_long("--frame", v, &a->only) < 0)
		return -1;
	else if (a->only < 0)
		return fprintf(stderr, "skintool fk: --frame expects a frame number (0 or more), got %ld\n", a->only), -1;
	return 0;
}

static int fk_file(void *ctx, const char *arg)
{
	fk_args *a = ctx;
	const char **slots[] = { &a->asf, &a->amc };
	return cli_take_positional("skintool fk", slots, 2, arg);
}

static const cli_command fk_command = {
	.prog = "skintool fk",
	.usage = "SKELETON.asf MOTION.amc [--frame=N]\n  or:  skintool fk MOTION.bvh [--frame=N]",
	.about = "Forward kinematics: prints CSV, a header then one row per bone per frame: frame,bone,x,y,z\n"
		 "(the bone's tip in world space, the skeleton's length unit) and qw,qx,qy,qz (its global\n"
		 "rotation, qw >= 0). The root comes first, then the bones in file order.",
	.opts = { fk_opts },
	.take = fk_take,
	.positional = fk_file,
};

int cmd_fk(int argc, char **argv)
{
	static skel s;
	static cli_motion m;
	static amc_frame f;
	static skel_pose pose;
	fk_args args = { NULL, NULL, -1 };
	int rc = cli_parse(&fk_command, &args, argc, argv, 0);
	if (rc != 0)
		return rc < 0;
	const char *asf = args.asf, *amc = args.amc;
	long only = args.only;
	cli_bvh_slots(&asf, &amc, NULL);
	if (!asf || !amc)
		return -cli_missing(fk_command.prog, "SKELETON.asf MOTION.amc, or MOTION.bvh");
	if (cli_load_skel(asf, &s) < 0 || cli_motion_open(&m, amc, &s) < 0)
		return 1;
	printf("frame,bone,x,y,z,qw,qx,qy,qz\n");
	int r, found = 0;
	long first = -1, last = -1;
	while ((r = cli_motion_next(&m, &f)) > 0) {
		if (first < 0)
			first = f.number;
		last = f.number;
		if (only >= 0 && f.number != only)
			continue;
		fk_pose(&s, f.value, &pose);
		print_pose(&s, f.number, &pose);
		found = 1;
		if (only >= 0)
			break;
	}
	cli_motion_close(&m);
	if (r < 0)
		return 1;
	if (only >= 0 && !found) {
		fprintf(stderr, "%s: no frame %ld (the file has frames %ld..%ld)\n", amc, only, first, last);
		return 1;
	}
	return 0;
}
