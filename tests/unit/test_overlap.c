/* overlap_of_mesh on boxes whose overlap is known: none for one box, the
 * intersection for two that overlap (also turned to an odd angle), minus
 * the volume for a box turned inside out; and a full scratch reported. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>

#include "metrics.h"
#include "overlap.h"

#define GRID 256
#define MAX_HITS 200000

static float xyz[3 * 64];
static uint32_t tri[128][3];
static int verts, tris;
static int ray_start[GRID * GRID + 1];
static float hit_z[MAX_HITS];
static signed char hit_dir[MAX_HITS];
static const overlap_work work = { GRID, MAX_HITS, ray_start, hit_z, hit_dir };

static void reset(void)
{
	verts = tris = 0;
}

/* Two triangles of the quad a b c d, turned to face away from centre. */
static void add_face(const int q[4], const double centre[3])
{
	const float *a = xyz + 3 * q[0], *b = xyz + 3 * q[1], *c = xyz + 3 * q[2];
	double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
	double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
	double out = 0;
	for (int k = 0; k < 3; k++)
		out += n[k] * ((a[k] + c[k]) / 2 - centre[k]);
	int flip = out < 0;
	uint32_t t0[3] = { q[0], q[1], q[2] }, t1[3] = { q[0], q[2], q[3] };
	for (int k = 0; k < 3; k++) {
		tri[tris][k] = flip ? t0[2 - k] : t0[k];
		tri[tris + 1][k] = flip ? t1[2 - k] : t1[k];
	}
	tris += 2;
}

/* An axis-aligned box, outward (inside_out: inward) triangles. */
static void add_box(const double lo[3], const double hi[3], int inside_out)
{
	int base = verts;
	for (int c = 0; c < 8; c++) {
		xyz[3 * verts] = (float)(c & 1 ? hi[0] : lo[0]);
		xyz[3 * verts + 1] = (float)(c & 2 ? hi[1] : lo[1]);
		xyz[3 * verts + 2] = (float)(c & 4 ? hi[2] : lo[2]);
		verts++;
	}
	static const int faces[6][4] = { { 0, 2, 6, 4 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 },
					  { 2, 3, 7, 6 }, { 0, 1, 3, 2 }, { 4, 5, 7, 6 } };
	double centre[3];
	for (int k = 0; k < 3; k++)
		centre[k] = (lo[k] + hi[k]) / 2;
	int first = tris;
	for (int f = 0; f < 6; f++) {
		int q[4];
		for (int k = 0; k < 4; k++)
			q[k] = base + faces[f][k];
		add_face(q, centre);
	}
	if (inside_out)
		for (int t = first; t < tris; t++) {
			uint32_t s = tri[t][1];
			tri[t][1] = tri[t][2];
			tri[t][2] = s;
		}
}

/* Every vertex turned by angle about the unit axis (Rodrigues). */
static void rotate_all(const double axis[3], double angle)
{
	double c = cos(angle), s = sin(angle);
	for (int v = 0; v < verts; v++) {
		double p[3] = { xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2] };
		double d = axis[0] * p[0] + axis[1] * p[1] + axis[2] * p[2];
		double x[3] = { axis[1] * p[2] - axis[2] * p[1], axis[2] * p[0] - axis[0] * p[2],
				axis[0] * p[1] - axis[1] * p[0] };
		for (int k = 0; k < 3; k++)
			xyz[3 * v + k] = (float)(p[k] * c + x[k] * s + axis[k] * d * (1 - c));
	}
}

static double overlap(void)
{
	int ok;
	double e = overlap_of_mesh(xyz, verts, (const uint32_t (*)[3])tri, tris, &work, &ok);
	assert_true(ok);
	return e;
}

static double signed_volume(void)
{
	return metrics_mesh_volume(xyz, (const uint32_t (*)[3])tri, tris);
}

static void test_one_box_has_none(void **state)
{
	(void)state;
	reset();
	add_box((double[]){ 0, 0, 0 }, (double[]){ 2, 1, 3 }, 0);
	assert_true(fabs(signed_volume() - 6.0) < 1e-5);
	assert_true(fabs(overlap()) < 1e-9);
}

/* Boxes of 8 and 3 sharing [1,2]x[0.5,1.5]x[0.25,1.75]: 1.5 counted twice. */
static void two_boxes(void)
{
	reset();
	add_box((double[]){ 0, 0, 0 }, (double[]){ 2, 2, 2 }, 0);
	add_box((double[]){ 1, 0.5, 0.25 }, (double[]){ 3, 1.5, 1.75 }, 0);
}

static void test_two_boxes_overlap(void **state)
{
	(void)state;
	two_boxes();
	double e = overlap(), v = signed_volume();
	print_message("two boxes: signed %.4f, excess %.4f (exact 1.5), enclosed %.4f (exact 9.5)\n", v, e,
		      v - e);
	assert_true(fabs(v - 11.0) < 1e-4);
	assert_true(fabs(e - 1.5) < 0.02 * 1.5);
	const double axis[3] = { 0.48, 0.6, 0.64 };
	rotate_all(axis, 0.7);
	e = overlap();
	print_message("turned: excess %.4f\n", e);
	assert_true(fabs(e - 1.5) < 0.02 * 1.5);
}

static void test_inside_out_box_is_negative(void **state)
{
	(void)state;
	reset();
	add_box((double[]){ 0, 0, 0 }, (double[]){ 1, 2, 2 }, 1);
	double v = signed_volume(), e = overlap();
	assert_true(fabs(v + 4.0) < 1e-5);
	assert_true(fabs(e + 4.0) < 0.02 * 4.0); /* it encloses nothing */
}

static void test_scratch_too_small(void **state)
{
	(void)state;
	two_boxes();
	const overlap_work tiny = { GRID, 1000, ray_start, hit_z, hit_dir };
	int ok = 1;
	overlap_of_mesh(xyz, verts, (const uint32_t (*)[3])tri, tris, &tiny, &ok);
	assert_false(ok);
	overlap_of_mesh(xyz, 0, (const uint32_t (*)[3])tri, 0, &work, &ok);
	assert_false(ok);
}

/* A vertex blown up to nan (a degenerate skinning): its triangles are left
 * out, not spread over every ray. */
static void test_nan_vertex_left_out(void **state)
{
	(void)state;
	two_boxes();
	xyz[3 * 9] = NAN;
	int ok;
	double e = overlap_of_mesh(xyz, verts, (const uint32_t (*)[3])tri, tris, &work, &ok);
	assert_true(ok);
	assert_true(isfinite(e));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_one_box_has_none),
		cmocka_unit_test(test_two_boxes_overlap),
		cmocka_unit_test(test_inside_out_box_is_negative),
		cmocka_unit_test(test_scratch_too_small),
		cmocka_unit_test(test_nan_vertex_left_out),
	};
	return cmocka_run_group_tests_name("overlap", tests, NULL, NULL);
}
