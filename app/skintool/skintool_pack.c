/* skintool pack SKELETON.asf MOTION.amc [MOTION2.amc ...]
 *               [--mesh MESH.obj [--group G] [--fit|--no-fit] [--bind-pose P.amc[:F]|rest] [--weights W.csv] [--balance on|off]]
 *               [--fps F] [--sequence N] [--block-size B] -o show.skn
 * Binds the body (the generated one without --mesh) and packs it with the
 * clips into a flash image (app/image/image_format.h). Each clip is read twice
 * (its range, then its frames), so memory does not grow with its length.
 * The image is written to a temporary in OUT's directory (unnamed where the
 * file system allows), synced and renamed over OUT, and the directory
 * synced: a pack cut short, even by kill -9, leaves the previous OUT whole
 * and no temporary behind; two packs to one OUT each write whole. Parity:
 * --parity G (data blocks per group, 2 or more) or none; the default is
 * groups of 8 (image_format.h). Clips are compressed (app/encode: every
 * frame within --error of ACL's shell measure) unless --raw. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli_bind_args.h"
#include "cli_args.h"
#include "cli_error.h"
#include "cli_image_out.h"
#include "cli_progress.h"
#include "cli_quiet.h"
#include "motion_file.h"
#include "rig_load.h"
#include "setup_bind.h"
#include "show_source.h"
#include "tool_clip.h"
#include "image_write.h"
#include "pack_encode.h"
#include "random_bytes.h"
#include "skp_format.h"
#include "skintool_cmds.h"
#include "tool_args.h"
#include "tool_state.h"

#define PACK_MAX_AMC SKP_IMAGE_MAX_CLIPS

typedef struct pack_args {
	bind_args bind;
	const char *asf, *mesh, *out;
	const char *amc[PACK_MAX_AMC];
	int amc_count;
	double fps;
	long sequence;
	long block_size;
	int parity;               /* data blocks per parity group; 0 default, -1 none */
	int raw;                  /* --raw: 16-bit quantised clips, not compressed */
	pack_codec codec;
} pack_args;

static int parse_parity(pack_args *p, const char *v)
{
	long g;
	if (!strcmp(v, "none")) {
		p->parity = -1;
		return 0;
	}
	if (cli_parse_long("--parity", v, &g) < 0 || g < 2 || g > 65535) {
		fprintf(stderr, "skintool pack: --parity expects data blocks per parity group (2..65535) or none, got '%s'\n", v);
		return -1;
	}
	p->parity = (int)g;
	return 0;
}

enum { OPT_FPS = 1, OPT_SEQUENCE, OPT_BLOCK_SIZE, OPT_PARITY, OPT_RAW, OPT_ERROR, OPT_UNIT };

static const cli_opt pack_cmd_opts[] = {
	{ "fps", 0, "F", OPT_FPS, "the clips' capture rate in Hz (default: a BVH's own, else 120, the CMU rate)" },
	{ "sequence", 0, "N", OPT_SEQUENCE, "the image's sequence number: the newest valid slot plays (default: now)" },
	{ "block-size", 0, "B", OPT_BLOCK_SIZE, "the flash block size in bytes (default 4096)" },
	{ "parity", 0, "G|none", OPT_PARITY, "one parity block per G data blocks, or none (default 8)" },
	{ "error", 0, "CM", OPT_ERROR, "the worst error a compressed clip may have, in cm at points 3 cm from each joint "
				       "(ACL's measure; default 0.01)" },
	{ "unit", 0, "CM", OPT_UNIT, "cm a skeleton length unit, for --error (default 2.54 for an ASF with "
				     ":units length 0.45, as CMU's, else 1)" },
	{ "raw", 0, NULL, OPT_RAW, "store clips as 16-bit values a dof (128 bytes a CMU frame; fast to pack), "
				   "not compressed" },
	{ NULL, 0, NULL, 0, NULL },
};

static const cli_opt pack_motion_opt[] = {
	{ "motion", 0, "M.amc", TOOL_OPT_MOTION, "a clip, AMC or BVH (repeat for more; or the files after the skeleton)" },
	{ NULL, 0, NULL, 0, NULL },
};

static int add_clip(pack_args *p, const char *path)
{
	if (p->amc_count >= PACK_MAX_AMC) {
		fprintf(stderr, "skintool pack: more than %d clips (board limit SKP_IMAGE_MAX_CLIPS)\n", PACK_MAX_AMC);
		return -1;
	}
	p->amc[p->amc_count++] = path;
	return 0;
}

static int take_rate(pack_args *p, const char *v)
{
	char *end;
	p->fps = strtod(v, &end);
	if (*end || !(p->fps >= 1.0 && p->fps <= 10000.0))
		return fprintf(stderr, "skintool pack: --fps expects a rate from 1 to 10000 Hz, got '%s'\n", v), -1;
	return 0;
}

static int pack_take(void *ctx, int id, const char *v)
{
	pack_args *p = ctx;
	if (BIND_OPT_ID(id))
		return bind_args_take(&p->bind, "skintool pack", id, v);
	switch (id) {
	case TOOL_OPT_SKELETON: p->asf = v; return 0;
	case TOOL_OPT_MOTION: return add_clip(p, v);
	case TOOL_OPT_MESH: p->mesh = v; return 0;
	case TOOL_OPT_OUTPUT: p->out = v; return 0;
	case OPT_FPS: return take_rate(p, v);
	case OPT_SEQUENCE:
		if (cli_parse_long("--sequence", v, &p->sequence) < 0)
			return -1;
		if (p->sequence < 0 || p->sequence > 0xffffffffL)
			return fprintf(stderr, "skintool pack: --sequence expects 0 to 4294967295, got '%s'\n", v), -1;
		return 0;
	case OPT_BLOCK_SIZE: return cli_parse_long("--block-size", v, &p->block_size);
	case OPT_PARITY: return parse_parity(p, v);
	case OPT_RAW: p->raw = 1; return 0;
	case OPT_ERROR:
	case OPT_UNIT: {
		char *end;
		double x = strtod(v, &end);
		if (*end || !(x >= 1e-6 && x <= 1e6))
			return fprintf(stderr, "skintool pack: --%s expects centimetres (1e-6 to 1e6), got '%s'\n",
				       id == OPT_ERROR ? "error" : "unit", v), -1;
		*(id == OPT_ERROR ? &p->codec.error_cm : &p->codec.unit_cm) = x;
		return 0;
	}
	}
	return -1;
}

static int pack_file(void *ctx, const char *arg)
{
	pack_args *p = ctx;
	if (!p->asf) {
		p->asf = arg;
		return 0;
	}
	return add_clip(p, arg);
}

static const cli_command pack_command = {
	.prog = "skintool pack",
	.usage = "SKELETON MOTION [MOTION2]... [--mesh=MESH [OPTION]...] -o SHOW.skn\n"
		 "  or:  skintool pack MOTION.bvh [MOTION2.bvh]... [OPTION]... -o SHOW.skn",
	.about = "Binds the body (the generated one without --mesh) and packs it with the clips into a flash\n"
		 "image for skinplay --image: CRC-checked blocks with parity, written under a temporary name,\n"
		 "synced and renamed, so a pack cut short leaves the previous image whole.",
	.opts = { tool_opt_skeleton, pack_motion_opt, tool_opt_mesh, tool_opt_output, pack_cmd_opts, bind_opts },
	.take = pack_take,
	.positional = pack_file,
	.examples = (const cli_example[]){
		{ "Two clips on the generated body",
		  "skintool pack 02.asf 02_01.amc 02_02.amc -o show.skn" },
		{ "A rigged body with its own weights",
		  "skintool pack 02.asf 02_01.amc --mesh=male_base_mesh.glb --weights=mesh -o show.skn" },
		{ NULL, NULL },
	},
};

/* The default sequence, the unix time, from a clock that can be right: a
 * board without a real-time clock boots in 1970 (its pack would lose to
 * every older show), and past 2106 the time does not fit. Refused, saying
 * so, else: --sequence says what the clock cannot. */
static int sequence_from_clock(pack_args *p)
{
	time_t now = time(NULL);
	if (now >= (time_t)SKP_IMAGE_SEQUENCE_CLOCK_FLOOR && now <= (time_t)0xffffffffL) {
		p->sequence = (long)now;
		return 0;
	}
	char when[32] = "an unknown time";
	struct tm tm;
	if (gmtime_r(&now, &tm))
		strftime(when, sizeof when, "%Y-%m-%d", &tm);
	fprintf(stderr, "skintool pack: the clock says %s: no sequence number to trust (an image packed now would "
		"lose to older shows, or beat every later one); set the clock, or give --sequence N (1 to 4294967295; "
		"of two valid images the larger plays)\n", when);
	return -1;
}

static int pack_parse(pack_args *p, int argc, char **argv)
{
	bind_args_init(&p->bind);
	p->fps = 0.0;   /* not given: the BVH's rate, else 120 */
	p->sequence = -1; /* not given: the clock's */
	p->block_size = SKP_IMAGE_DEFAULT_BLOCK;
	p->codec.error_cm = 0.01;
	int rc = cli_parse(&pack_command, p, argc, argv, 0);
	if (rc != 0)
		return rc;
	/* MOTION.bvh [MOTION2.bvh ...]: the first file is the skeleton too */
	if (p->asf && bvh_is_path(p->asf) && p->amc_count < PACK_MAX_AMC) {
		memmove(p->amc + 1, p->amc, sizeof p->amc[0] * (size_t)p->amc_count);
		p->amc[0] = p->asf;
		p->amc_count++;
	}
	if (!p->asf || !p->amc_count || !p->out) {
		return cli_missing(pack_command.prog, "SKELETON MOTION... and -o SHOW.skn");
	}
	return p->sequence < 0 ? sequence_from_clock(p) : 0;
}

/* The clip's name: the AMC's file name without directory and extension,
 * control characters as \xNN (it is printed and shown on screen). */
static void clip_name(const char *path, char *out, size_t cap)
{
	const char *base = strrchr(path, '/');
	skp_escape_name(out, cap, base ? base + 1 : path);
	char *dot = strrchr(out, '.');
	if (dot && dot != out)
		*dot = '\0';
}

/* Pass 1 over a clip; *rate: the BVH's own frame rate (1 / Frame Time), or
 * 0 for an AMC, which carries none. */
static int clip_range(const char *path, const skel *s, skp_clip_range *range, double *rate)
{
	static motion_file m;
	static amc_frame f;
	skp_error err;
	int r;
	skp_clip_range_init(range, s);
	if (motion_file_open(&m, path, s) < 0)
		return -1;
	*rate = m.is_bvh ? 1.0 / m.layout.frame_time : 0.0;
	while ((r = motion_file_next(&m, &f)) > 0) {
		if (skp_clip_range_add(range, &f, &err) != SKP_OK) {
			cli_error(path, &err);
			r = -1;
			break;
		}
	}
	motion_file_close(&m);
	if (r == 0 && range->frames == 0) {
		fprintf(stderr, "%s: no frames\n", path);
		return -1;
	}
	return r;
}

/* Pass 1's checks (numbering, finite values) on a clip held whole. */
static int check_clip(const char *path, const skel *s, const tool_clip *c)
{
	static skp_clip_range range;
	static amc_frame f;
	skp_error err;
	skp_clip_range_init(&range, s);
	for (long i = 0; i < c->n; i++) {
		f.number = c->first_number + i;
		f.line = 0;
		memcpy(f.value, c->frames + (size_t)i * (size_t)c->dofs, sizeof(float) * (size_t)c->dofs);
		if (skp_clip_range_add(&range, &f, &err) != SKP_OK) {
			cli_error(path, &err);
			return -1;
		}
	}
	return 0;
}

static int pack_coded(skp_image_writer *w, const char *path, double fps, const pack_codec *o)
{
	static tool_clip c;
	char name[SKP_MAX_NAME + 16];
	if (tool_clip_load(path, w->s, &c) < 0)
		return -1;
	clip_name(path, name, sizeof name);
	if (fps <= 0)
		fps = c.rate > 0 ? c.rate : 120.0;
	int r = check_clip(path, w->s, &c);
	if (r == 0)
		r = pack_encode_clip(w, path, name, fps, &c, o);
	tool_clip_free(&c);
	return r;
}

static int pack_clip(skp_image_writer *w, const char *path, double fps)
{
	static skp_clip_range range;
	static motion_file m;
	static amc_frame f;
	char name[SKP_MAX_NAME + 16];
	skp_error err;
	int r;
	double rate;
	if (clip_range(path, w->s, &range, &rate) < 0)
		return -1;
	clip_name(path, name, sizeof name);
	/* --fps wins; else a BVH's own rate; else 120 Hz, the CMU rate */
	if (fps <= 0)
		fps = rate > 0 ? rate : 120.0;
	if (skp_image_clip_begin(w, name, (float)fps, &range, &err) != SKP_OK) {
		cli_error(path, &err);
		return -1;
	}
	if (motion_file_open(&m, path, w->s) < 0)
		return -1;
	static cli_progress pr;
	static char what[SKP_MAX_NAME + 32];
	snprintf(what, sizeof what, "pack %s", name);
	cli_progress_start(&pr, what, "frames", range.frames);
	long n = 0;
	while ((r = motion_file_next(&m, &f)) > 0) {
		if (skp_image_clip_frame(w, &f, &err) != SKP_OK) {
			cli_error(path, &err);
			r = -1;
			break;
		}
		cli_progress_step(&pr, ++n);
	}
	cli_progress_clear(&pr);
	motion_file_close(&m);
	if (r == 0)
		fprintf(cli_summary(), "clip %s: %ld frames, max error %.3g rad (%.3g deg), %.3g length units\n", name,
		       range.frames, (double)w->dir[w->clip_count - 1].max_rot_err,
		       (double)w->dir[w->clip_count - 1].max_rot_err * 57.29577951308232,
		       (double)w->dir[w->clip_count - 1].max_trans_err);
	return r;
}

static void refuse_written(const char *out, const char *what, const skp_error *err)
{
	fprintf(stderr, "%s: not written: skinplay would refuse %s: ", out, what);
	if (err->block >= 0)
		fprintf(stderr, "block %ld: ", err->block);
	fprintf(stderr, "%s\n", err->msg);
}

/* What skinplay would refuse is not written: the image as written, opened
 * and judged by the very acceptance skinplay runs (show_accept.c). */
static int accept_written(const skp_blockdev *dev, const char *out)
{
	static skp_image im;
	TOOL_STATE(bound_body, body);
	skp_error err;
	if (skp_image_open(&im, dev, &err) != SKP_OK || image_accept_body(&im, body, &err) < 0) {
		refuse_written(out, "it", &err);
		return -1;
	}
	for (int c = 0; c < im.clip_count; c++)
		if (image_accept_clip(&im, &body->skel, c, &err) < 0) {
			char what[SKP_MAX_NAME + 8];
			snprintf(what, sizeof what, "clip %s", im.clip[c].name);
			refuse_written(out, what, &err);
			return -1;
		}
	return 0;
}

static int write_image(const pack_args *p, const bound_body *body, storage_file *sf)
{
	static skp_image_writer w;
	uint8_t id[SKP_IMAGE_ID_BYTES];
	skp_error err;
	int e = random_bytes(id, sizeof id);
	if (e < 0) {
		fprintf(stderr, "%s: cannot choose the image id: %s\n", p->out, strerror(-e));
		return -1;
	}
	skp_status rc = skp_image_write_begin(&w, &sf->bd, (uint64_t)p->sequence, id, &body->skel, &err);
	w.parity_group = p->parity;
	w.texture = body->mesh.textured ? &body->texture : NULL;
	if (rc != SKP_OK ||
	    skp_image_write_bind(&w, &body->mesh, &body->weights, bound_pose_values(body),
				 body->pose_frame, &err) != SKP_OK) {
		cli_error(p->out, &err);
		return -1;
	}
	for (int i = 0; i < p->amc_count; i++)
		if ((p->raw ? pack_clip(&w, p->amc[i], p->fps) : pack_coded(&w, p->amc[i], p->fps, &p->codec)) < 0)
			return -1;
	if (skp_image_write_end(&w, &err) != SKP_OK) {
		cli_error(p->out, &err);
		return -1;
	}
	if (accept_written(&sf->bd, p->out) < 0)
		return -1;
	fprintf(cli_summary(), "%s: %lu blocks of %lu bytes (%lu bytes), sequence %ld, %d bones, %d vertices, %d triangles\n",
	       p->out, (unsigned long)w.hdr.block_count, (unsigned long)w.hdr.block_size,
	       (unsigned long)w.hdr.block_count * w.hdr.block_size, p->sequence, body->skel.count,
	       body->mesh.vert_count, body->mesh.tri_count);
	return 0;
}

int cmd_pack(int argc, char **argv)
{
	static pack_args p;
	TOOL_STATE(bound_body, body);
	static cli_image_out out;
	memset(&p, 0, sizeof p);
	int rc = pack_parse(&p, argc, argv);
	if (rc != 0)
		return rc < 0;
	p.bind.gate_motion = p.amc;
	p.bind.gate_motion_count = p.amc_count;
	if (rig_bind_load(&p.bind, p.asf, p.mesh, body) < 0)
		return 1;
	rig_load_texture(p.mesh, body);
	if (cli_image_out_open(&out, p.out, (uint32_t)p.block_size) < 0)
		return 1;
	if (write_image(&p, body, &out.sf) < 0) {
		cli_image_out_abort(&out);
		return 1;
	}
	return cli_image_out_commit(&out) < 0 ? 1 : 0;
}
