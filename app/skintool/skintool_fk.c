/* skintool fk SKELETON.asf MOTION.amc [--frame N]: joint positions as CSV. */
#include <stdio.h>
#include <string.h>

#include "fk.h"
#include "skintool_cmds.h"
#include "cli_common.h"

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

int cmd_fk(int argc, char **argv)
{
	static skel s;
	static cli_motion m;
	static amc_frame f;
	static skel_pose pose;
	const char *asf = NULL, *amc = NULL;
	long only = -1;

	for (int i = 0; i < argc; i++) {
		if (strcmp(argv[i], "--frame") == 0) {
			if (cli_parse_long("--frame", i + 1 < argc ? argv[++i] : NULL, &only) < 0)
				return 1;
		} else if (argv[i][0] == '-' && argv[i][1]) {
			fprintf(stderr, "skintool fk: unknown option '%s'\n", argv[i]);
			return 1;
		} else if (!asf) {
			asf = argv[i];
		} else if (!amc) {
			amc = argv[i];
		} else {
			fprintf(stderr, "skintool fk: unexpected argument '%s'\n", argv[i]);
			return 1;
		}
	}
	cli_bvh_slots(&asf, &amc, NULL);
	if (!asf || !amc) {
		fprintf(stderr, "usage: skintool fk SKELETON.asf MOTION.amc [--frame N] | fk MOTION.bvh [--frame N]\n");
		return 1;
	}
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
