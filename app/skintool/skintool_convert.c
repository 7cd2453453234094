/* skintool convert SKELETON.asf MOTION.amc -o OUT.bvh [--fps F]
 * skintool convert IN.bvh -o OUT.asf          (writes OUT.asf and OUT.amc)
 * The output's format follows its name (.bvh, or .asf with its .amc);
 * either input converts to either output. Outputs are replaced whole. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_text_out.h"
#include "convert.h"
#include "skintool_cmds.h"
#include "text_tokens.h"

#define CONVERT_USAGE "usage: skintool convert SKELETON.asf MOTION.amc -o OUT.bvh|OUT.asf [--fps F]\n" \
	"       skintool convert IN.bvh -o OUT.asf|OUT.bvh [--fps F]\n"
#define AMC_DEFAULT_FPS 120.0   /* the CMU database's rate; AMC does not record one */

typedef struct convert_args {
	const char *skel_path, *motion_path, *out;
	double fps;                 /* 0: the BVH's own, or AMC_DEFAULT_FPS */
	char amc_out[4096];
} convert_args;

static int ends_with(const char *path, const char *ext)
{
	size_t n = strlen(path), k = strlen(ext);
	return n > k && tok_ieq(path + n - k, ext);
}

static int parse(convert_args *a, int argc, char **argv)
{
	const char *next = NULL;
	const char **slots[] = { &a->skel_path, &a->motion_path, &next };
	for (int i = 0; i < argc; i++) {
		const char *v;
		if (!strcmp(argv[i], "-o") || !strcmp(argv[i], "--fps")) {
			if (!(v = cli_option_value("skintool convert", argv[i], argc, argv, &i)))
				return -1;
			if (argv[i - 1][1] == 'o') {
				a->out = v;
			} else if (!((a->fps = atof(v)) >= 1e-3 && a->fps <= 1e6)) {
				fprintf(stderr, "skintool convert: --fps expects a rate in Hz, got '%s'\n", v);
				return -1;
			}
		} else if (argv[i][0] == '-' && argv[i][1]) {
			fprintf(stderr, "skintool convert: unknown option '%s'\n%s", argv[i], CONVERT_USAGE);
			return -1;
		} else if (cli_take_positional("skintool convert", slots, 3, argv[i]) < 0) {
			return -1;
		}
	}
	cli_bvh_slots(&a->skel_path, &a->motion_path, &next);
	if (!a->skel_path || !a->motion_path || !a->out || next) {
		fprintf(stderr, "%s", CONVERT_USAGE);
		return -1;
	}
	if (!ends_with(a->out, ".bvh") && !ends_with(a->out, ".asf")) {
		fprintf(stderr, "skintool convert: -o: expected a name ending in .bvh or .asf, got '%s'\n", a->out);
		return -1;
	}
	return 0;
}

static int to_bvh(const convert_args *a, const skel *s)
{
	static cli_motion m;
	static cli_text_out out;
	long frames = cli_motion_count(a->motion_path, s);
	if (frames < 0 || cli_motion_open(&m, a->motion_path, s) < 0)
		return -1;
	double fps = a->fps > 0 ? a->fps : m.is_bvh && m.layout.frame_time > 0 ? 1.0 / m.layout.frame_time
									: AMC_DEFAULT_FPS;
	if (cli_text_out_open(&out, a->out) < 0) {
		cli_motion_close(&m);
		return -1;
	}
	int rc = convert_write_bvh(out.f, s, &m, frames, 1.0 / fps);
	cli_motion_close(&m);
	if (rc < 0) {
		cli_text_out_abort(&out);
		return -1;
	}
	if (cli_text_out_commit(&out) < 0)
		return -1;
	printf("%s: %d joints, %ld frames at %.6g Hz%s\n", a->out, s->count, frames, fps,
	       !m.is_bvh && a->fps <= 0 ? " (AMC records no rate: --fps sets it)" : "");
	return 0;
}

static int to_asf(convert_args *a, const skel *s)
{
	static cli_motion m;
	static cli_text_out asf, amc;
	size_t n = strlen(a->out);
	if (n >= sizeof a->amc_out) {
		fprintf(stderr, "%s: name too long\n", a->out);
		return -1;
	}
	memcpy(a->amc_out, a->out, n - 4);
	memcpy(a->amc_out + n - 4, ".amc", 5);
	if (cli_motion_open(&m, a->motion_path, s) < 0)
		return -1;
	asf.f = NULL;
	if (cli_text_out_open(&asf, a->out) < 0 || cli_text_out_open(&amc, a->amc_out) < 0) {
		if (asf.f)
			cli_text_out_abort(&asf);
		cli_motion_close(&m);
		return -1;
	}
	convert_write_asf(asf.f, s);
	long frames = convert_write_amc(amc.f, s, &m);
	cli_motion_close(&m);
	if (frames < 0) {
		cli_text_out_abort(&amc);
		cli_text_out_abort(&asf);
		return -1;
	}
	if (cli_text_out_commit(&amc) < 0) {
		cli_text_out_abort(&asf);
		return -1;
	}
	if (cli_text_out_commit(&asf) < 0)
		return -1;
	printf("%s: %d bones; %s: %ld frames%s\n", a->out, s->count, a->amc_out, frames,
	       m.is_bvh ? " (AMC records no frame rate)" : "");
	return 0;
}

int cmd_convert(int argc, char **argv)
{
	static convert_args a;
	static skel s;
	memset(&a, 0, sizeof a);
	if (parse(&a, argc, argv) < 0 || cli_load_skel(a.skel_path, &s) < 0)
		return 1;
	int bone;
	const char *why = ends_with(a.out, ".bvh") ? convert_unsupported(&s, &bone) : NULL;
	if (why) {
		fprintf(stderr, "%s: bone '%s' %s\n", a.skel_path, s.bone[bone].name, why);
		return 1;
	}
	return (ends_with(a.out, ".bvh") ? to_bvh(&a, &s) : to_asf(&a, &s)) < 0;
}
