/* The skinning kernels on hand-made cases with known answers: the DQBS
 * hemisphere fix, vertices without influence, rigid single influences,
 * normals, fixed point against float, and the synthetic scene's classic
 * artifacts (scene.h) with the metrics that measure them. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "skin.h"
#include "metrics.h"
#include "scene.h"

#define PI 3.14159265358979323846
#define MAXV 4096

static _Alignas(SKIN_ALIGN) unsigned char block[SKIN_SOA_BYTES(MAXV)];
static scene_rig sc;            /* its 2-bone skeleton and bind pose serve every case */
static mesh m;
static skin_weights w;
static skin_soa soa;
static skin_bones bones;
static float pos[3 * MAXV], nrm[3 * MAXV];
static int32_t fpos[3 * MAXV], fnrm[3 * MAXV];

/* Output of vertex v of the last run of algo, as double. */
static void result(skin_algo algo, int v, double p[3], double n[3])
{
	for (int k = 0; k < 3; k++) {
		p[k] = algo == SKIN_DQBS_FIXED ? fpos[3 * v + k] / 65536.0 : pos[3 * v + k];
		n[k] = algo == SKIN_DQBS_FIXED ? fnrm[3 * v + k] / 65536.0 : nrm[3 * v + k];
	}
}

static void run(skin_algo algo, const skel *s, const skel_pose *bind, const skel_pose *pose)
{
	skp_error err;
	assert_true(skin_soa_bytes(m.vert_count) <= sizeof block);
	skin_soa_attach(&soa, block, m.vert_count);
	assert_int_equal(skin_soa_load(&soa, &m, &w, s->count, &err), SKP_OK);
	skin_bones_compute(&bones, s, bind, pose);
	skin_out out = { pos, nrm, fpos, fnrm, NULL };
	skin_run(algo, &soa, &bones, 0, m.vert_count, &out);
}

static void add_vertex(vec3 p, vec3 n, int count, const int *bone, const float *weight)
{
	int v = m.vert_count++;
	m.pos[v] = p;
	m.normal[v] = n;
	w.count[v] = (uint8_t)count;
	for (int k = 0; k < count; k++) {
		w.bone[v][k] = (uint16_t)bone[k];
		w.weight[v][k] = weight[k];
	}
	w.vert_count = m.vert_count;
}

static void reset(void)
{
	m.vert_count = m.tri_count = 0;
	memset(&w, 0, sizeof w);
}

/* Scene pose: bone 1 turned by deg about axis (0 x, 1 y, 2 z) at its head. */
static void turn(int axis, double deg, skel_pose *out)
{
	*out = sc.bind;
	out->rot[1] = quat_from_basis_angle(axis, (float)(deg * PI / 180));
}

static double dist3(const double a[3], const double b[3])
{
	return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
		    (a[2] - b[2]) * (a[2] - b[2]));
}

static double len3(const double a[3])
{
	const double z[3] = { 0, 0, 0 };
	return dist3(a, z);
}

/* (x, r cos a, r sin a) with a in degrees */
static void about_x(double x, double r, double deg, double out[3])
{
	out[0] = x;
	out[1] = r * cos(deg * PI / 180);
	out[2] = r * sin(deg * PI / 180);
}

/* A 350 degree twist is a -10 degree one: DQBS must blend the short way
 * (to -5 degrees at equal weights), whichever influence is the pivot. */
static void test_antipodal_short_way(void **state)
{
	(void)state;
	skel_pose pose;
	turn(0, 350, &pose);
	assert_true(quat_dot(pose.rot[1], sc.bind.rot[1]) < 0); /* the hemispheres differ */
	reset();
	const int b01[2] = { 0, 1 }, b10[2] = { 1, 0 };
	const float half[2] = { 0.5f, 0.5f }, most[2] = { 0.7f, 0.3f };
	add_vertex(vec3_make(1, 0.2f, 0), vec3_make(0, 1, 0), 2, b01, half);
	add_vertex(vec3_make(1, 0.2f, 0), vec3_make(0, 1, 0), 2, b10, half);
	add_vertex(vec3_make(1, 0.2f, 0), vec3_make(0, 1, 0), 2, b01, most);
	add_vertex(vec3_make(1, 0.2f, 0), vec3_make(0, 1, 0), 2, b10, most);
	for (int a = SKIN_DQBS; a <= SKIN_DQBS_FIXED; a++) {
		run((skin_algo)a, &sc.skel, &sc.bind, &pose);
		double p[3], n[3], want[3], wn[3];
		about_x(1, 0.2, -5, want);
		about_x(0, 1, -5, wn);
		for (int v = 0; v < 2; v++) {
			result((skin_algo)a, v, p, n);
			assert_true(dist3(p, want) < 2e-5);
			assert_true(dist3(n, wn) < 2e-5);
		}
		/* unequal weights: between 0 and -10 degrees, never round the back */
		for (int v = 2; v < 4; v++) {
			result((skin_algo)a, v, p, n);
			double ang = atan2(p[2], p[1]) * 180 / PI;
			assert_true(fabs(len3((double[3]){ 0, p[1], p[2] }) - 0.2) < 2e-5);
			assert_true(v == 2 ? ang < -1 && ang > -5 : ang < -5 && ang > -9);
		}
	}
}

/* No influence: the vertex stays where it was bound, whatever the bones do. */
static void test_no_influence_stays(void **state)
{
	(void)state;
	skel_pose pose;
	turn(2, 70, &pose);
	pose.head[0] = pose.head[1] = vec3_make(3, -2, 1);
	reset();
	add_vertex(vec3_make(1.5f, 0.25f, -0.125f), vec3_make(0.6f, 0, 0.8f), 0, NULL, NULL);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		run((skin_algo)a, &sc.skel, &sc.bind, &pose);
		double p[3], n[3];
		result((skin_algo)a, 0, p, n);
		assert_true(dist3(p, (double[3]){ 1.5, 0.25, -0.125 }) < 2e-5);
		assert_true(dist3(n, (double[3]){ 0.6, 0, 0.8 }) < 2e-5);
	}
}

static void rotate_d(quat q, const double v[3], double out[3])
{
	double qw = q.w, x = q.x, y = q.y, z = q.z;
	double r[3][3] = {
		{ 1 - 2 * (y * y + z * z), 2 * (x * y - qw * z), 2 * (x * z + qw * y) },
		{ 2 * (x * y + qw * z), 1 - 2 * (x * x + z * z), 2 * (y * z - qw * x) },
		{ 2 * (x * z - qw * y), 2 * (y * z + qw * x), 1 - 2 * (x * x + y * y) },
	};
	for (int i = 0; i < 3; i++)
		out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
}

/* One influence of weight 1: the vertex moves rigidly with its bone (bind
 * rotations identity here, so R = G_pose, t = head_pose - R head_bind);
 * normals turn with it and stay unit. */
static void test_single_influence_rigid(void **state)
{
	(void)state;
	skel_pose pose = sc.bind;
	quat q = quat_normalize((quat){ 0.8f, 0.3f, -0.4f, 0.33f });
	pose.rot[1] = q;
	pose.head[1] = vec3_make(0.5f, 1.25f, -0.75f);
	reset();
	const int one[1] = { 1 };
	const float full[1] = { 1 };
	const double p0[3] = { 1.6, -0.15, 0.1 }, n0[3] = { 0, 0.6, -0.8 };
	add_vertex(vec3_make(1.6f, -0.15f, 0.1f), vec3_make(0, 0.6f, -0.8f), 1, one, full);
	double rel[3] = { p0[0] - 1, p0[1], p0[2] }, want[3], wn[3];
	rotate_d(q, rel, want);
	want[0] += 0.5; want[1] += 1.25; want[2] += -0.75;
	rotate_d(q, n0, wn);
	for (int a = 0; a < SKIN_ALGO_COUNT; a++) {
		run((skin_algo)a, &sc.skel, &sc.bind, &pose);
		double p[3], n[3];
		result((skin_algo)a, 0, p, n);
		double tol = a == SKIN_DQBS_FIXED ? 5 * 1.53e-5 : 1e-6; /* fixed: 5 Q16 steps */
		assert_true(dist3(p, want) < tol);
		assert_true(dist3(n, wn) < tol);
		assert_true(fabs(len3(n) - 1) < tol);
	}
}

static float frand(float lo, float hi)
{
	return lo + (hi - lo) * (float)rand() / (float)RAND_MAX;
}

static quat qrand(void)
{
	return quat_normalize((quat){ frand(-1, 1), frand(-1, 1), frand(-1, 1), frand(-1, 1) });
}

static void random_vertices(int bone_count)
{
	reset();
	for (int v = 0; v < 1000; v++) {
		int n = 1 + rand() % SKP_MAX_INFLUENCES, bone[SKP_MAX_INFLUENCES];
		float weight[SKP_MAX_INFLUENCES], sum = 0;
		for (int k = 0; k < n; k++) {
			bone[k] = rand() % bone_count;
			sum += weight[k] = frand(0.05f, 1);
		}
		for (int k = 0; k < n; k++)
			weight[k] /= sum;
		vec3 nn = vec3_normalize(vec3_make(frand(-1, 1), frand(-1, 1), frand(-1, 1) + 2));
		add_vertex(vec3_make(frand(-2, 2), frand(-2, 2), frand(-2, 2)), nn, n, bone, weight);
	}
}

/* Largest position and normal difference between float (pos, nrm) and
 * fixed point (fpos, fnrm); worst |n| - 1 of either. */
static void compare_fixed(const float *fp, const float *fn, double err[3])
{
	err[0] = err[1] = err[2] = 0;
	for (int v = 0; v < m.vert_count; v++) {
		double p[3], n[3], a[3] = { fp[3 * v], fp[3 * v + 1], fp[3 * v + 2] };
		double b[3] = { fn[3 * v], fn[3 * v + 1], fn[3 * v + 2] };
		result(SKIN_DQBS_FIXED, v, p, n);
		err[0] = fmax(err[0], dist3(p, a));
		err[1] = fmax(err[1], dist3(n, b));
		err[2] = fmax(err[2], fmax(fabs(len3(n) - 1), fabs(len3(b) - 1)));
	}
}

/* Random bind and posed bones (positions within 2 units, so skinned points
 * within about 7), random influences: fixed point agrees with float DQBS.
 * With the same (Q1.15) weights only the arithmetic differs: a few Q16
 * steps (up to 4x more where cancelling influences shrink the blend);
 * with the float weights, quantising them adds up to 2^-15 of the
 * spread between the influences' transforms. Every normal is unit. */
static void test_fixed_matches_float(void **state)
{
	(void)state;
	static skel s;
	static skel_pose bind, pose;
	memset(&s, 0, sizeof s);
	s.count = 8;
	srand(12345);
	for (int b = 0; b < s.count; b++) {
		bind.rot[b] = qrand();
		pose.rot[b] = qrand();
		bind.head[b] = vec3_make(frand(-2, 2), frand(-2, 2), frand(-2, 2));
		pose.head[b] = vec3_make(frand(-2, 2), frand(-2, 2), frand(-2, 2));
	}
	random_vertices(s.count);
	run(SKIN_DQBS_FIXED, &s, &bind, &pose);
	skin_out out = { pos, nrm, NULL, NULL, NULL };
	double err[3], same[3];
	skin_run(SKIN_DQBS, &soa, &bones, 0, m.vert_count, &out);
	compare_fixed(pos, nrm, err);
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		for (int v = 0; v < m.vert_count; v++)
			soa.weight[k][v] = soa.fweight[k][v] / 32768.0f;
	skin_run(SKIN_DQBS, &soa, &bones, 0, m.vert_count, &out);
	compare_fixed(pos, nrm, same);
	print_message("fixed vs float DQBS, 1000 random vertices on 8 random bones:\n"
		      "  same weights:  position %.3g, normal %.3g\n"
		      "  float weights: position %.3g, normal %.3g; worst |n| - 1: %.3g\n",
		      same[0], same[1], err[0], err[1], fmax(err[2], same[2]));
	assert_true(same[0] < 10 * 1.53e-5 && same[1] < 5e-5); /* 10 Q16 steps */
	assert_true(err[0] < 1e-3 && err[1] < 2e-4);
	assert_true(err[2] < 2e-5 && same[2] < 2e-5);
}

/* Runs the scene posed by kind/deg with algo and measures it. */
static metrics_radius scene_radius(scene_kind kind, double deg, skin_algo algo, double *vol)
{
	static skel_pose pose;
	static float xyz[3 * SCENE_VERTS], rest[SCENE_VERTS];
	static metrics_segments seg;
	m = sc.mesh;
	w = sc.weights;
	for (int v = 0; v < m.vert_count; v++) {
		xyz[3 * v] = m.pos[v].x; xyz[3 * v + 1] = m.pos[v].y; xyz[3 * v + 2] = m.pos[v].z;
	}
	double rest_vol = metrics_mesh_volume(xyz, (const uint32_t (*)[3])m.tri, m.tri_count);
	metrics_segments_from_pose(&seg, &sc.bind, 2);
	metrics_distances(&seg, xyz, m.vert_count, rest);
	scene_pose(&sc, kind, (float)(deg * PI / 180), &pose);
	run(algo, &sc.skel, &sc.bind, &pose);
	for (int i = 0; i < 3 * m.vert_count; i++)
		xyz[i] = algo == SKIN_DQBS_FIXED ? (float)fpos[i] / 65536.0f : pos[i];
	*vol = metrics_mesh_volume(xyz, (const uint32_t (*)[3])m.tri, m.tri_count) / rest_vol;
	metrics_segments_from_pose(&seg, &pose, 2);
	return metrics_radius_ratio(&seg, xyz, rest, m.vert_count, 1e-4f);
}

/* The scene's rest volume is that of a 48-gon prism of length 2; the cap
 * centres (on the bones) are not measured. */
static void test_scene_rest(void **state)
{
	(void)state;
	double vol;
	assert_int_equal(sc.mesh.vert_count, SCENE_VERTS);
	assert_int_equal(sc.mesh.tri_count, SCENE_TRIS);
	metrics_radius r = scene_radius(SCENE_TWIST, 0, SKIN_LBS, &vol);
	static float xyz[3 * SCENE_VERTS];
	for (int v = 0; v < m.vert_count; v++) {
		xyz[3 * v] = m.pos[v].x; xyz[3 * v + 1] = m.pos[v].y; xyz[3 * v + 2] = m.pos[v].z;
	}
	double prism = 2 * 0.5 * SCENE_SEGMENTS * 0.04 * sin(2 * PI / SCENE_SEGMENTS);
	double v0 = metrics_mesh_volume(xyz, (const uint32_t (*)[3])m.tri, m.tri_count);
	assert_true(fabs(v0 / prism - 1) < 1e-6);
	assert_true(fabs(vol - 1) < 1e-6);
	assert_int_equal(r.counted, SCENE_VERTS - 2);
	assert_true(fabs(r.min - 1) < 1e-5 && fabs(r.max - 1) < 1e-5);
}

/* LBS collapses the joint ring of a twist to |cos(a/2)| of its radius, a
 * point at 180 degrees; DQBS keeps the radius and the volume. */
static void test_scene_twist(void **state)
{
	(void)state;
	print_message("twist  angle  analytic LBS  LBS min radius  DQBS min radius  fixed min  LBS volume  DQBS volume\n");
	for (int deg = 45; deg <= 180; deg += 45) {
		double vl, vd, vf;
		metrics_radius l = scene_radius(SCENE_TWIST, deg, SKIN_LBS, &vl);
		metrics_radius d = scene_radius(SCENE_TWIST, deg, SKIN_DQBS, &vd);
		metrics_radius f = scene_radius(SCENE_TWIST, deg, SKIN_DQBS_FIXED, &vf);
		double analytic = fabs(cos(deg * PI / 360));
		print_message("       %5d  %12.6f  %14.6f  %15.6f  %9.6f  %10.6f  %11.6f\n", deg, analytic,
			      (double)l.min, (double)d.min, (double)f.min, vl, vd);
		assert_true(fabs(l.min - analytic) < 1e-4);
		assert_true(fabs(d.min - 1) < 1e-4 && fabs(d.max - 1) < 1e-4);
		assert_true(fabs(f.min - 1) < 1e-3 && fabs(f.max - 1) < 1e-3);
		assert_true(fabs(vd - 1) < 2e-3);
		assert_true(vl < vd);
	}
	double v;
	assert_true(scene_radius(SCENE_TWIST, 180, SKIN_LBS, &v).min < 1e-3);
	assert_true(scene_radius(SCENE_TWIST, 180, SKIN_DQBS, &v).min > 0.999);
}

/* Bending: LBS loses volume at the elbow, DQBS keeps it (and bulges). */
static void test_scene_bend(void **state)
{
	(void)state;
	print_message("bend   angle  LBS min radius  DQBS min radius  DQBS max radius  LBS volume  DQBS volume\n");
	for (int deg = 45; deg <= 180; deg += 45) {
		double vl, vd;
		metrics_radius l = scene_radius(SCENE_BEND, deg, SKIN_LBS, &vl);
		metrics_radius d = scene_radius(SCENE_BEND, deg, SKIN_DQBS, &vd);
		print_message("       %5d  %14.6f  %15.6f  %15.6f  %10.6f  %11.6f\n", deg, (double)l.min,
			      (double)d.min, (double)d.max, vl, vd);
		assert_true(vl < vd);
		assert_true(fabs(vd - 1) < 5e-3);
		if (deg < 180)
			assert_true(l.min < d.min);
	}
}

/* Distances to segments: the nearest bone, clamped to its ends; the root
 * (zero length) is no segment. */
static void test_segment_distance(void **state)
{
	(void)state;
	skel_pose p;
	memset(&p, 0, sizeof p);
	p.head[0] = p.tip[0] = vec3_make(5, 5, 5);
	p.head[1] = vec3_make(0, 0, 0); p.tip[1] = vec3_make(0, 2, 0);
	p.head[2] = vec3_make(0, 2, 0); p.tip[2] = vec3_make(2, 2, 0);
	metrics_segments g;
	metrics_segments_from_pose(&g, &p, 3);
	assert_int_equal(g.count, 2);
	assert_float_equal(metrics_segment_distance(&g, vec3_make(5, 5, 5)), sqrtf(9 + 9 + 25), 1e-5);
	assert_float_equal(metrics_segment_distance(&g, vec3_make(0.5f, 1, 0)), 0.5f, 1e-6);
	assert_float_equal(metrics_segment_distance(&g, vec3_make(0, -3, 4)), 5, 1e-6);
	assert_float_equal(metrics_segment_distance(&g, vec3_make(1, 2.25f, 0)), 0.25f, 1e-6);
}

static int setup(void **state)
{
	(void)state;
	scene_build(&sc);
	return 0;
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_antipodal_short_way),
		cmocka_unit_test(test_no_influence_stays),
		cmocka_unit_test(test_single_influence_rigid),
		cmocka_unit_test(test_fixed_matches_float),
		cmocka_unit_test(test_segment_distance),
		cmocka_unit_test(test_scene_rest),
		cmocka_unit_test(test_scene_twist),
		cmocka_unit_test(test_scene_bend),
	};
	return cmocka_run_group_tests_name("skin", tests, setup, NULL);
}
