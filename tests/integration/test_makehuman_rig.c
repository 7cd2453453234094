/* MakeHuman rigs (--rig FILE.mhskel, app/import/rig_makehuman.c): the
 * shared base mesh with its default skeleton and weights binds onto the
 * CMU skeleton with the artist's weights, which agree with the computed
 * ones on most of the body; hand-made broken rigs (JSON syntax, missing or
 * wrong members, vertices beyond the OBJ's, a weights file that is not
 * there) get messages naming the file, the line or the member, and what
 * was expected, with exit status 1. The shared-data tests skip without
 * ../shared. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_paths.h"
#include "test_run.h"
#include "test_weights.h"

#define MH "mesh/makehuman/"
#define MH_BODY_VERTS 13380

/* The shared files' paths, or 0 without ../shared. */
static int shared(char *asf, char *obj, char *rig, size_t n)
{
	const char *p;
	if (!(p = test_data_path("mocap/cmu/02.asf")))
		return 0;
	snprintf(asf, n, "%s", p);
	snprintf(obj, n, "%s", test_data_path(MH "base.obj"));
	snprintf(rig, n, "%s", test_data_path(MH "default.mhskel"));
	return 1;
}

static void test_base_mesh_binds(void **state)
{
	(void)state;
	char asf[4096], obj[4096], rig[4096];
	if (!shared(asf, obj, rig, sizeof asf))
		skip();
	const char *own = test_scratch("mh_own.csv"), *computed = test_scratch("mh_computed.csv");
	const char *log = test_scratch("mh_bind.log");
	assert_int_equal(test_run("%s bind %s %s --rig=%s --weights=mesh --report -o %s 2> %s",
				  test_tool_path("skintool"), asf, obj, rig, own, log), 0);
	/* --report says what the importer did, not the OBJ path's fit and pose */
	test_assert_contains_all(log, (const char *const[]){
		"\nbind pose: the skeleton posed as the mesh stands, by its joints\n",
		"\nfit: the mesh put on the skeleton by its joints",
		"\nweights: the mesh's own\n",
		"group 'body', 13380 vertices, 26756 triangles",
		"163 bones, weights from",
		"42 of 163 joints mapped onto the skeleton (names: MakeHuman default)",
		"upperarm01.L=lhumerus",
		"finger2-1.L=lfingers",
		"toe1-1.R=rtoes",
		"finger1-1.L->wrist.L",
		"lowerleg01.R=rtibia",
		"the mesh's own weights",
		NULL,
	});
	assert_int_equal(test_run("%s bind %s %s --rig=%s -o %s 2> %s", test_tool_path("skintool"), asf, obj, rig,
				  computed, log), 0);
	int same, same_part = test_same_part(own, computed, MH_BODY_VERTS, &same);
	printf("MakeHuman's weights and the computed ones agree on the body part of %d of %d vertices (%.1f%%), "
	       "on the bone of %d (%.1f%%)\n", same_part, MH_BODY_VERTS, 100.0 * same_part / MH_BODY_VERTS, same,
	       100.0 * same / MH_BODY_VERTS);
	/* measured 81.4%: they differ where parts meet */
	assert_true(same_part >= MH_BODY_VERTS * 3 / 4);
}

/* A 2 x 2 quad patch in group body, 9 vertices, and a helper cube's
 * vertex (9) beyond it, as MakeHuman places its joints. */
static const char tiny_obj[] =
	"v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\nv 1 3 0\n"
	"g body\nf 1 2 5 4\nf 2 3 6 5\nf 4 5 8 7\nf 5 6 9 8\n";

static const char tiny_rig[] =
	"{\n \"bones\": {\n  \"root\": {\"head\": \"root____head\", \"parent\": null},\n"
	"  \"spine05\": {\"head\": \"spine05____head\", \"parent\": \"root\"}\n },\n"
	" \"joints\": {\"root____head\": [0, 1, 2], \"spine05____head\": [9]},\n"
	" \"weights_file\": \"tiny.mhw\"\n}\n";

static const char tiny_weights[] = "{\"weights\": {\"root\": [[0, 1.0], [1, 0.5]], \"spine05\": [[1, 0.5]]}}\n";

typedef struct bad_rig {
	const char *rig, *weights; /* NULL: the good one */
	const char *file, *error;  /* which file the message names, and what it says */
} bad_rig;

static void test_broken_rigs(void **state)
{
	(void)state;
	static const bad_rig bad[] = {
		{ "{\n \"bones\": {\n", NULL, "tiny.mhskel:3: ", "JSON: the file ends inside a value" },
		{ "{\n \"bones\": {},\n  \x01 }\n", NULL, "tiny.mhskel:3: ", "JSON: " },
		{ "{} x\n", NULL, "tiny.mhskel:1: ", "JSON: text after the value, expected the end of the file" },
		{ "[1, 2]\n", NULL, "tiny.mhskel: ", "expected a MakeHuman skeleton" },
		{ "{\"bones\": {}, \"joints\": {}}", NULL, "tiny.mhskel: ", "bones: none" },
		{ "{\"bones\": {\"root\": {}}, \"joints\": {}}", NULL, "tiny.mhskel: ",
		  "bones: 'root': expected \"head\": the name of a joint" },
		{ "{\"bones\": {\"root\": {\"head\": \"h\"}}, \"joints\": {}}", NULL, "tiny.mhskel: ",
		  "joints: no list of vertices named 'h'" },
		{ "{\"bones\": {\"root\": {\"head\": \"h\"}}, \"joints\": {\"h\": [10]}}", NULL, "tiny.mhskel: ",
		  "joints: 'h' entry 1: expected a vertex number from 0 to 9 (the OBJ's)" },
		{ "{\"bones\": {\"root\": {\"head\": \"h\"}}, \"joints\": {\"h\": [1.5]}}", NULL, "tiny.mhskel: ",
		  "joints: 'h' entry 1: expected a vertex number" },
		{ "{\"bones\": {\"root\": {\"head\": \"h\", \"parent\": \"hip\"}}, \"joints\": {\"h\": [0]}}", NULL,
		  "tiny.mhskel: ", "bones: 'root': expected \"parent\": another bone's name or null" },
		{ "{\"bones\": {\"a\": {\"head\": \"h\", \"parent\": \"b\"}, \"b\": {\"head\": \"h\", \"parent\": \"a\"}},"
		  " \"joints\": {\"h\": [0]}}", NULL, "tiny.mhskel: ", "bones: 'a': its parents form a loop" },
		{ "{\"bones\": {\"r\\u0001\": {}}, \"joints\": {}}", NULL, "tiny.mhskel: ", "bones: 'r\\x01'" },
		{ "{\"bones\": {\"root\": {\"head\": \"h\"}}, \"joints\": {\"h\": [0]}}", NULL, "tiny.mhskel: ",
		  "expected \"weights_file\"" },
		{ NULL, "{\"weights\": {\"hip\": [[0, 1.0]]}}", "tiny.mhw: ",
		  "weights: 'hip' is not a bone of the skeleton" },
		{ NULL, "{\"weights\": {\"root\": [[0, 1.0], [1]]}}", "tiny.mhw: ",
		  "weights: 'root' entry 2: expected [vertex, weight], a vertex from 0 to 9 and a weight from 0 to 1" },
		{ NULL, "{\"weights\": {\"root\": [[0, 1.5]]}}", "tiny.mhw: ", "weights: 'root' entry 1: expected [vertex, weight]" },
		{ NULL, "{\"weights\": {\"root\": [[12, 1.0]]}}", "tiny.mhw: ", "weights: 'root' entry 1: expected [vertex, weight], a vertex from 0 to 9" },
		{ NULL, "{\"weights\": [\n]}", "tiny.mhw: ", "expected MakeHuman weights" },
		{ NULL, "{\"weights\": {\n\"root\": [[0, 1.0]]]\n}}", "tiny.mhw:2: ", "JSON: " },
	};
	char asf[4096], obj[4096], rig[4096];
	int with_shared = shared(asf, obj, rig, sizeof asf);
	const char *tiny = test_scratch("tiny.obj"), *mhskel = test_scratch("tiny.mhskel");
	const char *mhw = test_scratch("tiny.mhw"), *log = test_scratch("tiny.log"), *out = test_scratch("tiny.csv");
	/* any skeleton file serves: the rig fails before it meets it */
	const char *skel = with_shared ? asf : test_scratch("tiny.asf");
	if (!with_shared)
		test_write_text(skel, ":version 1.10\n:name t\n:units\n  mass 1.0\n  length 1.0\n  angle deg\n"
				"  :root\n   order TX TY TZ RX RY RZ\n   axis XYZ\n   position 0 0 0\n   orientation 0 0 0\n"
				":bonedata\n  begin\n     id 1\n     name a\n     direction 0 1 0\n     length 1\n"
				"     axis 0 0 0 XYZ\n  end\n:hierarchy\n  begin\n    root a\n  end\n");
	test_write_text(tiny, tiny_obj);
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		test_write_text(mhskel, bad[i].rig ? bad[i].rig : tiny_rig);
		test_write_text(mhw, bad[i].weights ? bad[i].weights : tiny_weights);
		assert_int_equal(test_run("%s bind %s %s --rig=%s --weights=mesh -o %s 2> %s",
					  test_tool_path("skintool"), skel, tiny, mhskel, out, log), 1);
		char want[512];
		snprintf(want, sizeof want, "%s%s", bad[i].file, bad[i].error);
		if (!test_file_contains(log, want)) {
			size_t size = 0;
			char *got = test_read_file(log, &size);
			fail_msg("case %zu: no '%s' in: %s", i + 1, want, got ? got : "(nothing)");
		}
	}
	/* the good tiny rig reads; its two bones are no arms or legs */
	test_write_text(mhskel, tiny_rig);
	test_write_text(mhw, tiny_weights);
	assert_int_equal(test_run("%s bind %s %s --rig=%s --weights=mesh -o %s 2> %s", test_tool_path("skintool"),
				  skel, tiny, mhskel, out, log), 1);
	assert_true(test_file_contains(log, "2 bones, weights from"));
	assert_true(test_file_contains(log, "--weights mesh: its arms and legs did not map onto the skeleton"));
	/* the weights file it names is not there */
	assert_int_equal(remove(mhw), 0);
	assert_int_equal(test_run("%s bind %s %s --rig=%s -o %s 2> %s", test_tool_path("skintool"), skel, tiny,
				  mhskel, out, log), 1);
	assert_true(test_file_contains(log, "tiny.mhw: cannot open: No such file or directory"));
	/* an OBJ without the group; --rig on a mesh with its own joints; no mesh */
	test_write_text(tiny, "v 0 0 0\nv 1 0 0\nv 0 1 0\ng hat\nf 1 2 3\n");
	assert_int_equal(test_run("%s bind %s %s --rig=%s -o %s 2> %s", test_tool_path("skintool"), skel, tiny,
				  mhskel, out, log), 1);
	assert_true(test_file_contains(log, "--rig: no faces in group 'body', the MakeHuman body (--group NAME picks another)"));
	if (with_shared) {
		char amc[4096], glb[4096];
		snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/02_01.amc"));
		snprintf(glb, sizeof glb, "%s", test_data_path("mesh/orange_juice_male_base/male_base_mesh.glb"));
		assert_int_equal(test_run("%s compare %s %s --rig=%s -o %s 2> %s", test_tool_path("skintool"), skel,
					  amc, mhskel, test_scratch("nomesh"), log), 1);
		assert_true(test_file_contains(log, "--joint-map and --rig need a mesh"));
		assert_int_equal(test_run("%s bind %s %s --rig=%s -o %s 2> %s", test_tool_path("skintool"), skel, glb,
					  mhskel, out, log), 1);
		assert_true(test_file_contains(log, "--rig gives an OBJ its MakeHuman rig"));
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_base_mesh_binds),
		cmocka_unit_test(test_broken_rigs),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
