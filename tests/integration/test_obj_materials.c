/* An OBJ's materials (issue 44): its mtllib's Kd and map_Kd per usemtl
 * group, as the glTF path packs a file's (rig_obj_colour.h, rig_mtl.h).
 *   - Files nobody here made: assimp-testmodels' OBJ samples with their
 *     .mtl (skipped without them): the library read (spider's five
 *     materials and JPEGs, names with spaces, an empty name), and their
 *     meshes coloured (spider's JPEGs, cube_usemtl's missing mtl3).
 *   - The shared MakeHuman base.obj with an mtllib and usemtl added, as a
 *     MakeHuman export has them: a PNG checker goes to the GPU with the
 *     OBJ's vt (the file's vertices kept in order, twins at UV seams with
 *     their source's place and weights), packed and played red and blue; a
 *     Kd alone colours every vertex.
 *   - Broken: a missing library, a missing, truncated, too large or
 *     unreadable texture, a bad Kd line: a warning naming file and
 *     material (and line), exit 0, the body in its Kd or today's colour;
 *     without mtllib nothing changes. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "png_writer.h"
#include "rig_mtl.h"
#include "rig_obj_colour.h"
#include "rig_scene.h"
#include "setup_mesh_io.h"
#include "test_paths.h"
#include "test_run.h"

#define SAMPLES "/usr/share/assimp/models/OBJ/"

static mesh m;
static rig_scene scene;
static rig_obj_colour_report rep;
static rig_mtl lib;

static void need(const char *path)
{
	if (access(path, R_OK))
		skip();
}

/* The OBJ read (group: NULL all) and coloured from its materials. */
static const obj_work *colour(const char *obj, const char *group)
{
	const obj_work *w = setup_load_obj(obj, group, &m, NULL);
	assert_non_null(w);
	scene.mesh = &m;
	rig_scene_reset(&scene);
	memset(scene.infl_count, 0, sizeof scene.infl_count);
	rig_obj_colour(obj, w, &scene, &rep);
	return w;
}

static int warned(const char *a, const char *b)
{
	for (int k = 0; k < rep.warnings && k < RIG_OBJ_WARNINGS; k++)
		if (strstr(rep.warning[k], a) && (!b || strstr(rep.warning[k], b)))
			return 1;
	for (int k = 0; k < rep.warnings && k < RIG_OBJ_WARNINGS; k++)
		print_message("warning: %s\n", rep.warning[k]);
	return 0;
}

static void test_sample_libraries(void **state)
{
	(void)state;
	const char *why = NULL;
	need(SAMPLES "spider.mtl");
	assert_true(rig_mtl_read(SAMPLES "spider.mtl", &lib, &why));
	assert_int_equal(lib.count, 5);
	assert_int_equal(lib.warnings, 0);
	const rig_mtl_material *skin = rig_mtl_find(&lib, "Skin");
	assert_non_null(skin);
	assert_true(skin->has_kd && skin->kd[0] > 0.8274f && skin->kd[0] < 0.8275f && skin->kd[2] < 0.7726f);
	assert_string_equal(skin->map_kd, "./wal67ar_small.jpg"); /* written .\wal67ar_small.jpg */
	assert_string_equal(rig_mtl_find(&lib, "Augentex")->map_kd, "./engineflare1.jpg");

	assert_true(rig_mtl_read(SAMPLES "box_spaces.mtl", &lib, &why));
	const rig_mtl_material *sp = rig_mtl_find(&lib, "Material name with many, many spaces");
	assert_non_null(sp);
	assert_true(sp->has_kd && sp->kd[1] > 0.19f && sp->kd[1] < 0.21f);

	/* `newmtl ` with no name: its line a warning, its Kd left out */
	assert_true(rig_mtl_read(SAMPLES "empty_mat.mtl", &lib, &why));
	assert_int_equal(lib.count, 0);
	assert_int_equal(lib.warnings, 1);
	assert_non_null(strstr(lib.warning[0], "3: 'newmtl' expects a material name"));

	assert_false(rig_mtl_read(SAMPLES "no_such.mtl", &lib, &why));
	assert_string_equal(why, "is missing");
}

static void test_sample_meshes(void **state)
{
	(void)state;
	need(SAMPLES "spider.obj");
	need(SAMPLES "SpiderTex.jpg");
	colour(SAMPLES "spider.obj", NULL);
	assert_int_equal(rep.warnings, 0);
	assert_int_equal(rep.materials, 4); /* HLeibTex Skin BeinTex Augentex; Brusttex unused */
	assert_int_equal(rep.textures, 4);
	assert_true(m.coloured && m.textured);
	print_message("spider: %d vertices (%d seam twins), texture '%s' (material '%s', %dx%d) on the GPU\n",
		      m.vert_count, rep.twins, scene.texture_path, scene.texture_material, scene.texture_w,
		      scene.texture_h);
	int sampled = 0;
	for (int v = 0; v < m.vert_count; v++)
		sampled += m.sampled[v];
	assert_true(sampled > 0 && sampled < m.vert_count); /* one texture drawn, the others baked */
	rig_scene_release(&scene);

	/* mtl3 is used but not in the library: named, its faces in the skin colour */
	colour(SAMPLES "cube_usemtl.obj", NULL);
	assert_true(warned("material 'mtl3' is not in", "cube_usemtl.mtl"));
	assert_int_equal(rep.materials, 2);
	assert_true(m.coloured && !m.textured);

	/* a name with spaces matches its newmtl */
	colour(SAMPLES "box_mat_with_spaces.obj", NULL);
	assert_int_equal(rep.warnings, 0);
	assert_int_equal(rep.materials, 1);
	for (int v = 0; v < m.vert_count; v++)
		assert_int_equal(m.colour[v][0], 124); /* Kd 0.2, linear, as sRGB */

	colour(SAMPLES "empty_mat.obj", NULL);
	assert_true(warned("empty_mat.mtl:3: 'newmtl' expects a material name", NULL));
	assert_false(m.coloured);
}

/* MakeHuman's base mesh as an export has it, in the scratch directory:
 * `mtllib base.mtl` after its header, `usemtl skin` on its body, the
 * library's text mtl (NULL: none written). */
static const char *makehuman(const char *mtl)
{
	const char *src = test_data_path("mesh/makehuman/base.obj");
	if (!src || access(src, R_OK))
		skip();
	size_t n;
	char *text = test_read_file(src, &n);
	assert_non_null(text);
	static char obj[600];
	snprintf(obj, sizeof obj, "%s", test_scratch("base.obj"));
	FILE *f = fopen(obj, "wb");
	assert_non_null(f);
	fputs("mtllib base.mtl\n", f);
	char *body = strstr(text, "\ng body\n");
	assert_non_null(body);
	body += strlen("\ng body\n");
	fwrite(text, 1, (size_t)(body - text), f);
	fputs("usemtl skin\n", f);
	fwrite(body, 1, n - (size_t)(body - text), f);
	assert_int_equal(fclose(f), 0);
	free(text);
	unlink(test_scratch("base.mtl"));
	if (mtl) {
		f = fopen(test_scratch("base.mtl"), "wb");
		assert_non_null(f);
		fputs(mtl, f);
		assert_int_equal(fclose(f), 0);
	}
	for (int k = 0; k < 2; k++) {
		const char *rig = k ? "mesh/makehuman/default_weights.mhw" : "mesh/makehuman/default.mhskel";
		assert_int_equal(test_run("cp '%s' '%s'", test_data_path(rig), test_scratch_dir()), 0);
	}
	return obj;
}

/* A 256x256 checker of 32-pixel squares, red and blue, at textures/NAME. */
static void checker(const char *name)
{
	static uint8_t px[256 * 256 * 4];
	for (int y = 0; y < 256; y++)
		for (int x = 0; x < 256; x++) {
			uint8_t *p = px + 4 * (256 * y + x);
			int red = ((x / 32) + (y / 32)) % 2 == 0;
			p[0] = red ? 220 : 40;
			p[1] = red ? 40 : 60;
			p[2] = red ? 40 : 220;
			p[3] = 255;
		}
	char path[700];
	assert_int_equal(test_run("mkdir -p '%s/textures'", test_scratch_dir()), 0);
	snprintf(path, sizeof path, "%s/textures/%s", test_scratch_dir(), name);
	skp_error err;
	assert_int_equal(png_write_rgba(path, px, 256, 256, 0, &err), 0);
}

static const char *const CHECKER_MTL = "# MakeHuman export\nnewmtl skin\nKa 0 0 0\nKd 1.0 1.0 1.0\n"
				       "map_Kd textures/skin_diffuse.png\n";

static void test_makehuman_textured(void **state)
{
	(void)state;
	const char *obj = makehuman(CHECKER_MTL);
	checker("skin_diffuse.png");
	const obj_work *w = colour(obj, "body");
	assert_int_equal(rep.warnings, 0);
	assert_true(m.coloured && m.textured);
	assert_int_equal(scene.texture_w, 256);
	assert_string_equal(scene.texture_material, "skin");
	/* the file's vertices keep their numbers; the twins come after them */
	int file_verts = (int)(m.vert_count - rep.twins);
	assert_int_equal(file_verts, 13380);
	assert_true(rep.twins > 0 && rep.twins == scene.seams);
	for (int v = 0; v < m.vert_count; v++) {
		assert_true(m.sampled[v]);
		if (v < file_verts) {
			assert_int_equal(scene.seam_lead[v], v);
			continue;
		}
		int lead = scene.seam_lead[v];
		assert_true(lead < file_verts);
		assert_memory_equal(&m.pos[v], &m.pos[lead], sizeof m.pos[v]);
		assert_true(m.uv[v][0] != m.uv[lead][0] || m.uv[v][1] != m.uv[lead][1]);
	}
	/* each corner shows its own vt */
	for (int t = 0; t < m.tri_count; t++)
		for (int k = 0; k < 3; k++) {
			int v = (int)m.tri[t][k], vt = w->tri_vt[t][k];
			assert_true(m.uv[v][0] == w->vt[vt][0] && m.uv[v][1] == w->vt[vt][1]);
		}
	print_message("MakeHuman body: %d vertices, %d twins at UV seams\n", m.vert_count, rep.twins);
	rig_scene_release(&scene);
}

/* The frame's share of red and of blue pixels. */
static void frame_colours(const char *png, double *red, double *blue)
{
	static uint8_t px[480 * 540 * 4];
	int fw, fh;
	skp_error err;
	if (png_read_rgba(png, px, sizeof px, &fw, &fh, &err) != 0)
		fail_msg("%s: %s", png, err.msg);
	*red = *blue = 0;
	for (long i = 0; i < (long)fw * fh; i++) {
		const uint8_t *p = px + 4 * i;
		*red += p[0] > 2 * p[1] + 30 && p[0] > 2 * p[2] + 30;
		*blue += p[2] > 2 * p[0] + 30 && p[2] > p[1] + 60;
	}
	*red /= (double)fw * fh;
	*blue /= (double)fw * fh;
}

static void test_makehuman_packed_and_played(void **state)
{
	(void)state;
	const char *obj = makehuman(CHECKER_MTL);
	checker("skin_diffuse.png");
	const char *img = test_scratch("mh.skn"), *err = test_scratch("mh_err.txt"), *out = test_scratch("frames");
	/* under the sanitizers or an emulator the clip's first 30 frames (the
	 * whole clip's pack took 23 s under qemu, 6 s so): the texture is the
	 * same; natively the whole clip */
	const char *amc = test_slow() ? test_clip_head("assets/cmu/02_01.amc", 30, NULL) : "assets/cmu/02_01.amc";
	assert_int_equal(test_run("%s pack -q assets/cmu/02.asf '%s' --mesh '%s' --rig '%s' "
				  "--weights mesh -o '%s' 2>'%s'", test_tool_path("skintool"), amc, obj,
				  test_scratch("default.mhskel"), img, err), 0);
	const char *info = test_scratch("mh_info.txt");
	assert_int_equal(test_run("%s info '%s' > '%s' 2>&1", test_tool_path("skintool"), img, info), 0);
	if (!test_file_contains(info, "texture: 256x256 ETC1, 9 mip levels") ||
	    !test_file_contains(info, "vertices sample it"))
		fail_msg("skintool info did not list the texture");
	if (test_emulator())
		return; /* no aarch64 Mesa under qemu-user */
	assert_int_equal(test_run("%s --image '%s' --platform surfaceless --size 480x540 --hud off --frames 1 --out '%s' "
				  ">/dev/null 2>&1", test_tool_path("skinplay"), img, out), 0);
	char png[700];
	snprintf(png, sizeof png, "%s/frame_000001.png", out);
	double red, blue;
	frame_colours(png, &red, &blue);
	print_message("MakeHuman played in the checker: %.2f%% of the frame red, %.2f%% blue\n", 100 * red, 100 * blue);
	assert_true(red > 0.01 && blue > 0.01);
}

static void test_makehuman_kd(void **state)
{
	(void)state;
	colour(makehuman("newmtl skin\nKd 0.2 0.5 0.8\n"), "body");
	assert_int_equal(rep.warnings, 0);
	assert_true(m.coloured && !m.textured);
	assert_int_equal(m.vert_count, 13380);
	for (int v = 0; v < m.vert_count; v++) {
		assert_int_equal(m.colour[v][0], 124);
		assert_int_equal(m.colour[v][1], 188);
		assert_int_equal(m.colour[v][2], 231);
	}
}

/* The body coloured wholly in Kd 0.2 0.5 0.8 (or, green 0, today's skin colour). */
static void all_kd(int kd)
{
	assert_false(m.textured);
	assert_int_equal(m.coloured, kd);
	for (int v = 0; kd && v < m.vert_count; v++)
		assert_true(m.colour[v][0] == 124 && m.colour[v][1] == 188 && m.colour[v][2] == 231);
}

/* skintool bind says the warning and exits 0. Each case's warning is
 * checked in this process (colour()); the tool prints them all alike, so
 * under the sanitizers or an emulator (a bind a minute under qemu) the
 * first case alone goes through it. */
static void tool_warns(const char *obj, const char *text)
{
	static int ran;
	if (test_slow() && ran++)
		return;
	const char *csv = test_scratch("w.csv"), *err = test_scratch("bind_err.txt");
	assert_int_equal(test_run("%s bind -q assets/cmu/02.asf '%s' --rig '%s' --weights mesh -o '%s' 2>'%s'",
				  test_tool_path("skintool"), obj, test_scratch("default.mhskel"), csv, err), 0);
	if (!test_file_contains(err, text) || !test_file_contains(err, "base.obj: warning: "))
		fail_msg("skintool bind did not warn '%s'", text);
}

static void test_broken_input(void **state)
{
	(void)state;
	static const char *const tex = "newmtl skin\nKd 0.2 0.5 0.8\nmap_Kd textures/skin_diffuse.png\n";
	char path[700];
	/* no library */
	const char *obj = makehuman(NULL);
	colour(obj, "body");
	assert_true(warned("base.mtl' is missing: material 'skin'", "skin colour"));
	all_kd(0);
	tool_warns(obj, "base.mtl' is missing: material 'skin' drawn in the skin colour");

	/* the texture missing, then cut at half, then 9000 pixels wide, then text */
	makehuman(tex);
	snprintf(path, sizeof path, "%s/textures/skin_diffuse.png", test_scratch_dir());
	unlink(path);
	colour(obj, "body");
	assert_true(warned("material 'skin'", "texture 'textures/skin_diffuse.png' is missing: drawn in the material's colour (Kd)"));
	all_kd(1);
	tool_warns(obj, "material 'skin' (");

	checker("skin_diffuse.png");
	assert_int_equal(test_run("truncate -s $(($(stat -c %%s '%s') / 2)) '%s'", path, path), 0);
	colour(obj, "body");
	assert_true(warned("material 'skin'", "is truncated or damaged"));
	all_kd(1);
	tool_warns(obj, "is truncated or damaged: drawn in the material's colour");

	static uint8_t wide[9000 * 4];
	skp_error err;
	assert_int_equal(png_write_rgba(path, wide, 9000, 1, 0, &err), 0);
	colour(obj, "body");
	assert_true(warned("material 'skin'", "is larger than 8192 pixels a side"));
	all_kd(1);

	FILE *f = fopen(path, "wb");
	assert_non_null(f);
	fputs("not an image\n", f);
	fclose(f);
	colour(obj, "body");
	assert_true(warned("material 'skin'", "is neither PNG nor JPEG"));
	all_kd(1);

	/* a bad Kd line: named by file and line, the body in today's colour */
	makehuman("newmtl skin\nKd 0.2 zz\x01 0.8\n");
	colour(obj, "body");
	assert_true(warned("base.mtl:2: material 'skin': 'Kd' expects r g b", "zz\\x01"));
	all_kd(0);
	tool_warns(obj, "base.mtl:2: material 'skin': 'Kd' expects r g b");
}

/* Without mtllib the mesh is left as the OBJ reader made it. */
static void test_no_library(void **state)
{
	(void)state;
	const char *src = test_data_path("mesh/makehuman/base.obj");
	if (!src || access(src, R_OK))
		skip();
	colour(src, "body");
	assert_int_equal(rep.warnings, 0);
	assert_false(m.coloured || m.textured);
	assert_int_equal(m.vert_count, 13380);
	assert_int_equal(scene.seams, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_sample_libraries),
		cmocka_unit_test(test_sample_meshes),
		cmocka_unit_test(test_makehuman_textured),
		cmocka_unit_test(test_makehuman_packed_and_played),
		cmocka_unit_test(test_makehuman_kd),
		cmocka_unit_test(test_broken_input),
		cmocka_unit_test(test_no_library),
	};
	int failed = cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
	rig_scene_release(&scene);
	return failed;
}
