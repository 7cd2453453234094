/* mesh_format_sniff: hand-made starts of every format it knows, files
 * whose name lies (the content decides), text and binary it does not
 * know, and real files: the shared data's OBJ and glb, and Debian's
 * assimp-testmodels samples of each format when installed. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_format.h"
#include "test_paths.h"

static mesh_format sniff(const char *s, size_t n)
{
	return mesh_format_sniff((const unsigned char *)s, n);
}

#define SNIFF(lit) sniff(lit, sizeof lit - 1)

static void test_signatures(void **state)
{
	(void)state;
	assert_int_equal(SNIFF("glTF\x02\0\0\0"), MESH_FMT_GLB);
	assert_int_equal(SNIFF("PK\x03\x04\x14\0"), MESH_FMT_ZIP);
	assert_int_equal(SNIFF("BLENDER-v279"), MESH_FMT_BLEND);
	assert_int_equal(SNIFF("Kaydara FBX Binary  \0\x1a"), MESH_FMT_FBX);
	assert_int_equal(SNIFF("; FBX 7.4.0 project file\n"), MESH_FMT_FBX);
	assert_int_equal(SNIFF("xof 0303txt 0032\n"), MESH_FMT_X);
	assert_int_equal(SNIFF("ply\nformat ascii 1.0\n"), MESH_FMT_PLY);
	assert_int_equal(SNIFF("solid cube\n facet"), MESH_FMT_STL);
	assert_int_equal(SNIFF("MS3D000000\x04\0\0\0"), MESH_FMT_OTHER_MODEL);
	assert_int_equal(SNIFF(""), MESH_FMT_EMPTY);
}

static void test_text_formats(void **state)
{
	(void)state;
	assert_int_equal(SNIFF("<?xml version=\"1.0\"?>\n<COLLADA xmlns=\"x\">"), MESH_FMT_COLLADA);
	assert_int_equal(SNIFF("\xef\xbb\xbf<?xml version=\"1.0\"?>\n<X3D>"), MESH_FMT_XML);
	assert_int_equal(SNIFF("{\n  \"accessors\": [ { \"count\": 3 } ]"), MESH_FMT_GLTF);
	assert_int_equal(SNIFF("{\"asset\": {\"version\": \"2.0\"}}"), MESH_FMT_GLTF);
	assert_int_equal(SNIFF("{\"bones\": {\"root\": {}}}"), MESH_FMT_JSON);
	assert_int_equal(SNIFF("# made by hand\n\nv 0 0 0\nf 1 2 3\n"), MESH_FMT_OBJ);
	assert_int_equal(SNIFF("mtllib a.mtl\no body\n"), MESH_FMT_OBJ);
	assert_int_equal(SNIFF("# only comments so far"), MESH_FMT_OBJ);
	assert_int_equal(SNIFF("hello world\n"), MESH_FMT_UNKNOWN_TEXT);
	assert_int_equal(SNIFF("\x01\x02\x03\x04"), MESH_FMT_UNKNOWN_BINARY);
	/* a truncated signature is not the format */
	assert_int_equal(SNIFF("gl"), MESH_FMT_UNKNOWN_TEXT);
	assert_int_equal(SNIFF("PK"), MESH_FMT_UNKNOWN_TEXT);
}

static void test_interchange(void **state)
{
	(void)state;
	assert_true(mesh_format_is_interchange(MESH_FMT_GLB));
	assert_true(mesh_format_is_interchange(MESH_FMT_ZIP));
	assert_true(mesh_format_is_interchange(MESH_FMT_BLEND));
	assert_false(mesh_format_is_interchange(MESH_FMT_OBJ));
	assert_false(mesh_format_is_interchange(MESH_FMT_JSON));
	assert_false(mesh_format_is_interchange(MESH_FMT_UNKNOWN_BINARY));
	assert_string_equal(mesh_format_extension(MESH_FMT_ZIP), "zae");
	for (int f = 0; f < MESH_FMT_COUNT; f++)
		assert_true(strlen(mesh_format_name((mesh_format)f)) > 4);
}

static mesh_format sniff_file(const char *path)
{
	unsigned char head[MESH_FORMAT_HEAD];
	FILE *f = fopen(path, "rb");
	if (!f)
		return MESH_FMT_COUNT;
	size_t n = fread(head, 1, sizeof head, f);
	fclose(f);
	return mesh_format_sniff(head, n);
}

static void test_real_files(void **state)
{
	(void)state;
	static const struct {
		const char *path;
		mesh_format want;
	} samples[] = {
		{ "/usr/share/assimp/models/Collada/human.zae", MESH_FMT_ZIP },
		{ "/usr/share/assimp/models/Collada/duck.dae", MESH_FMT_COLLADA },
		{ "/usr/share/assimp/models/BLEND/HUMAN.blend", MESH_FMT_BLEND },
		{ "/usr/share/assimp/models/FBX/huesitos.fbx", MESH_FMT_FBX },
		{ "/usr/share/assimp/models/FBX/embedded_ascii/box.FBX", MESH_FMT_FBX },
		{ "/usr/share/assimp/models/X/BCN_Epileptic.X", MESH_FMT_X },
		{ "/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf", MESH_FMT_GLTF },
		{ "/usr/share/assimp/models/OBJ/box.obj", MESH_FMT_OBJ },
	};
	int seen = 0;
	for (size_t i = 0; i < sizeof samples / sizeof samples[0]; i++) {
		mesh_format f = sniff_file(samples[i].path);
		if (f == MESH_FMT_COUNT)
			continue;
		if (f != samples[i].want)
			fail_msg("%s: sniffed as %s, expected %s", samples[i].path, mesh_format_name(f),
				 mesh_format_name(samples[i].want));
		seen++;
	}
	const char *obj = test_data_path("mesh/makehuman/base.obj");
	if (obj) {
		assert_int_equal(sniff_file(obj), MESH_FMT_OBJ);
		assert_int_equal(sniff_file(test_data_path("mesh/orange_juice_male_base/male_base_mesh.glb")),
				 MESH_FMT_GLB);
		assert_int_equal(sniff_file(test_data_path("mesh/makehuman/default.mhskel")), MESH_FMT_JSON);
		seen += 3;
	}
	if (!seen)
		skip();
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_signatures),
		cmocka_unit_test(test_text_formats),
		cmocka_unit_test(test_interchange),
		cmocka_unit_test(test_real_files),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
