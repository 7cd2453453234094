/* skintool convert SKELETON.asf MOTION.amc -o OUT.bvh [--fps F]
 * skintool convert IN.bvh -o OUT.asf          (writes OUT.asf and OUT.amc)
 * The output's format follows its name (.bvh, or .asf with its .amc);
 * either input converts to either output. Outputs are replaced whole. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli_args.h"
#include "cli_text_out.h"
#include "cli_opts.h"
#include "cli_quiet.h"
#include "convert.h"
#include "motion_file.h"
#include "skintool_cmds.h"
#include "text_tokens.h"

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

enum { OPT_SKELETON = 1, OPT_MOTION, OPT_OUTPUT, OPT_FPS };

static const cli_opt convert_opts[] = {
	{ "skeleton", 0, "S.asf", OPT_SKELETON, "the skeleton (or the first file named)" },
	{ "motion", 0, "M.amc", OPT_MOTION, "the motion (or the second file; a BVH alone is both)" },
	{ "output", 'o', "OUT", OPT_OUTPUT, "OUT.bvh, or OUT.asf (which also writes OUT.amc)" },
	{ "fps", 0, "F", OPT_FPS, "the BVH's frame rate in Hz (default: a BVH input's own, else 120)" },
	{ NULL, 0, NULL, 0, NULL },
};

typedef struct convert_parse {
	convert_args *a;
	const char *next;
} convert_parse;

static int convert_take(void *ctx, int id, const char *v)
{
	convert_args *a = ((convert_parse *)ctx)->a;
	char *end;
	switch (id) {
	case OPT_SKELETON: a->skel_path = v; return 0;
	case OPT_MOTION: a->motion_path = v; return 0;
	case OPT_OUTPUT: a->out = v; return 0;
	}
	a->fps = strtod(v, &end);
	if (*end || !(a->fps >= 1e-3 && a->fps <= 1e6)) {
		fprintf(stderr, "skintool convert: --fps expects a rate in Hz, got '%s'\n", v);
		return -1;
	}
	return 0;
}

static int convert_file(void *ctx, const char *arg)
{
	convert_parse *c = ctx;
	const char **slots[] = { &c->a->skel_path, &c->a->motion_path, &c->next };
	return cli_take_positional("skintool convert", slots, 3, arg);
}

static const cli_command convert_command = {
	.prog = "skintool convert",
	.usage = "SKELETON.asf MOTION.amc -o OUT.bvh|OUT.asf [--fps=F]\n"
		 "  or:  skintool convert IN.bvh -o OUT.asf|OUT.bvh [--fps=F]",
	.about = "Converts motion between ASF/AMC and BVH, the format following the output's name (.asf also\n"
		 "writes its .amc). Forward kinematics on the result equals that on the source within 1e-6 of\n"
		 "the body's height. Outputs are written under a temporary name and renamed.",
	.opts = { convert_opts },
	.take = convert_take,
	.positional = convert_file,
	.examples = (const cli_example[]){
		{ "A CMU clip as BVH, its Frame Time from the CMU rate",
		  "skintool convert 02.asf 02_01.amc -o 02_01.bvh" },
		{ "A BVH as ASF and AMC (writes walk.asf and walk.amc)",
		  "skintool convert 131_01.bvh -o walk.asf" },
		{ NULL, NULL },
	},
};

static int parse(convert_args *a, int argc, char **argv)
{
	convert_parse c = { a, NULL };
	int rc = cli_parse(&convert_command, &c, argc, argv, 0);
	if (rc != 0)
		return rc;
	motion_bvh_slots(&a->skel_path, &a->motion_path, &c.next);
	if (!a->skel_path || !a->motion_path || !a->out || c.next) {
		return cli_missing(convert_command.prog, "SKELETON.asf MOTION.amc or IN.bvh, and -o OUT");
	}
	if (!ends_with(a->out, ".bvh") && !ends_with(a->out, ".asf")) {
		fprintf(stderr, "skintool convert: -o: expected a name ending in .bvh or .asf, got '%s'\n", a->out);
		return -1;
	}
	return 0;
}

static int to_bvh(const convert_args *a, const skel *s)
{
	static motion_file m;
	static cli_text_out out;
	long frames = motion_file_count(a->motion_path, s);
	if (frames < 0 || motion_file_open(&m, a->motion_path, s) < 0)
		return -1;
	double fps = a->fps > 0 ? a->fps : m.is_bvh && m.layout.frame_time > 0 ? 1.0 / m.layout.frame_time
									: AMC_DEFAULT_FPS;
	if (cli_text_out_open(&out, a->out) < 0) {
		motion_file_close(&m);
		return -1;
	}
	int rc = convert_write_bvh(out.f, s, &m, frames, 1.0 / fps);
	motion_file_close(&m);
	if (rc < 0) {
		cli_text_out_abort(&out);
		return -1;
	}
	if (cli_text_out_commit(&out) < 0)
		return -1;
	fprintf(cli_summary(), "%s: %d joints, %ld frames at %.6g Hz%s\n", a->out, s->count, frames, fps,
	       !m.is_bvh && a->fps <= 0 ? " (AMC records no rate: --fps sets it)" : "");
	return 0;
}

static int to_asf(convert_args *a, const skel *s)
{
	static motion_file m;
	static cli_text_out asf, amc;
	size_t n = strlen(a->out);
	if (n >= sizeof a->amc_out) {
		fprintf(stderr, "%s: name too long\n", a->out);
		return -1;
	}
	memcpy(a->amc_out, a->out, n - 4);
	memcpy(a->amc_out + n - 4, ".amc", 5);
	if (motion_file_open(&m, a->motion_path, s) < 0)
		return -1;
	asf.f = NULL;
	if (cli_text_out_open(&asf, a->out) < 0 || cli_text_out_open(&amc, a->amc_out) < 0) {
		if (asf.f)
			cli_text_out_abort(&asf);
		motion_file_close(&m);
		return -1;
	}
	convert_write_asf(asf.f, s);
	long frames = convert_write_amc(amc.f, s, &m);
	motion_file_close(&m);
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
	fprintf(cli_summary(), "%s: %d bones; %s: %ld frames%s\n", a->out, s->count, a->amc_out, frames,
	       m.is_bvh ? " (AMC records no frame rate)" : "");
	return 0;
}

int cmd_convert(int argc, char **argv)
{
	static convert_args a;
	static skel s;
	memset(&a, 0, sizeof a);
	int rc = parse(&a, argc, argv);
	if (rc != 0)
		return rc < 0;
	if (motion_load_skel(a.skel_path, &s) < 0)
		return 1;
	int bone;
	const char *why = ends_with(a.out, ".bvh") ? convert_unsupported(&s, &bone) : NULL;
	if (why) {
		fprintf(stderr, "%s: bone '%s' %s\n", a.skel_path, s.bone[bone].name, why);
		return 1;
	}
	return (ends_with(a.out, ".bvh") ? to_bvh(&a, &s) : to_asf(&a, &s)) < 0;
}
