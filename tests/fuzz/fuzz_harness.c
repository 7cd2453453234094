/* Harnesses for the text parsers. The state lives in static storage as in
 * the front ends; the input is streamed through an skp_mem_reader, so the
 * fixed line buffer and its chunk boundaries are exercised as with a file. */
#include "fuzz_harness.h"

#include "amc.h"
#include "asf.h"
#include "board_config.h"
#include "fk.h"
#include "ini.h"
#include "obj.h"
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

const fuzz_target fuzz_targets[] = {
	{ "asf", fuzz_asf },
	{ "amc", fuzz_amc },
	{ "obj", fuzz_obj },
	{ "ini", fuzz_ini },
	{ "board_config", fuzz_board_config },
	{ NULL, NULL },
};
