/* OBJ import: polygons, corner forms, indices, groups, normals, errors,
 * and the MakeHuman base mesh. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "clock.h"
#include "file_reader.h"
#include "obj.h"
#include "test_paths.h"

static mesh m;
static obj_work work;
static text_lines tl;
static skp_error err;

static skp_status parse_opt(const char *text, const char *group, int max_verts, int max_tris)
{
	skp_mem_source src;
	obj_options opt = { group, max_verts, max_tris };
	text_lines_init(&tl, skp_mem_reader(&src, text, strlen(text)));
	return obj_parse(&m, &work, &tl, &opt, &err);
}

static skp_status parse(const char *text)
{
	return parse_opt(text, NULL, 0, 0);
}

static void assert_tri(int t, uint32_t a, uint32_t b, uint32_t c)
{
	assert_int_equal(m.tri[t][0], a);
	assert_int_equal(m.tri[t][1], b);
	assert_int_equal(m.tri[t][2], c);
}

static void assert_vec(vec3 v, float x, float y, float z)
{
	assert_true(fabsf(v.x - x) < 1e-5f);
	assert_true(fabsf(v.y - y) < 1e-5f);
	assert_true(fabsf(v.z - z) < 1e-5f);
}

static void assert_fails(skp_status want, long line, const char *text_in_msg)
{
	assert_int_equal(err.code, want);
	assert_int_equal(err.line, line);
	if (!strstr(err.msg, text_in_msg))
		fail_msg("message '%s' lacks '%s'", err.msg, text_in_msg);
}

static void test_triangle(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), SKP_OK);
	assert_int_equal(m.vert_count, 3);
	assert_int_equal(m.tri_count, 1);
	assert_tri(0, 0, 1, 2);
	assert_vec(m.pos[1], 1, 0, 0);
	for (int i = 0; i < 3; i++)
		assert_vec(m.normal[i], 0, 0, 1);
	assert_int_equal(work.normals_from_file, 0);
}

/* A rhombus long along x: the short diagonal is 2-4. */
static void test_quad_short_diagonal(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\nv 2 -1 0\nv 4 0 0\nv 2 1 0\nf 1 2 3 4\n"), SKP_OK);
	assert_int_equal(m.tri_count, 2);
	assert_tri(0, 0, 1, 3);
	assert_tri(1, 1, 2, 3);
	/* the same rhombus from its second corner: now corners 1-3 are closer */
	assert_int_equal(parse("v 0 0 0\nv 2 -1 0\nv 4 0 0\nv 2 1 0\nf 2 3 4 1\n"), SKP_OK);
	assert_tri(0, 1, 2, 3);
	assert_tri(1, 1, 3, 0);
}

static void test_ngon_fan(void **state)
{
	(void)state;
	assert_int_equal(parse("v 1 0 0\nv 0.3 0.95 0\nv -0.8 0.6 0\nv -0.8 -0.6 0\nv 0.3 -0.95 0\n"
			       "f 1 2 3 4 5\n"), SKP_OK);
	assert_int_equal(m.tri_count, 3);
	assert_tri(0, 0, 1, 2);
	assert_tri(1, 0, 2, 3);
	assert_tri(2, 0, 3, 4);
	assert_int_equal(work.kept_faces, 1);
}

static void test_corner_forms(void **state)
{
	(void)state;
	const char *text =
		"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
		"vt 0 0\nvt 1 0\nvt 0 1\n"
		"vn 0 0 1\nvn 1 0 0\n"
		"f 1/1/1 2/2/1 3/3/1\n"
		"f 2//2 4//2 3//1\n";
	assert_int_equal(parse(text), SKP_OK);
	assert_int_equal(work.normals_from_file, 1);
	assert_int_equal(work.file_texcoords, 3);
	assert_tri(1, 1, 3, 2);
	assert_vec(m.normal[0], 0, 0, 1);
	/* two corners with (0,0,1) and (1,0,0): normalised sum */
	float h = sqrtf(0.5f);
	assert_vec(m.normal[1], h, 0, h);
	assert_vec(m.normal[2], 0, 0, 1);
	assert_vec(m.normal[3], 1, 0, 0);
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n"), SKP_OK);
	assert_vec(m.normal[0], 0, 0, 1);
}

static void test_negative_indices(void **state)
{
	(void)state;
	const char *text =
		"v 9 9 9\n"
		"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -1\nf -3//-1 -2//-1 -1//-1\n"
		"v 5 5 5\nf -5 -4 -1\n";
	assert_int_equal(parse(text), SKP_OK);
	assert_int_equal(m.vert_count, 5);
	assert_tri(0, 1, 2, 3);
	assert_tri(1, 0, 1, 4);
}

/* Vertex 1 is in a triangle of |cross| 4 along +Z and one of 1 along +Y. */
static void test_area_weighted_normals(void **state)
{
	(void)state;
	const char *text =
		"v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 1\nv 1 0 0\n"
		"f 1 2 3\nf 1 4 5\n";
	assert_int_equal(parse(text), SKP_OK);
	float k = 1.0f / sqrtf(17.0f);
	assert_vec(m.normal[0], 0, k, 4 * k);
	assert_vec(m.normal[1], 0, 0, 1);
	assert_vec(m.normal[3], 0, 1, 0);
}

/* Some corners without vn: the file's normals are not used at all. */
/* Tiny faces still get unit normals; a face of no area gives +Y. */
static void test_normals_degenerate(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\nv 1e-20 0 0\nv 0 1e-20 0\nv 5 5 5\nv 5 5 5\nv 5 5 5\n"
			       "f 1 2 3\nf 4 5 6\n"), SKP_OK);
	assert_vec(m.normal[0], 0, 0, 1);
	assert_vec(m.normal[4], 0, 1, 0);
	/* huge file normals are fine; opposite ones cancel: computed there */
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nvn 3e38 0 0\nvn -3e38 0 0\n"
			       "f 1//1 2//1 3//1\nf 1//2 3//2 4//2\n"), SKP_OK);
	assert_vec(m.normal[1], 1, 0, 0);
	assert_vec(m.normal[3], -1, 0, 0);
	assert_vec(m.normal[0], 0, 0, 1);
}

static void test_partial_normals_computed(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 0\nf 1//1 2 3\n"), SKP_OK);
	assert_int_equal(work.normals_from_file, 0);
	assert_vec(m.normal[0], 0, 0, 1);
}

static void test_crlf(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n"), SKP_OK);
	assert_int_equal(m.tri_count, 1);
	assert_vec(m.pos[2], 0, 1, 0);
	assert_int_not_equal(parse("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 x\r\n"), SKP_OK);
	assert_fails(SKP_ERR_SYNTAX, 4, "'x'");
}

static const char groups_text[] =
	"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 0 0\nv 2 1 0\n"
	"f 1 2 3\n"
	"g arm\nf 2 5 6\n"
	"g body arm\nf 2 4 3\n"
	"o thing\nf 4 5 6\n";

static void test_group_filter(void **state)
{
	(void)state;
	assert_int_equal(parse_opt(groups_text, "body", 0, 0), SKP_OK);
	assert_int_equal(m.vert_count, 3);
	assert_int_equal(m.tri_count, 1);
	assert_tri(0, 0, 2, 1);
	assert_int_equal(work.source[0], 1);
	assert_int_equal(work.source[1], 2);
	assert_int_equal(work.source[2], 3);
	assert_vec(m.pos[1], 0, 1, 0);
	assert_int_equal(work.file_faces, 4);
	assert_int_equal(work.kept_faces, 1);

	assert_int_equal(parse_opt(groups_text, "arm", 0, 0), SKP_OK);
	assert_int_equal(m.tri_count, 2);
	assert_int_equal(m.vert_count, 5);
	assert_tri(0, 0, 3, 4);     /* file 2 5 6 -> kept 1 2 3 4 5 6 minus 1 */
	assert_tri(1, 0, 2, 1);

	assert_int_equal(parse_opt(groups_text, "thing", 0, 0), SKP_OK);
	assert_int_equal(m.tri_count, 1);
	assert_int_equal(parse_opt(groups_text, "default", 0, 0), SKP_OK);
	assert_int_equal(m.tri_count, 1);
	assert_int_equal(work.source[2], 2);

	assert_int_equal(parse_opt(groups_text, "leg", 0, 0), SKP_ERR_RANGE);
	assert_true(strstr(err.msg, "no faces in group 'leg'") != NULL);
}

/* Group names are listed on terminals: their control characters kept as
 * \xNN, a repeated name counted once. */
static void test_group_names_escaped(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\ng bo\x1b[2Jdy\nf 1 2 3\ng bo\x1b[2Jdy\nf 1 3 2\n"), SKP_OK);
	assert_int_equal(work.group_count, 1);
	assert_string_equal(work.group[0].name, "bo\\x1b[2Jdy");
	assert_int_equal(work.group[0].faces, 2);
}

/* Without a filter every v is kept, used or not, in file order. */
static void test_unused_vertices_kept(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\nv 7 7 7\nv 1 0 0\nv 0 1 0\nf 1 3 4\n"), SKP_OK);
	assert_int_equal(m.vert_count, 4);
	assert_tri(0, 0, 2, 3);
	assert_int_equal(work.source[1], 1);
	assert_vec(m.normal[1], 0, 1, 0);
}

static void test_ignored_statements(void **state)
{
	(void)state;
	const char *text =
		"# made by hand\n"
		"mtllib skin.mtl\n"
		"\n"
		"   # indented comment\n"
		"v 0 0 0 1\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0  # trailing\n"
		"usemtl skin\ns 1\ns off\nl 1 2\np 3\nvp 0.5\n"
		"f\t1 2 3\n";
	assert_int_equal(parse(text), SKP_OK);
	assert_int_equal(m.vert_count, 3);
	assert_int_equal(m.tri_count, 1);
}

/* For the importer's materials (app/import/rig_obj_colour.h): the vt
 * coordinates, each triangle's corners' vt and usemtl, the first mtllib;
 * a material name with spaces is its words one space apart. */
static void test_materials_recorded(void **state)
{
	(void)state;
	assert_int_equal(parse("mtllib my lib.mtl\nmtllib other.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
			       "vn 0 0 1\nvt 0.25 0.5\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\nusemtl Hard  Shiny\nf 2/2 4 3/1\n"
			       "usemtl b\nf 1//1 2 3\nusemtl Hard Shiny\nf 1/-1 2/-2 3/-3\n"),
			 SKP_OK);
	assert_string_equal(work.mtllib, "my lib.mtl");
	assert_int_equal(work.mtl_count, 2);
	assert_string_equal(work.mtl_name[0], "Hard Shiny");
	assert_string_equal(work.mtl_name[1], "b");
	assert_int_equal(m.tri_count, 4);
	static const int16_t mtl[4] = { -1, 0, 1, 0 };
	static const int32_t vt[4][3] = { { 0, 1, 2 }, { 1, -1, 0 }, { -1, -1, -1 }, { 2, 1, 0 } };
	for (int t = 0; t < 4; t++) {
		assert_int_equal(work.tri_mtl[t], mtl[t]);
		for (int k = 0; k < 3; k++)
			assert_int_equal(work.tri_vt[t][k], vt[t][k]);
	}
	assert_true(work.vt[0][0] == 0.25f && work.vt[0][1] == 0.5f);
	/* a mesh without any: nothing recorded */
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), SKP_OK);
	assert_int_equal(work.mtllib[0], '\0');
	assert_int_equal(work.mtl_count, 0);
	assert_int_equal(work.tri_mtl[0], -1);
}

static void test_bad_number(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\nv 1 x 0\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 2, "expected a finite number, found 'x'");
	assert_int_equal(parse("vn 1 0 nan\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 1, "'vn'");
	assert_int_equal(parse("v 1 0 inf\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 1, "finite");
	/* finite as a double, not as the float a vertex holds */
	assert_int_equal(parse("v 1 0 1e308\n"), SKP_ERR_RANGE);
	assert_fails(SKP_ERR_RANGE, 1, "value '1e308' is beyond a float's range");
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3a\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 4, "expected a vertex index, found '3a'");
}

static void test_bad_indices(void **state)
{
	(void)state;
	const char *tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
	char text[256];
	snprintf(text, sizeof text, "%sf 0 1 2\n", tri);
	assert_int_equal(parse(text), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 4, "index 0");
	snprintf(text, sizeof text, "%sf 1 2 4\n", tri);
	assert_int_equal(parse(text), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 4, "vertex index 4 out of range (3 defined so far)");
	snprintf(text, sizeof text, "%sf -1 -2 -4\n", tri);
	assert_int_equal(parse(text), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 4, "vertex index -4 out of range");
	snprintf(text, sizeof text, "%svn 0 0 1\nf 1//1 2//2 3//1\n", tri);
	assert_int_equal(parse(text), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 5, "normal index 2 out of range");
	snprintf(text, sizeof text, "%sf 1/1 2/1 3/1\n", tri);
	assert_int_equal(parse(text), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 4, "texture index 1 out of range (0 defined so far)");
}

static void test_short_face_and_truncated_lines(void **state)
{
	(void)state;
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nf 1 2\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 3, "at least 3 corners, found 2");
	assert_int_equal(parse("v 0 0 0\nv 1 0"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 2, "'v' expects 3 to 7 numbers, found 2");
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2 3\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 4, "expected a texture index, found ''");
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1// 2 3\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 4, "expected a normal index");
	assert_int_equal(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 4, "more than two '/'");
	assert_int_equal(parse("v 0 0 0\nbogus 1 2\n"), SKP_ERR_SYNTAX);
	assert_fails(SKP_ERR_SYNTAX, 2, "unknown statement 'bogus'");
	assert_int_equal(parse("v 0 0 0\n"), SKP_ERR_RANGE);
	assert_true(strstr(err.msg, "no faces") != NULL);
}

static void test_limits(void **state)
{
	(void)state;
	const char *quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
	assert_int_equal(parse_opt(quad, NULL, 3, 0), SKP_ERR_LIMIT);
	assert_fails(SKP_ERR_LIMIT, 4, "more than 3 vertices (board limit SKP_MAX_VERTS)");
	assert_int_equal(parse_opt(quad, NULL, 0, 1), SKP_ERR_LIMIT);
	assert_fails(SKP_ERR_LIMIT, 5, "more than 1 triangles (board limit SKP_MAX_TRIS)");
	assert_int_equal(parse_opt(quad, NULL, 4, 2), SKP_OK);
	/* with a filter only the used vertices count, at the face using them */
	const char *grouped = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\ng a\nf 1 2 3\nf 1 3 4\n";
	assert_int_equal(parse_opt(grouped, "a", 3, 0), SKP_ERR_LIMIT);
	assert_fails(SKP_ERR_LIMIT, 7, "group 'a' uses more than 3 vertices (board limit SKP_MAX_VERTS)");
}

/* A long polygon is fine as long as its line fits SKP_MAX_LINE. */
static void test_long_polygon(void **state)
{
	(void)state;
	static char text[16384];
	size_t n = 0;
	int corners = 150;
	for (int i = 0; i < corners; i++) {
		double a = 2.0 * M_PI * i / corners;
		n += (size_t)snprintf(text + n, sizeof text - n, "v %.6f %.6f 0\n", cos(a), sin(a));
	}
	n += (size_t)snprintf(text + n, sizeof text - n, "f");
	for (int i = 1; i <= corners; i++)
		n += (size_t)snprintf(text + n, sizeof text - n, " %d", i);
	snprintf(text + n, sizeof text - n, "\n");
	assert_int_equal(parse(text), SKP_OK);
	assert_int_equal(m.tri_count, corners - 2);
	assert_vec(m.normal[17], 0, 0, 1);
}

static skp_status load_file(const char *path, const char *group, double *ms)
{
	static file_reader fr;
	obj_options opt = { group, 0, 0 };
	assert_int_equal(file_reader_open(&fr, path), 0);
	text_lines_init(&tl, file_reader_as_reader(&fr));
	uint64_t t0 = clock_now_ns();
	skp_status rc = obj_parse(&m, &work, &tl, &opt, &err);
	*ms = (double)(clock_now_ns() - t0) / 1e6;
	file_reader_close(&fr);
	return rc;
}

static void test_makehuman(void **state)
{
	(void)state;
	const char *path = test_data_path("mesh/makehuman/base.obj");
	if (!path)
		skip();
	double ms;
	assert_int_equal(load_file(path, "body", &ms), SKP_OK);
	print_message("base.obj, group body: %d vertices, %d triangles in %.1f ms\n",
		      m.vert_count, m.tri_count, ms);
	assert_int_equal(m.vert_count, 13380);
	assert_int_equal(m.tri_count, 26756);
	assert_int_equal(work.kept_faces, 13378);
	assert_int_equal(work.file_faces, 18486);
	assert_int_equal(work.file_texcoords, 21334);
	for (int i = 0; i < m.vert_count; i++)
		assert_int_equal(work.source[i], i);
	for (int i = 0; i < m.vert_count; i++)
		assert_true(fabsf(vec3_length(m.normal[i]) - 1.0f) < 1e-4f);

	assert_int_equal(load_file(path, NULL, &ms), SKP_OK);
	print_message("base.obj, all groups: %d vertices, %d triangles in %.1f ms\n",
		      m.vert_count, m.tri_count, ms);
	assert_int_equal(m.vert_count, 19158);
	assert_int_equal(m.tri_count, 2 * 18486);
	assert_vec(m.pos[0], -0.3492f, 7.3299f, 1.4076f);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_triangle),
		cmocka_unit_test(test_quad_short_diagonal),
		cmocka_unit_test(test_ngon_fan),
		cmocka_unit_test(test_corner_forms),
		cmocka_unit_test(test_negative_indices),
		cmocka_unit_test(test_area_weighted_normals),
		cmocka_unit_test(test_partial_normals_computed),
		cmocka_unit_test(test_normals_degenerate),
		cmocka_unit_test(test_crlf),
		cmocka_unit_test(test_group_filter),
		cmocka_unit_test(test_materials_recorded),
		cmocka_unit_test(test_group_names_escaped),
		cmocka_unit_test(test_unused_vertices_kept),
		cmocka_unit_test(test_ignored_statements),
		cmocka_unit_test(test_bad_number),
		cmocka_unit_test(test_bad_indices),
		cmocka_unit_test(test_short_face_and_truncated_lines),
		cmocka_unit_test(test_limits),
		cmocka_unit_test(test_long_polygon),
		cmocka_unit_test(test_makehuman),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
