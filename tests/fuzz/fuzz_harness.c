/* Harnesses for the text parsers. The state lives in static storage as in
 * the front ends; the input is streamed through an skp_mem_reader, so the
 * fixed line buffer and its chunk boundaries are exercised as with a file. */
#define _POSIX_C_SOURCE 200809L /* fmemopen: the .mtl reader takes a stream */
#include "fuzz_harness.h"

#include <stdio.h>
#include <string.h>

#include "amc.h"
#include "asf.h"
#include "board_config.h"
#include "bvh.h"
#include "codec_decode.h"
#include "crc32.h"
#include "fk.h"
#include "image_accept.h"
#include "image_stream.h"
#include "image_read.h"
#include "image_survey.h"
#include "ini.h"
#include "mesh_format.h"
#include "obj.h"
#include "rig_makehuman.h"
#include "rig_map_file.h"
#include "rig_mtl.h"
#include "skel_tpose.h"
#include "skp_reader.h"
#include "text_lines.h"

static skel sk;
static text_lines tl;
static skp_error err;

int fuzz_asf(const uint8_t *data, size_t size)
{
	static skel_pose pose;
	skp_mem_source src;
	text_lines_init(&tl, skp_mem_reader(&src, data, size));
	if (asf_parse(&sk, &tl, &err) == SKP_OK)
		fk_pose(&sk, NULL, &pose); /* a skeleton that parses must pose */
	return 0;
}

/* The AMC is read against a fixed skeleton (the tests' three-bone arm with
 * a root, a 3-dof and a 2-dof bone) so the fuzzer explores the motion
 * syntax rather than skeletons. */
static const char amc_skeleton[] =
	":version 1.10\n:name tiny\n:units\n  mass 1.0\n  length 1.0\n  angle deg\n"
	":root\n  order TX TY TZ RX RY RZ\n  axis XYZ\n  position 0 0 0\n  orientation 0 0 0\n"
	":bonedata\n  begin\n    id 1\n    name upper\n    direction 1 0 0\n    length 2\n"
	"    axis 0 0 0 XYZ\n    dof rx ry rz\n  end\n  begin\n    id 2\n    name lower\n"
	"    direction 1 0 0\n    length 1.5\n    axis 0 0 90 XYZ\n    dof rx rz l\n  end\n"
	":hierarchy\n  begin\n    root upper\n    upper lower\n  end\n";

int fuzz_amc(const uint8_t *data, size_t size)
{
	static int ready;
	static amc_stream as;
	static amc_frame frame;
	static skel_pose pose;
	skp_mem_source src;
	if (!ready) {
		text_lines_init(&tl, skp_mem_reader(&src, amc_skeleton, sizeof amc_skeleton - 1));
		if (asf_parse(&sk, &tl, &err) != SKP_OK)
			return 0;
		ready = 1;
	}
	text_lines_init(&tl, skp_mem_reader(&src, data, size));
	amc_open(&as, &sk, &tl);
	while (amc_next(&as, &frame, &err) == 1)
		fk_pose(&sk, frame.value, &pose);
	return 0;
}

/* The hierarchy, every frame through FK, and the arms-out bind pose the
 * generated body would use on that skeleton. */
int fuzz_bvh(const uint8_t *data, size_t size)
{
	static skel bs;
	static bvh_layout lay;
	static bvh_stream st;
	static amc_frame frame;
	static skel_pose pose;
	static float tpose[SKP_MAX_DOF];
	skp_mem_source src;
	text_lines_init(&tl, skp_mem_reader(&src, data, size));
	if (bvh_parse(&bs, &lay, &tl, &err) != SKP_OK)
		return 0;
	skel_tpose(&bs, tpose, &pose);
	bvh_open(&st, &bs, &lay, &tl);
	while (bvh_next(&st, &frame, &err) == 1)
		fk_pose(&bs, frame.value, &pose);
	return 0;
}

int fuzz_obj(const uint8_t *data, size_t size)
{
	static mesh m;
	static obj_work work;
	skp_mem_source src;
	/* Small limits: the fuzzer reaches the limit checks with short inputs. */
	obj_options opt = { NULL, 64, 128 };
	text_lines_init(&tl, skp_mem_reader(&src, data, size));
	obj_parse(&m, &work, &tl, &opt, &err);
	/* and once with a group filter, which keeps a different vertex set */
	obj_options grp = { "body", 64, 128 };
	text_lines_init(&tl, skp_mem_reader(&src, data, size));
	obj_parse(&m, &work, &tl, &grp, &err);
	return 0;
}

int fuzz_ini(const uint8_t *data, size_t size)
{
	static ini_reader r;
	skp_mem_source src;
	ini_entry e;
	ini_init(&r, skp_mem_reader(&src, data, size));
	while (ini_next(&r, &e, &err) == 1)
		;
	return 0;
}

int fuzz_board_config(const uint8_t *data, size_t size)
{
	static board_config c;
	skp_mem_source src;
	board_config_defaults(&c);
	board_config_read(&c, skp_mem_reader(&src, data, size), &err);
	return 0;
}

/* The image reader behind its CRCs: every block's CRC-32 and the header's
 * are recomputed over the input first, or the fuzzer would spend its time
 * on CRC mismatches (tests/unit/test_image.c tests those). Then what
 * skinplay does with an image: open, skeleton, body, every clip's frames. */
#define FUZZ_IMAGE_MAX (64 * 1024)

static void image_fix_crcs(uint8_t *d, size_t size, uint32_t bs)
{
	if (size >= SKP_IMAGE_BLOCK_HDR + SKP_IMAGE_HEADER_SIZE) {
		uint8_t *h = d + SKP_IMAGE_BLOCK_HDR;
		le_put32(h + SKP_IMAGE_HEADER_SIZE - 4, crc32_compute(h, SKP_IMAGE_HEADER_SIZE - 4));
	}
	for (size_t at = 0; at + bs <= size; at += bs)
		le_put32(d + at + bs - 4, crc32_compute(d + at, bs - 4));
}

int fuzz_image(const uint8_t *data, size_t size)
{
	static uint8_t buf[FUZZ_IMAGE_MAX];
	static skp_image im;
	static skp_clip_stream stream;
	static mesh m;
	static skin_weights w;
	static float bind_values[SKP_MAX_DOF];
	static amc_frame frame;
	static skel_pose pose;
	static skp_block_report report;
	static uint8_t block[SKP_IMAGE_BLOCK_SIZE];
	if (size > sizeof buf)
		size = sizeof buf;
	memcpy(buf, data, size);
	image_fix_crcs(buf, size, SKP_IMAGE_MIN_BLOCK);
	uint32_t bs = skp_image_block_size_hint(buf, (uint32_t)size);
	if (bs == 0)
		bs = SKP_IMAGE_MIN_BLOCK;
	image_fix_crcs(buf, size, bs);
	skp_mem_blockdev mb;
	skp_blockdev dev = skp_mem_blockdev_ro(&mb, buf, size, bs);
	if (skp_image_open(&im, &dev, &err) != SKP_OK || skp_image_load_skel(&im, &sk, &err) != SKP_OK)
		return 0;
	skp_accept_skel(&sk, &err);
	long bind_number;
	if (skp_image_load_bind(&im, &sk, &m, &w, bind_values, &bind_number, &err) == SKP_OK) {
		fk_pose(&sk, bind_values, &pose);
		skp_accept_body(&sk, &pose, &m, &err);
	}
	for (int c = 0; c < im.clip_count; c++) {
		if (skp_clip_stream_open(&stream, &im, c, &err) != SKP_OK)
			continue;
		static float qmin[SKP_MAX_DOF], qstep[SKP_MAX_DOF];
		if (skp_image_load_quant(&im, c, qmin, qstep, &err) == SKP_OK)
			skp_accept_clip(&sk, &im.clip[c], qmin, qstep, &err);
		skp_image_check_frames(&im, c, &err);
		for (int i = 0; i < 4096 && skp_clip_stream_next(&stream, &frame, &err) > 0; i++)
			;
		skp_clip_stream_seek(&stream, 1);
		skp_clip_stream_next(&stream, &frame, &err);
		skp_clip_stream_seek(&stream, im.clip[c].frame_count / 2); /* a compressed clip: mid-segment */
		skp_clip_stream_next(&stream, &frame, &err);
	}
	for (uint32_t b = 0; b < im.hdr.block_count && b < 64; b++)
		skp_image_survey(&im, b, &report, block);
	return 0;
}

/* the joint map parser of the host tool's importer (app/import) */
int fuzz_joint_map(const uint8_t *data, size_t size)
{
	static rig_map_file map;
	if (rig_map_file_parse((const char *)data, size, &map, &err) == SKP_OK)
		for (int i = 0; i < map.count; i++)
			if (!map.entry[i].joint[0] || !map.entry[i].bone[0])
				__builtin_trap();
	return 0;
}

/* A material library (.mtl), read from memory as from a file: what is
 * kept has a name, Kd in [0, 1] and a texture path without backslashes,
 * each within its array. */
int fuzz_mtl(const uint8_t *data, size_t size)
{
	static rig_mtl lib;
	const char *why;
	if (!size)
		return 0;
	FILE *f = fmemopen((void *)(uintptr_t)data, size, "rb");
	if (!f)
		return 0;
	int ok = rig_mtl_read_stream(f, &lib, &why);
	fclose(f);
	if (!ok)
		return 0;
	if (lib.count < 0 || lib.count > RIG_MTL_MAX)
		__builtin_trap();
	for (int i = 0; i < lib.count; i++) {
		const rig_mtl_material *m = &lib.mat[i];
		if (!memchr(m->name, '\0', sizeof m->name) || !m->name[0] ||
		    !memchr(m->map_kd, '\0', sizeof m->map_kd) || strchr(m->map_kd, '\\'))
			__builtin_trap();
		for (int c = 0; c < 3 && m->has_kd; c++)
			if (!(m->kd[c] >= 0.0f && m->kd[c] <= 1.0f))
				__builtin_trap();
		if (rig_mtl_find(&lib, m->name) == NULL)
			__builtin_trap();
	}
	for (int w = 0; w < lib.warnings && w < RIG_MTL_WARNINGS; w++)
		if (!memchr(lib.warning[w], '\0', sizeof lib.warning[w]))
			__builtin_trap();
	return 0;
}

/* MakeHuman's JSON over a fixed mesh (nine vertices of ten in the file):
 * the input read as a skeleton, then as the weights of a fixed two-bone
 * skeleton; what reads must name existing joints with weights in [0, 1]. */
static const char mh_skeleton[] =
	"{\"bones\": {\"root\": {\"head\": \"r\", \"parent\": null}, \"spine05\": {\"head\": \"s\", "
	"\"parent\": \"root\"}}, \"joints\": {\"r\": [0, 1], \"s\": [9]}, \"weights_file\": \"w.mhw\"}";

static void mh_check(const rig_scene *r)
{
	for (int v = 0; v < r->mesh->vert_count; v++)
		for (int k = 0; k < r->infl_count[v]; k++)
			if (r->infl_joint[v][k] >= r->joint_count || !(r->infl_weight[v][k] >= 0.0f))
				__builtin_trap();
	for (int j = 0; j < r->joint_count; j++)
		if (r->joint[j].parent >= r->joint_count)
			__builtin_trap();
}

int fuzz_makehuman(const uint8_t *data, size_t size)
{
	static obj_work w;
	static mesh m;
	static rig_scene r;
	const char *wf;
	w.file_verts = 10;
	for (int i = 0; i < 10; i++) {
		w.pos[i] = vec3_make((float)(i % 3), (float)(i / 3), 0.0f);
		w.source[i] = (uint32_t)i;
	}
	m.vert_count = 9;
	r.mesh = &m;
	json_object *in = rig_json_parse((const char *)data, size, &err);
	if (!in)
		return 0;
	if (rig_mh_skeleton(in, &w, &r, &wf, &err) == SKP_OK)
		mh_check(&r);
	json_object *sk_json = rig_json_parse(mh_skeleton, sizeof mh_skeleton - 1, &err);
	if (!sk_json || rig_mh_skeleton(sk_json, &w, &r, &wf, &err) != SKP_OK)
		__builtin_trap();
	if (rig_mh_weights(in, &w, &r, &err) == SKP_OK)
		mh_check(&r);
	json_object_put(sk_json);
	json_object_put(in);
	return 0;
}

/* The mesh format sniffer on every prefix length the reader could hand it:
 * a known answer, and the same one for the same bytes (it reads nothing
 * past n). */
int fuzz_mesh_format(const uint8_t *data, size_t size)
{
	size_t n = size < MESH_FORMAT_HEAD ? size : MESH_FORMAT_HEAD;
	mesh_format f = mesh_format_sniff(data, n);
	if (f >= MESH_FMT_COUNT || !mesh_format_name(f)[0] || mesh_format_sniff(data, n) != f)
		__builtin_trap();
	if (n && mesh_format_sniff(data, n - 1) >= MESH_FMT_COUNT)
		__builtin_trap();
	return 0;
}

/* A compressed segment (app/codec): the first bytes make the clip's
 * header (tracks, frames a segment, each track's bits, base and step), the
 * rest is the segment. Every frame decoded must be on the tracks' grids. */
int fuzz_codec(const uint8_t *data, size_t size)
{
	static codec_clip c;
	static codec_decoder d;
	static float values[SKP_MAX_DOF];
	if (size < 2)
		return 0;
	memset(&c, 0, sizeof c);
	c.tracks = (uint16_t)(1 + data[0] % 16);
	c.segment_frames = (uint16_t)(1 + data[1] % 64);
	c.frames = c.segment_frames;
	size_t at = 2;
	for (int t = 0; t < c.tracks && at + 9 <= size; t++, at += 9) {
		c.track[t].bits = data[at] % 32;
		memcpy(&c.track[t].base, data + at + 1, 4);
		memcpy(&c.track[t].step, data + at + 5, 4);
	}
	if (codec_clip_check(&c, &err) != SKP_OK || codec_begin(&d, &c, 0, data + at, (uint32_t)(size - at), &err))
		return 0;
	while (codec_next(&d, values, &err) == 1)
		for (int t = 0; t < c.tracks; t++) {
			int32_t q = codec_last_q(&d, t);
			if (q < 0 || (c.track[t].bits ? q >= (1 << c.track[t].bits) : q != 0) ||
			    values[t] != codec_value(&c.track[t], q))
				__builtin_trap();
		}
	return 0;
}

const fuzz_target fuzz_targets[] = {
	{ "asf", fuzz_asf },
	{ "amc", fuzz_amc },
	{ "bvh", fuzz_bvh },
	{ "obj", fuzz_obj },
	{ "ini", fuzz_ini },
	{ "board_config", fuzz_board_config },
	{ "image", fuzz_image },
	{ "joint_map", fuzz_joint_map },
	{ "makehuman", fuzz_makehuman },
	{ "mesh_format", fuzz_mesh_format },
	{ "codec", fuzz_codec },
	{ "mtl", fuzz_mtl },
	{ NULL, NULL },
};
