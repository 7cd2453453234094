/* skintool mannequin SKELETON.asf -o body.obj [--detail N]: a closed body
 * mesh generated around the skeleton's rest pose. */
#include <stdio.h>
#include <string.h>

#include "cli_common.h"
#include "cli_mesh_io.h"
#include "mannequin.h"
#include "skintool_cmds.h"

static const char usage_text[] = "usage: skintool mannequin SKELETON.asf -o BODY.obj [--detail N]\n";

typedef struct manq_args {
	const char *asf, *out;
	long detail;
} manq_args;

static int parse_args(int argc, char **argv, manq_args *a)
{
	a->asf = a->out = NULL;
	a->detail = MANQ_DEFAULT_DETAIL;
	for (int i = 0; i < argc; i++) {
		if (strcmp(argv[i], "--detail") == 0) {
			if (cli_parse_long("--detail", i + 1 < argc ? argv[++i] : NULL, &a->detail) < 0)
				return -1;
		} else if (strcmp(argv[i], "-o") == 0) {
			if (i + 1 >= argc) {
				fprintf(stderr, "skintool mannequin: -o needs a file name\n");
				return -1;
			}
			a->out = argv[++i];
		} else if (argv[i][0] == '-' && argv[i][1]) {
			fprintf(stderr, "skintool mannequin: unknown option '%s'\n", argv[i]);
			return -1;
		} else if (!a->asf) {
			a->asf = argv[i];
		} else {
			fprintf(stderr, "skintool mannequin: unexpected argument '%s'\n", argv[i]);
			return -1;
		}
	}
	if (!a->asf || !a->out) {
		fputs(usage_text, stderr);
		return -1;
	}
	if (a->detail < MANQ_MIN_DETAIL || a->detail > MANQ_MAX_DETAIL) {
		fprintf(stderr, "skintool mannequin: --detail must be %d..%d, got %ld\n",
			MANQ_MIN_DETAIL, MANQ_MAX_DETAIL, a->detail);
		return -1;
	}
	return 0;
}

int cmd_mannequin(int argc, char **argv)
{
	static skel s;
	static manq_work work;
	static mesh body;
	manq_args a;
	skp_error err;

	if (parse_args(argc, argv, &a) < 0 || cli_load_skel(a.asf, &s) < 0)
		return 1;
	if (manq_build(&s, (int)a.detail, &work, &body, &err) != SKP_OK) {
		cli_error(a.asf, &err);
		return 1;
	}
	if (mesh_write_obj(a.out, &body, TOOL_GENERATED_BODY) < 0)
		return 1;
	printf("%s: %d vertices, %d triangles", a.out, body.vert_count, body.tri_count);
	if (work.arms_raised)
		printf(", around the rest pose with %d hanging arm%s raised sideways (the pose it binds in)",
		       work.arms_raised, work.arms_raised == 1 ? "" : "s");
	printf("\n");
	return 0;
}
