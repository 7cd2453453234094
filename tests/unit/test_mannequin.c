/* The generated body: closed, 2-manifold, outward, human-sized, fast; and
 * the skintool mannequin command end to end. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "clock.h"
#include "file_reader.h"
#include "mannequin.h"
#include "mesh_normals.h"
#include "obj.h"
#include "test_parse.h"
#include "test_paths.h"

static skel s;
static manq_work work;
static mesh body, faces;
static uint64_t edges[3 * SKP_MAX_TRIS];

static int cmp_u64(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
	return x < y ? -1 : x > y;
}

/* Each directed edge once and its reverse present: every undirected edge
 * is in exactly two triangles, which run along it in opposite directions. */
static void assert_closed_manifold(const mesh *m)
{
	size_t n = 0;
	for (int t = 0; t < m->tri_count; t++)
		for (int j = 0; j < 3; j++) {
			uint64_t a = m->tri[t][j], b = m->tri[t][(j + 1) % 3];
			assert_true(a != b && a < (uint64_t)m->vert_count);
			edges[n++] = a << 32 | b;
		}
	qsort(edges, n, sizeof edges[0], cmp_u64);
	for (size_t i = 0; i < n; i++) {
		if (i + 1 < n && edges[i] == edges[i + 1])
			fail_msg("edge %llu-%llu used twice in one direction",
				 (unsigned long long)(edges[i] >> 32), (unsigned long long)(edges[i] & 0xffffffffu));
		uint64_t rev = (edges[i] & 0xffffffffu) << 32 | edges[i] >> 32;
		if (!bsearch(&rev, edges, n, sizeof edges[0], cmp_u64))
			fail_msg("edge %llu-%llu has no opposite",
				 (unsigned long long)(edges[i] >> 32), (unsigned long long)(edges[i] & 0xffffffffu));
	}
}

/* Divergence theorem: the sum of signed tetrahedra to the origin. */
static double volume(const mesh *m)
{
	double v = 0.0;
	for (int t = 0; t < m->tri_count; t++) {
		vec3 a = m->pos[m->tri[t][0]], b = m->pos[m->tri[t][1]], c = m->pos[m->tri[t][2]];
		v += (double)vec3_dot(a, vec3_cross(b, c)) / 6.0;
	}
	return v;
}

static void rest_extent_y(const skel *sk, float *lo, float *hi)
{
	skel_pose *p = &work.rest;
	fk_pose(sk, NULL, p);
	*lo = *hi = p->tip[0].y;
	for (int b = 1; b < sk->count; b++) {
		*lo = fminf(*lo, fminf(p->head[b].y, p->tip[b].y));
		*hi = fmaxf(*hi, fmaxf(p->head[b].y, p->tip[b].y));
	}
}

static float segment_distance(vec3 p, vec3 a, vec3 b, vec3 *closest)
{
	vec3 ab = vec3_sub(b, a);
	float len2 = vec3_dot(ab, ab);
	float t = len2 > 0.0f ? vec3_dot(vec3_sub(p, a), ab) / len2 : 0.0f;
	t = t < 0.0f ? 0.0f : t > 1.0f ? 1.0f : t;
	*closest = vec3_madd(a, ab, t);
	return vec3_length(vec3_sub(p, *closest));
}

/* Normals are unit, agree with the faces' and point away from the
 * nearest bone (a vertex in a crease may see another bone first). */
static void assert_normals_outward(const skel *sk, const mesh *m)
{
	faces.vert_count = m->vert_count;
	faces.tri_count = m->tri_count;
	memcpy(faces.pos, m->pos, sizeof faces.pos[0] * (size_t)m->vert_count);
	memcpy(faces.tri, m->tri, sizeof faces.tri[0] * (size_t)m->tri_count);
	mesh_compute_normals(&faces);
	fk_pose(sk, NULL, &work.rest);
	int agree = 0, away = 0;
	for (int i = 0; i < m->vert_count; i++) {
		assert_true(fabsf(vec3_length(m->normal[i]) - 1.0f) < 1e-3f);
		agree += vec3_dot(m->normal[i], faces.normal[i]) > 0.0f;
		float best = INFINITY;
		vec3 near = m->pos[i];
		for (int b = 1; b < sk->count; b++) {
			vec3 c;
			float d = segment_distance(m->pos[i], work.rest.head[b], work.rest.tip[b], &c);
			if (d < best)
				best = d, near = c;
		}
		away += vec3_dot(m->normal[i], vec3_sub(m->pos[i], near)) > 0.0f;
	}
	print_message("  normals: %.2f%% agree with the faces, %.2f%% point away from the nearest bone\n",
		      100.0 * agree / m->vert_count, 100.0 * away / m->vert_count);
	assert_true(agree >= m->vert_count * 0.995);
	assert_true(away >= m->vert_count * 0.95);
}

static void check_skeleton(const char *rel)
{
	const char *path = test_data_path(rel);
	if (!path)
		skip();
	skp_error err;
	assert_int_equal(test_parse_asf_file(path, &s, &err), SKP_OK);
	uint64_t t0 = clock_now_ns();
	assert_int_equal(manq_build(&s, 0, &work, &body, &err), SKP_OK);
	double ms = (double)(clock_now_ns() - t0) / 1e6;
	print_message("%s: %d vertices, %d triangles in %.1f ms\n", rel, body.vert_count, body.tri_count, ms);

	assert_true(body.vert_count >= 2000);
	assert_closed_manifold(&body);
	assert_true(volume(&body) > 0.0);
	float lo, hi, mlo = INFINITY, mhi = -INFINITY;
	rest_extent_y(&s, &lo, &hi);
	for (int i = 0; i < body.vert_count; i++) {
		mlo = fminf(mlo, body.pos[i].y);
		mhi = fmaxf(mhi, body.pos[i].y);
	}
	print_message("  height %.4g (skeleton %.4g), volume %.4g\n", mhi - mlo, hi - lo, volume(&body));
	assert_true(fabsf((mhi - mlo) - (hi - lo)) <= 0.1f * (hi - lo));
	assert_normals_outward(&s, &body);
}

static void test_cmu(void **state)
{
	(void)state;
	check_skeleton("mocap/cmu/02.asf");
}

static void test_hdm05(void **state)
{
	(void)state;
	check_skeleton("mocap/hdm05/HDM_dg.asf");
}

static void test_endorphin(void **state)
{
	(void)state;
	check_skeleton("mocap/endorphin/skeleton.asf");
}

static const char tiny_root[] =
	":root\n order TX TY TZ RX RY RZ\n axis XYZ\n position 0 0 0\n orientation 0 0 0\n";

/* Coarse grids, a flat two-bone arm and a lone point bone stay closed. */
static void test_small_and_odd(void **state)
{
	(void)state;
	skp_error err;
	char text[1024];
	snprintf(text, sizeof text, "%s:bonedata\n begin\n name a\n direction 1 0 0\n length 2\n end\n"
		 " begin\n name b\n direction 0 0 1\n length 0\n end\n"
		 ":hierarchy\n begin\n root a\n a b\n end\n", tiny_root);
	assert_int_equal(test_parse_asf(text, strlen(text), &s, &err), SKP_OK);
	for (int detail = MANQ_MIN_DETAIL; detail <= 40; detail += 16) {
		if (manq_build(&s, detail, &work, &body, &err) != SKP_OK)
			fail_msg("detail %d: %s", detail, err.msg);
		assert_closed_manifold(&body);
		assert_true(volume(&body) > 0.0);
	}
	const char *cmu = test_data_path("mocap/cmu/02.asf");
	if (cmu) {
		assert_int_equal(test_parse_asf_file(cmu, &s, &err), SKP_OK);
		assert_int_equal(manq_build(&s, MANQ_MIN_DETAIL, &work, &body, &err), SKP_OK);
		assert_closed_manifold(&body);
		assert_int_equal(manq_build(&s, 24, &work, &body, &err), SKP_OK);
		assert_closed_manifold(&body);
	}
}

static void test_errors(void **state)
{
	(void)state;
	skp_error err;
	assert_int_equal(test_parse_asf(tiny_root, strlen(tiny_root), &s, &err), SKP_OK);
	assert_int_equal(manq_build(&s, 0, &work, &body, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "no bones"));

	char text[512];
	snprintf(text, sizeof text, "%s:bonedata\n begin\n name a\n direction 1 0 0\n length 0\n end\n"
		 ":hierarchy\n begin\n root a\n end\n", tiny_root);
	assert_int_equal(test_parse_asf(text, strlen(text), &s, &err), SKP_OK);
	assert_int_equal(manq_build(&s, 0, &work, &body, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "no extent"));

	assert_int_equal(manq_build(&s, MANQ_MIN_DETAIL - 1, &work, &body, &err), SKP_ERR_RANGE);
	assert_non_null(strstr(err.msg, "detail 7 is outside 8..256"));
	assert_int_equal(manq_build(&s, MANQ_MAX_DETAIL + 1, &work, &body, &err), SKP_ERR_RANGE);

	const char *cmu = test_data_path("mocap/cmu/02.asf");
	if (!cmu)
		return;
	assert_int_equal(test_parse_asf_file(cmu, &s, &err), SKP_OK);
	assert_int_equal(manq_build(&s, MANQ_MAX_DETAIL, &work, &body, &err), SKP_ERR_LIMIT);
	assert_non_null(strstr(err.msg, "SKP_MAX_VERTS"));
}

static int run(const char *args, char **err_text)
{
	char cmd[1024], err_path[] = "/tmp/skp_manq_XXXXXX";
	int fd = mkstemp(err_path);
	assert_true(fd >= 0);
	snprintf(cmd, sizeof cmd, "%s mannequin %s >/dev/null 2>%s", test_tool_path("skintool"), args, err_path);
	int status = system(cmd);
	*err_text = test_read_file(err_path, NULL);
	unlink(err_path);
	close(fd);
	assert_non_null(*err_text);
	assert_true(WIFEXITED(status));
	return WEXITSTATUS(status);
}

static void expect_failure(const char *args, const char *want_start)
{
	char *e;
	int rc = run(args, &e);
	if (rc != 1 || strncmp(e, want_start, strlen(want_start)) != 0)
		fail_msg("mannequin %s: exit %d, stderr '%s'", args, rc, e);
	free(e);
}

/* The command writes an OBJ the importer reads back unchanged. */
static void test_command(void **state)
{
	(void)state;
	const char *asf = test_data_path("mocap/endorphin/skeleton.asf");
	if (!asf || access(test_tool_path("skintool"), X_OK) != 0)
		skip();
	char out[] = "/tmp/skp_manq_obj_XXXXXX", args[1200];
	int fd = mkstemp(out);
	assert_true(fd >= 0);
	close(fd);
	snprintf(args, sizeof args, "%s -o %s --detail 40", asf, out);
	char *e;
	assert_int_equal(run(args, &e), 0);
	free(e);

	static obj_work ow;
	static file_reader fr;
	static text_lines tl;
	skp_error err;
	assert_int_equal(file_reader_open(&fr, out), 0);
	text_lines_init(&tl, file_reader_as_reader(&fr));
	assert_int_equal(obj_parse(&faces, &ow, &tl, NULL, &err), SKP_OK);
	file_reader_close(&fr);
	unlink(out);
	assert_int_equal(ow.normals_from_file, 1);
	assert_int_equal(test_parse_asf_file(asf, &s, &err), SKP_OK);
	assert_int_equal(manq_build(&s, 40, &work, &body, &err), SKP_OK);
	assert_int_equal(faces.vert_count, body.vert_count);
	assert_int_equal(faces.tri_count, body.tri_count);
	for (int i = 0; i < body.vert_count; i++)
		assert_true(vec3_length(vec3_sub(faces.pos[i], body.pos[i])) < 1e-5f);

	expect_failure("tests/data/bad/truncated.asf -o /tmp/skp_never.obj", "tests/data/bad/truncated.asf:20:");
	expect_failure("tests/data/tiny.asf", "skintool mannequin: give SKELETON and -o BODY.obj");
	expect_failure("tests/data/tiny.asf -o /tmp/skp_never.obj --detail 3", "skintool mannequin: --detail");
	expect_failure("tests/data/tiny.asf -o /nonexistent/dir/x.obj", "/nonexistent/dir/x.obj: cannot create");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cmu),
		cmocka_unit_test(test_hdm05),
		cmocka_unit_test(test_endorphin),
		cmocka_unit_test(test_small_and_odd),
		cmocka_unit_test(test_errors),
		cmocka_unit_test(test_command),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
