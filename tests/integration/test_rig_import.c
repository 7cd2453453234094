/* Rigged meshes from interchange files (app/import): the shared CC0 body
 * (glTF binary, a Blender metarig skin) imports with its joints and
 * weights, maps onto the CMU and BVH skeletons, binds with its own weights
 * and with computed ones, renders, and gets the side-by-side compare
 * report; a rig whose names mean nothing (an FBX of Bone.NNN), a mesh
 * without a skin and a broken FBX get clear reports; a joint map file
 * remaps joints and its errors name their lines. Skips without
 * ../shared (and the FBX/glTF samples without Debian's assimp-testmodels). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "motion_file.h"
#include "rig_map.h"
#include "test_paths.h"
#include "test_run.h"
#include "test_weights.h"

#define GLB "mesh/orange_juice_male_base/male_base_mesh.glb"
#define SAMPLES "/usr/share/assimp/models"

static mesh glb_mesh;
static rig_scene scene;

static const char *data(const char *rel, char *buf, size_t n)
{
	const char *p = test_data_path(rel);
	if (!p)
		return NULL;
	snprintf(buf, n, "%s", p);
	return buf;
}

/* Imports the shared glb into scene; 0 when the shared data is absent. */
static int import_glb(char *glb, size_t n)
{
	if (!data(GLB, glb, n))
		return 0;
	skp_error err;
	scene.mesh = &glb_mesh;
	assert_int_equal(rig_import(glb, NULL, &scene, &err), SKP_OK);
	return 1;
}

static void test_glb_imports(void **state)
{
	(void)state;
	char glb[4096];
	skp_error err;
	if (!import_glb(glb, sizeof glb))
		skip();
	/* 1,226 file vertices, split at UV seams: welded back to 904 */
	assert_int_equal(glb_mesh.vert_count, 904);
	assert_int_equal(scene.welded, 322);
	assert_int_equal(glb_mesh.tri_count, 1804);
	assert_int_equal(scene.joint_count, 56);
	int ua = rig_find_joint(&scene, "upper_arm.L"), sh = rig_find_joint(&scene, "shoulder.L");
	assert_true(ua >= 0 && sh >= 0);
	assert_int_equal(scene.joint[ua].parent, sh);
	assert_int_equal(scene.joint[rig_find_joint(&scene, "spine")].parent, -1);
	for (int v = 0; v < glb_mesh.vert_count; v++) {
		float sum = 0.0f;
		for (int k = 0; k < scene.infl_count[v]; k++)
			sum += scene.infl_weight[v][k];
		if (fabsf(sum - 1.0f) > 1e-3f)
			fail_msg("vertex %d: weights sum to %g", v, (double)sum);
	}
	/* the armature is turned 90 degrees about Y: the node transforms are
	 * applied, so the body is 1.94 m tall along Y and its arms span X */
	float lo = INFINITY, hi = -INFINITY, xmin = INFINITY, xmax = -INFINITY;
	for (int v = 0; v < glb_mesh.vert_count; v++) {
		lo = fminf(lo, glb_mesh.pos[v].y);
		hi = fmaxf(hi, glb_mesh.pos[v].y);
		xmin = fminf(xmin, glb_mesh.pos[v].x);
		xmax = fmaxf(xmax, glb_mesh.pos[v].x);
	}
	assert_true(fabsf(hi - lo - 1.945f) < 0.01f);
	assert_true(xmax - xmin > 1.0f);
	/* the arms span X, one hand on each side */
	float lx = scene.joint[rig_find_joint(&scene, "hand.L")].head.x;
	float rx = scene.joint[rig_find_joint(&scene, "hand.R")].head.x;
	assert_true(fabsf(lx) > 0.5f && fabsf(rx) > 0.5f && lx * rx < 0.0f);
	assert_int_equal(rig_import(glb, "nosuch", &scene, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "'Cube.001'"));
}

typedef struct want_map {
	const char *joint, *bone;
} want_map;

static void check_map_of(const rig_scene *r, const char *skel_rel, const want_map *want, size_t n)
{
	char path[4096];
	static skel s;
	static skel_pose p;
	static rig_map m;
	skp_error err;
	if (!data(skel_rel, path, sizeof path) || motion_load_skel(path, &s) < 0)
		fail_msg("%s: cannot load", skel_rel);
	fk_pose(&s, NULL, &p);
	assert_int_equal(rig_map_joints(r, &s, &p, NULL, &m, &err), SKP_OK);
	assert_int_equal(m.limbs, 4);
	for (size_t i = 0; i < n; i++) {
		int j = rig_find_joint(r, want[i].joint);
		assert_true(j >= 0);
		const char *got = s.bone[m.follow[j]].name;
		if (strcmp(got, want[i].bone) != 0)
			fail_msg("%s on %s: %s moves with %s, want %s", skel_rel, GLB, want[i].joint, got, want[i].bone);
	}
}

static void check_map(const char *skel_rel, const want_map *want, size_t n)
{
	check_map_of(&scene, skel_rel, want, n);
}

static void test_glb_maps(void **state)
{
	(void)state;
	char glb[4096];
	if (!import_glb(glb, sizeof glb))
		skip();
	static const want_map cmu[] = {
		{ "spine", "root" }, { "spine.003", "thorax" }, { "spine.005", "head" },
		{ "shoulder.L", "lclavicle" }, { "upper_arm.L", "lhumerus" }, { "forearm.R", "rradius" },
		{ "hand.L", "lhand" }, { "f_index.01.L", "lfingers" }, { "f_index.02.L", "lfingers" },
		{ "f_pinky.03.R", "rfingers" }, { "thumb.03.R", "rhand" },
		{ "thigh.R", "rfemur" }, { "shin.L", "ltibia" }, { "foot.R", "rfoot" }, { "toe.L", "ltoes" },
		{ "heel.02.L", "lfoot" },
	};
	check_map("mocap/cmu/02.asf", cmu, sizeof cmu / sizeof cmu[0]);
	check_map("mocap/hdm05/HDM_dg.asf", cmu, sizeof cmu / sizeof cmu[0]);
	/* the CMU BVH conversion: other names, same parts */
	static const want_map bvh[] = {
		{ "spine", "Hips" }, { "upper_arm.L", "LeftShoulder" }, { "forearm.L", "LeftElbow" },
		{ "shoulder.R", "RightCollar" }, { "thigh.L", "LeftHip" }, { "shin.R", "RightKnee" },
		{ "foot.L", "LeftAnkle" }, { "f_middle.02.L", "LFingers" }, { "thumb.02.R", "rhand" },
	};
	check_map("mocap/cmu_bvh/131_01.bvh", bvh, sizeof bvh / sizeof bvh[0]);
	/* without a hand joint (RobotExpressive's fingers hang from its
	 * forearm) the fingers turn with the forearm, not alone with the
	 * skeleton's hand beside palms that do not */
	static rig_scene handless;
	handless = scene;
	snprintf(handless.joint[rig_find_joint(&handless, "hand.L")].name, RIG_NAME, "carpus.L");
	static const want_map no_hand[] = {
		{ "carpus.L", "lradius" }, { "f_index.01.L", "lradius" }, { "f_pinky.02.L", "lradius" },
		{ "f_index.01.R", "rfingers" },
	};
	check_map_of(&handless, "mocap/cmu/02.asf", no_hand, sizeof no_hand / sizeof no_hand[0]);
}

static void test_bind_own_and_computed(void **state)
{
	(void)state;
	char glb[4096], asf[4096];
	if (!data(GLB, glb, sizeof glb) || !data("mocap/cmu/02.asf", asf, sizeof asf))
		skip();
	const char *own = test_scratch("own.csv"), *computed = test_scratch("computed.csv");
	const char *log = test_scratch("bind.log");
	assert_int_equal(test_run("%s bind %s %s --weights mesh -o %s 2> %s", test_tool_path("skintool"), asf, glb,
				  own, log), 0);
	test_assert_contains_all(log, (const char *const[]){
		"30 of 56 joints mapped onto the skeleton (names: Rigify",
		"upper_arm.L=lhumerus",
		"f_index.01.L=lfingers",
		"26 joints unmapped, moving with their nearest mapped parent",
		"thumb.01.L->hand.L",
		"turned 180 degrees (a quarter-turn combination)",
		"skeleton posed as the mesh stands",
		"the mesh's own weights",
		NULL,
	});
	assert_int_equal(test_run("%s bind %s %s -o %s 2> %s", test_tool_path("skintool"), asf, glb, computed, log),
			 0);
	int same, same_part = test_same_part(own, computed, 904, &same);
	printf("dominant bone: the artist's and the computed weights agree on %d of 904 vertices (%.1f%%), "
	       "on the body part on %d (%.1f%%)\n", same, 100.0 * same / 904, same_part, 100.0 * same_part / 904);
	/* measured 855 (94.6%): the two differ where parts meet */
	assert_true(same_part >= 904 * 9 / 10);
}

/* Skin-toned pixels of a PNG's two panels (its halves), in each panel's
 * left third: the whole body, beside the compare view's close-up. */
static void figure_pixels(const char *path, long *left, long *right)
{
	png_image img;
	memset(&img, 0, sizeof img);
	img.version = PNG_IMAGE_VERSION;
	assert_true(png_image_begin_read_from_file(&img, path));
	img.format = PNG_FORMAT_RGB;
	unsigned char *buf = malloc(PNG_IMAGE_SIZE(img));
	assert_non_null(buf);
	assert_true(png_image_finish_read(&img, NULL, buf, 0, NULL));
	*left = *right = 0;
	for (size_t i = 0; i < (size_t)img.width * img.height; i++) {
		const unsigned char *p = buf + 3 * i;
		/* the body is skin-toned: red well above blue */
		size_t half = img.width / 2, x = i % img.width;
		if (x % half < half / 3 && p[0] > 120 && p[0] > p[2] + 40)
			++*(x < half ? left : right);
	}
	free(buf);
}

static void test_pack_and_render(void **state)
{
	(void)state;
	char glb[4096], asf[4096], amc[4096];
	if (!data(GLB, glb, sizeof glb) || !data("mocap/cmu/02.asf", asf, sizeof asf) ||
	    !data("mocap/cmu/02_01.amc", amc, sizeof amc))
		skip();
	const char *img = test_scratch("glb.skn"), *out = test_scratch("glb_frames");
	assert_int_equal(test_run("%s pack %s %s --mesh %s --weights mesh -o %s > /dev/null 2>&1",
				  test_tool_path("skintool"), asf, amc, glb, img), 0);
	assert_int_equal(test_run("%s --image %s --platform surfaceless --algo compare --size 320x240 --frames 61 "
				  "--every 60 --out %s > /dev/null 2>&1", test_tool_path("skinplay"), img, out), 0);
	char png[4200];
	for (int f = 1; f <= 61; f += 60) {
		snprintf(png, sizeof png, "%s/frame_%06d.png", out, f);
		long lbs, dqbs;
		figure_pixels(png, &lbs, &dqbs);
		printf("%s: body pixels %ld (LBS panel), %ld (DQBS panel) in the left third of each\n", png, lbs,
		       dqbs);
		/* a body of about 20 x 75 pixels in each panel, its lit side
		 * counted (measured 595), not a wrong fit's sliver or a body
		 * filling its column */
		assert_true(lbs > 300 && lbs < 3000 && dqbs > 300 && dqbs < 3000);
	}
}

/* The first render's caption of the report in dir (the ratios at its
 * vertex, measured as it renders), into buf. */
static void first_caption(const char *dir, char *buf, size_t n)
{
	char path[4200];
	snprintf(path, sizeof path, "%s/index.html", dir);
	size_t size = 0;
	char *html = test_read_file(path, &size);
	assert_non_null(html);
	const char *a = strstr(html, "<figcaption>Frame"), *b = a ? strstr(a, "</figcaption>") : NULL;
	assert_true(a && b && (size_t)(b - a) < n);
	snprintf(buf, n, "%.*s", (int)(b - a), a);
	free(html);
}

static void test_compare_side_by_side(void **state)
{
	(void)state;
	char glb[4096], asf[4096], amc[4096];
	if (!data(GLB, glb, sizeof glb) || !data("mocap/cmu/02.asf", asf, sizeof asf) ||
	    !data("mocap/cmu/02_01.amc", amc, sizeof amc))
		skip();
	const char *dir = test_scratch("glb_report"), *own = test_scratch("glb_own.csv");
	assert_int_equal(test_run("%s compare %s %s --mesh %s --weights mesh --renders 1 -o %s > /dev/null 2>&1",
				  test_tool_path("skintool"), asf, amc, glb, dir), 0);
	/* the renders are the main run's weights', not those of the side-by-side
	 * pass after it: the same as a report on the same weights from a file,
	 * which has no second pass */
	const char *dir2 = test_scratch("glb_report_csv");
	assert_int_equal(test_run("%s bind %s %s --weights mesh -o %s 2> /dev/null", test_tool_path("skintool"), asf,
				  glb, own), 0);
	assert_int_equal(test_run("%s compare %s %s --mesh %s --weights %s --renders 1 -o %s > /dev/null 2>&1",
				  test_tool_path("skintool"), asf, amc, glb, own, dir2), 0);
	char cap[512], cap2[512];
	first_caption(dir, cap, sizeof cap);
	first_caption(dir2, cap2, sizeof cap2);
	assert_string_equal(cap, cap2);
	char path[4200];
	snprintf(path, sizeof path, "%s/index.html", dir);
	assert_true(test_file_contains(path, "<table id=\"weights\">"));
	assert_true(test_file_contains(path, "the mesh&#39;s own") || test_file_contains(path, "the mesh's own"));
	assert_true(test_file_contains(path, "automatic (the paper"));
	snprintf(path, sizeof path, "%s/metrics_weights_computed.csv", dir);
	size_t size = 0;
	char *csv = test_read_file(path, &size);
	assert_non_null(csv);
	long lines = 0;
	for (size_t i = 0; i < size; i++)
		lines += csv[i] == '\n';
	free(csv);
	assert_int_equal(lines, 1 + 343 * 3);
}

/* --weights W.csv on a rigged mesh: the file's weights, as read */
static void test_weights_file_on_rig(void **state)
{
	(void)state;
	char glb[4096], asf[4096];
	if (!data(GLB, glb, sizeof glb) || !data("mocap/cmu/02.asf", asf, sizeof asf))
		skip();
	const char *own = test_scratch("file_own.csv"), *again = test_scratch("file_again.csv");
	assert_int_equal(test_run("%s bind %s %s --weights mesh -o %s 2> /dev/null", test_tool_path("skintool"), asf,
				  glb, own), 0);
	assert_int_equal(test_run("%s bind %s %s --weights %s -o %s 2> /dev/null", test_tool_path("skintool"), asf,
				  glb, own, again), 0);
	FILE *a = fopen(own, "r"), *b = fopen(again, "r");
	assert_true(a && b);
	char la[256], lb[256];
	long rows = 0;
	while (fgets(la, sizeof la, a)) {
		assert_non_null(fgets(lb, sizeof lb, b));
		char *ca = strrchr(la, ','), *cb = strrchr(lb, ',');
		assert_true(ca && cb && ca - la == cb - lb && memcmp(la, lb, (size_t)(ca - la)) == 0);
		if (rows++)
			assert_true(fabs(atof(ca + 1) - atof(cb + 1)) < 1e-6);
	}
	assert_null(fgets(lb, sizeof lb, b));
	fclose(a);
	fclose(b);
	assert_true(rows > 904);
}

static void test_unmapped_and_unskinned(void **state)
{
	(void)state;
	char asf[4096];
	if (!data("mocap/cmu/02.asf", asf, sizeof asf) || access(SAMPLES "/FBX/animation_with_skeleton.fbx", R_OK))
		skip();
	const char *log = test_scratch("unmapped.log"), *w = test_scratch("unmapped.csv");
	assert_int_equal(test_run("%s bind %s " SAMPLES "/FBX/animation_with_skeleton.fbx --weights mesh -o %s 2> %s",
				  test_tool_path("skintool"), asf, w, log), 1);
	test_assert_contains_all(log, (const char *const[]){
		"none of its 14 joints is named as the built-in maps know",
		"Bone Bone.001",
		"--joint-map FILE",
		NULL,
	});
	assert_int_not_equal(access(w, F_OK), 0);
	/* bound like an OBJ, it is no body a human skeleton can move: refused,
	 * and with --force the gate says why too */
	assert_int_equal(test_run("%s bind %s " SAMPLES "/FBX/animation_with_skeleton.fbx -o %s 2> %s",
				  test_tool_path("skintool"), asf, w, log), 1);
	test_assert_contains_all(log, (const char *const[]){
		"bound like an OBJ, weights computed",
		"animation_with_skeleton.fbx: not a biped: ",
		NULL,
	});
	assert_int_not_equal(access(w, F_OK), 0);
	assert_int_equal(test_run("%s bind %s " SAMPLES "/FBX/animation_with_skeleton.fbx --force -o %s 2> %s",
				  test_tool_path("skintool"), asf, w, log), 0);
	test_assert_contains_all(log, (const char *const[]){
		"not a biped: ",
		"(--force: bound anyway)",
		"animation_with_skeleton.fbx: the skin tears at ",
		"--force: bound anyway",
		NULL,
	});
	assert_int_equal(test_run("%s bind %s " SAMPLES "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb --weights mesh "
				  "-o %s 2> %s", test_tool_path("skintool"), asf, w, log), 1);
	assert_true(test_file_contains(log, "the mesh has no skin"));
}

static void test_broken_files(void **state)
{
	(void)state;
	char asf[4096], glb[4096], amc[4096];
	if (!data("mocap/cmu/02.asf", asf, sizeof asf) || !data(GLB, glb, sizeof glb) ||
	    !data("mocap/cmu/02_01.amc", amc, sizeof amc))
		skip();
	const char *fbx = test_scratch("broken.fbx"), *log = test_scratch("broken.log");
	FILE *f = fopen(fbx, "w");
	assert_non_null(f);
	fputs("; FBX 7.4.0 project file\nnot really\n", f);
	fclose(f);
	assert_int_equal(test_run("%s bind %s %s -o %s 2> %s", test_tool_path("skintool"), asf, fbx,
				  test_scratch("x.csv"), log), 1);
	assert_true(test_file_contains(log, "broken.fbx: "));
	assert_true(test_file_contains(log, "export the character as glTF 2.0 (.glb)"));
	assert_int_equal(test_run("%s bind %s %s -o %s 2> %s", test_tool_path("skintool"), asf,
				  test_scratch("missing.glb"), test_scratch("x.csv"), log), 1);
	assert_true(test_file_contains(log, "missing.glb: "));
	/* the device program reads packed images, never the interchange files */
	assert_int_equal(test_run("%s --asf %s --amc %s --mesh %s --platform surfaceless --frames 1 2> %s",
				  test_tool_path("skinplay"), asf, amc, glb, log), 1);
	assert_true(test_file_contains(log, "pack the rigged mesh into an image first"));
	assert_int_equal(test_run("%s bind %s %s --group nosuch -o %s 2> %s", test_tool_path("skintool"), asf, glb,
				  test_scratch("x.csv"), log), 1);
	assert_true(test_file_contains(log, "no mesh named 'nosuch'; there are: 'Cube.001'"));
}

/* Formats by content: a zipped COLLADA (.zae), the same file named .obj,
 * the glb named .obj, a MakeHuman skeleton given as the mesh, a Blender
 * file (meshes read, armature not). */
static void test_formats_by_content(void **state)
{
	(void)state;
	char asf[4096], glb[4096], mhskel[4096];
	if (!data("mocap/cmu/02.asf", asf, sizeof asf) || !data(GLB, glb, sizeof glb) ||
	    !data("mesh/makehuman/default.mhskel", mhskel, sizeof mhskel))
		skip();
	const char *log = test_scratch("format.log"), *w = test_scratch("format.csv");
	const char *renamed = test_scratch("glb_named.obj");
	assert_int_equal(test_run("cp %s %s", glb, renamed), 0);
	assert_int_equal(test_run("%s bind %s %s --weights mesh -o %s 2> %s", test_tool_path("skintool"), asf, renamed,
				  w, log), 0);
	test_assert_contains_all(log, (const char *const[]){
		"glb_named.obj: the file is a binary glTF (.glb), whatever its name says ('.obj'): read as that",
		"904 vertices, 1804 triangles, 56 joints",
		NULL,
	});
	assert_int_equal(test_run("%s bind %s %s -o %s 2> %s", test_tool_path("skintool"), asf, mhskel, w, log), 1);
	assert_true(test_file_contains(log, "default.mhskel: the file is a JSON file that is not glTF, not a mesh"));
	assert_true(test_file_contains(log, "goes with its OBJ as --rig FILE"));
	if (access(SAMPLES "/Collada/human.zae", R_OK) || access(SAMPLES "/BLEND/HUMAN.blend", R_OK))
		return;
	const char *zip_obj = test_scratch("zipped.obj");
	assert_int_equal(test_run("cp " SAMPLES "/Collada/human.zae %s", zip_obj), 0);
	assert_true(test_run("%s bind %s %s -o %s 2> %s", test_tool_path("skintool"), asf, zip_obj, w, log) >= 0);
	test_assert_contains_all(log, (const char *const[]){
		"zipped.obj: the file is a zip archive, whatever its name says ('.obj'): read as that",
		"zipped.obj: 14444 vertices, 28796 triangles",
		NULL,
	});
	assert_true(test_run("%s bind %s " SAMPLES "/BLEND/HUMAN.blend -o %s 2> %s", test_tool_path("skintool"), asf, w,
			     log) >= 0);
	assert_true(test_file_contains(log, "a Blender file's meshes are read, its armature and weights are not"));
}

static void test_joint_map_file(void **state)
{
	(void)state;
	char asf[4096], glb[4096];
	if (!data("mocap/cmu/02.asf", asf, sizeof asf) || !data(GLB, glb, sizeof glb))
		skip();
	const char *map = test_scratch("fingers.map"), *w = test_scratch("fingers.csv");
	const char *log = test_scratch("map.log");
	test_write_text(map, "# Rigify fingers onto CMU's finger bones\nf_index.01.L = lfingers\nthumb.01.L = lthumb\n"
		   "shoulder.R = -\n");
	assert_int_equal(test_run("%s bind %s %s --weights mesh --joint-map %s -o %s 2> %s",
				  test_tool_path("skintool"), asf, glb, map, w, log), 0);
	assert_true(test_file_contains(log, "and the joint map"));
	assert_true(test_file_contains(log, "f_index.01.L=lfingers"));
	assert_true(test_file_contains(w, ",lfingers,") && test_file_contains(w, ",lthumb,"));
	assert_false(test_file_contains(w, ",rclavicle,"));
	static const struct {
		const char *text, *error;
	} bad[] = {
		{ "hand.L = lhand\nnosuch = lhumerus\n", "bad.map:2: the mesh has no joint named 'nosuch'" },
		{ "hand.L = nosuch\n", "bad.map:1: the skeleton has no bone named 'nosuch'" },
		{ "\nhand.L lhumerus\n", "bad.map:2: expected JOINT = BONE, found no '='" },
	};
	const char *bad_map = test_scratch("bad.map");
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		test_write_text(bad_map, bad[i].text);
		assert_int_equal(test_run("%s bind %s %s --joint-map %s -o %s 2> %s", test_tool_path("skintool"), asf,
					  glb, bad_map, w, log), 1);
		if (!test_file_contains(log, bad[i].error))
			fail_msg("'%s': no '%s' in the message", bad[i].text, bad[i].error);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_glb_imports),
		cmocka_unit_test(test_glb_maps),
		cmocka_unit_test(test_bind_own_and_computed),
		cmocka_unit_test(test_pack_and_render),
		cmocka_unit_test(test_compare_side_by_side),
		cmocka_unit_test(test_weights_file_on_rig),
		cmocka_unit_test(test_unmapped_and_unskinned),
		cmocka_unit_test(test_broken_files),
		cmocka_unit_test(test_formats_by_content),
		cmocka_unit_test(test_joint_map_file),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
