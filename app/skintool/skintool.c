/* skintool: the host tool (parse, pose, bind, skin, pack, measure). */
#include <stdio.h>
#include <string.h>

#include "cli_opts.h"
#include "cli_quiet.h"
#include "cli_version.h"
#include "skintool_cmds.h"

typedef struct command {
	const char *name;
	int (*run)(int argc, char **argv);
	const char *what;
} command;

static const command commands[] = {
	{ "fk", cmd_fk, "joint positions and rotations per frame, as CSV" },
	{ "convert", cmd_convert, "ASF/AMC to BVH and back" },
	{ "bind", cmd_bind, "skin weights of a mesh on a skeleton, as CSV" },
	{ "mannequin", cmd_mannequin, "a closed body mesh around a skeleton's rest pose" },
	{ "skin", cmd_skin, "the mesh deformed for one frame, as OBJ" },
	{ "metrics", cmd_metrics, "volume and radius ratios per frame, as CSV" },
	{ "compare", cmd_compare, "the LBS vs DQBS report: a page, CSV, charts, renders" },
	{ "pack", cmd_pack, "a flash image of the bound body and clips for skinplay --image" },
	{ "view", cmd_view, "a mesh or rig and a motion played at once (bound, packed, skinplay)" },
	{ "info", cmd_info, "an image's header and clips; checks every block" },
	{ "repair", cmd_repair, "rebuilds an image's bad blocks from its parity" },
	{ "bench", cmd_bench, "skinning speed against the memory-bandwidth bound" },
	{ "bench-parse", cmd_bench_parse, "motion parse throughput against the first file" },
	{ "bench-image", cmd_bench_image, "an image's time to the first frame, bytes per frame" },
};

static void usage(FILE *to)
{
	fprintf(to, "Usage: skintool [-q] COMMAND [OPTION]... [FILE]...\n"
		"The host tool of skinplay: reads motion (ASF/AMC, BVH) and bodies (OBJ; rigged glTF, FBX,\n"
		"COLLADA), binds, skins, measures, compares and packs images for the device.\n\nCommands:\n");
	for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
		fprintf(to, "  %-13s %s\n", commands[i].name, commands[i].what);
	fprintf(to, "\n'skintool COMMAND --help' describes a command and its options (the man page skintool-COMMAND\n"
		"holds the same). Options take their value as --opt=value or --opt value; files and options come\n"
		"in any order. The options below go before the command or after it.\n\n"
		"Options:\n"
		"  -h, --help       show this help and exit\n"
		"  -q, --quiet      only errors and warnings on stderr: no notes, progress or summary lines\n"
		"      --version    show the version, revision, board and backends, and exit\n\n");
	cli_help_exit("a damaged image (info), blocks beyond repair (repair)", to);
}

static int is_quiet(const char *arg)
{
	return !strcmp(arg, "-q") || !strcmp(arg, "--quiet");
}

int main(int argc, char **argv)
{
	/* -q before the command: as after it (cli_parse), for every command */
	while (argc > 1 && is_quiet(argv[1])) {
		cli_set_quiet(1);
		argv[1] = argv[0];
		argc--;
		argv++;
	}
	if (cli_wants_version(argc, argv))
		return cli_print_version("skintool"), 0;
	if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
		usage(argc < 2 ? stderr : stdout);
		return argc < 2 ? 1 : 0;
	}
	for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
		if (strcmp(argv[1], commands[i].name) == 0)
			return commands[i].run(argc - 2, argv + 2);
	fprintf(stderr, "skintool: unknown command '%s'\nTry 'skintool --help' for the commands.\n", argv[1]);
	return 1;
}
