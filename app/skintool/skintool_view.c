/* skintool view MESH MOTION... [PACK OPTIONS] [-- SKINPLAY OPTIONS]: a rig
 * and a motion played in one command. The host tool binds them as `pack`
 * does (its importer reads glTF, FBX, COLLADA and MakeHuman; skinplay
 * links no importer), packs a temporary image, plays it with skinplay (the
 * one beside this program, else the PATH's) and removes the image. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_opts.h"
#include "cli_version.h"
#include "skintool_cmds.h"

#define VIEW_MAX_ARGS 64

static const cli_command view_command = {
	.prog = "skintool view",
	.usage = "MESH MOTION.bvh [PACK OPTION]... [-- SKINPLAY OPTION]...\n"
		 "  or:  skintool view MESH SKELETON.asf MOTION.amc... [PACK OPTION]... [-- SKINPLAY OPTION]...",
	.about = "Plays a rigged or plain mesh (glTF, GLB, FBX, COLLADA, a MakeHuman OBJ with --rig, an OBJ) with a\n"
		 "motion in one command: binds and packs them as 'skintool pack ... --mesh MESH' does, into a\n"
		 "temporary image, plays it with skinplay (the one beside skintool, else on the PATH) and removes\n"
		 "the image. The options before '--' are pack's (the bind options: --weights, --joint-map, --rig,\n"
		 "...: 'skintool pack --help'); those after it skinplay's ('skinplay --help'). The exit status is\n"
		 "skinplay's, or pack's when the bind is refused.",
	.exit2 = "skinplay's: headless, no clip of the show could play",
	.examples = (const cli_example[]){
		{ "A rigged glTF body walking, in a window",
		  "skintool view male.glb 02_01.bvh" },
		{ "The artist's weights, headless, LBS beside DQBS, every 30th frame into out/",
		  "skintool view male.glb 02.asf 02_01.amc --weights mesh -- --platform surfaceless --algo compare "
		  "--every 30 -o out" },
		{ NULL, NULL },
	},
};

/* skinplay beside this program (/proc/self/exe's folder), else "skinplay"
 * for the PATH. */
static const char *skinplay_path(char *buf, size_t cap)
{
	ssize_t n = readlink("/proc/self/exe", buf, cap - 16);
	if (n > 0) {
		buf[n] = '\0';
		char *slash = strrchr(buf, '/');
		if (slash) {
			strcpy(slash + 1, "skinplay");
			if (access(buf, X_OK) == 0)
				return buf;
		}
	}
	return "skinplay";
}

static int play(const char *image, char **play_args, int n)
{
	char path[PATH_MAX];
	char *argv[VIEW_MAX_ARGS + 4];
	int k = 0;
	argv[k++] = "skinplay";
	argv[k++] = "--image";
	argv[k++] = (char *)image;
	for (int i = 0; i < n; i++)
		argv[k++] = play_args[i];
	argv[k] = NULL;
	const char *prog = skinplay_path(path, sizeof path);
	fflush(NULL);
	pid_t pid = fork();
	if (pid < 0)
		return fprintf(stderr, "skintool view: fork: %s\n", strerror(errno)), 1;
	if (pid == 0) {
		execvp(prog, argv);
		fprintf(stderr, "skintool view: cannot run %s: %s (install skinplay beside skintool or on the PATH)\n",
			prog, strerror(errno));
		_exit(127);
	}
	int status;
	while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
		;
	return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

int cmd_view(int argc, char **argv)
{
	for (int i = 0; i < argc && strcmp(argv[i], "--"); i++) {
		if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))
			return cli_help(&view_command, stdout), 0;
		if (!strcmp(argv[i], "--version"))
			return cli_print_version("skintool"), 0;
	}
	int split = 0;
	while (split < argc && strcmp(argv[split], "--"))
		split++;
	if (split < 2 || argv[0][0] == '-')
		return fprintf(stderr, "skintool view: give the mesh, then the motion (MOTION.bvh, or SKELETON.asf "
			       "MOTION.amc)\nTry 'skintool view --help'.\n"), 1;
	if (split + 5 > VIEW_MAX_ARGS || argc - split > VIEW_MAX_ARGS)
		return fprintf(stderr, "skintool view: more than %d arguments\n", VIEW_MAX_ARGS), 1;
	char image[] = "/tmp/skintool-view-XXXXXX";
	int fd = mkstemp(image);
	if (fd < 0)
		return fprintf(stderr, "skintool view: a temporary image in /tmp: %s\n", strerror(errno)), 1;
	close(fd);
	/* pack MOTION... --mesh MESH [its options] -o IMAGE */
	char *pack[VIEW_MAX_ARGS + 8];
	int k = 0;
	for (int i = 1; i < split; i++)
		pack[k++] = argv[i];
	pack[k++] = "--mesh";
	pack[k++] = argv[0];
	pack[k++] = "-o";
	pack[k++] = image;
	pack[k] = NULL;
	int rc = cmd_pack(k, pack);
	if (rc == 0)
		rc = play(image, argv + split + (split < argc), argc - split - (split < argc));
	unlink(image);
	return rc;
}
