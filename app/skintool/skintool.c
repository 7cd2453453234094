/* skintool: the host tool (parse, pose, bind, skin, pack, measure). */
#include <stdio.h>
#include <string.h>

#include "cli_version.h"
#include "rig_load.h"
#include "skintool_cmds.h"

typedef struct command {
	const char *name;
	int (*run)(int argc, char **argv);
	const char *usage;
} command;

static const command commands[] = {
	{ "fk", cmd_fk, "fk SKELETON.asf MOTION.amc [--frame N] | fk MOTION.bvh [--frame N]    joint positions and rotations as CSV" },
	{ "convert", cmd_convert, "convert SKELETON.asf MOTION.amc -o OUT.bvh [--fps F] | convert IN.bvh -o OUT.asf    ASF/AMC to BVH and back (OUT.asf also writes OUT.amc)" },
	{ "bench", cmd_bench, "bench [--verts N] [--threads T]    skinning speed against the memory-bandwidth bound" },
	{ "bind", cmd_bind, "bind SKELETON.asf MESH.obj [--group G] [--fit|--no-fit] [--bind-pose P.amc[:F]|rest] [--weights IN.csv] [--balance on|off] [--report] -o W.csv    skin weights as CSV (report on stderr)" },
	{ "mannequin", cmd_mannequin, "mannequin SKELETON.asf -o BODY.obj [--detail N]    closed body mesh around the rest pose" },
	{ "skin", cmd_skin, "skin SKELETON.asf MOTION.amc MESH.obj --frame N --algo lbs|dqbs|dqbs-fixed [--group G] [--fit|--no-fit] [--bind-pose P.amc[:F]|rest] [--weights IN.csv] [--balance on|off] -o OUT.obj    the mesh deformed for frame N" },
	{ "pack", cmd_pack, "pack SKELETON.asf MOTION.amc [MOTION2.amc ...] [--mesh MESH.obj [bind options]] [--fps F] [--sequence N] [--block-size B] -o show.skn    flash image for skinplay --image" },
	{ "info", cmd_info, "info show.skn    header, sections and clips of an image; checks every block (exit 2 when damaged)" },
	{ "repair", cmd_repair, "repair show.skn    rebuilds an image's bad blocks from its parity and replaces it (exit 2 when beyond repair)" },
	{ "bench-parse", cmd_bench_parse, "bench-parse [SKELETON.asf] MOTION.amc|MOTION.bvh ... [--runs N]    motion parse throughput, MB/s against the first file" },
	{ "bench-image", cmd_bench_image, "bench-image show.skn [--amc M.amc]    time to the first frame, bytes per frame" },
	{ "metrics", cmd_metrics, "metrics SKELETON.asf MOTION.amc MESH.obj [bind options] [--algo LIST] | metrics --scene twist|bend --angle DEG [--algo LIST]    volume and radius ratios per frame as CSV" },
	{ "compare", cmd_compare, "compare SKELETON.asf MOTION.amc [--mesh MESH.obj [bind options]] -o DIR [--renders N]    LBS vs DQBS report: index.html, metrics.csv, charts, renders of the worst frames" },
};

static void usage(FILE *to)
{
	fprintf(to, "usage: skintool COMMAND [ARGS]\n\ncommands:\n");
	for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
		fprintf(to, "  %s\n", commands[i].usage);
}

int main(int argc, char **argv)
{
	if (cli_wants_version(argc, argv))
		return cli_print_version("skintool"), 0;
	if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
		usage(argc < 2 ? stderr : stdout);
		return argc < 2 ? 1 : 0;
	}
	bind_args_set_importer(rig_load_mesh);
	for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
		if (strcmp(argv[1], commands[i].name) == 0)
			return commands[i].run(argc - 2, argv + 2);
	fprintf(stderr, "skintool: unknown command '%s'\n", argv[1]);
	usage(stderr);
	return 1;
}
