/* Compact vertex streams: what quantising keeps. Normals through the
 * octahedral pair, positions within half a step of the bounds' grid,
 * weights summing to exactly 1 with the pivot first, bones as they were;
 * and a skinned position moves as the float one does. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "skin_compact.h"

#define N 4099

static mesh m;
static skin_weights w;
static skin_soa soa;
static skin_compact c;

static float frand(float lo, float hi)
{
	return lo + (hi - lo) * (float)rand() / (float)RAND_MAX;
}

/* random positions in a box from (-3, 10, -1) to (5, 190, 2), random unit
 * normals (the poles and the octahedron's edges among them), 1-4
 * influences on 40 bones */
static void build(void)
{
	static char soa_block[1 << 20] __attribute__((aligned(SKIN_ALIGN)));
	static char compact_block[1 << 18] __attribute__((aligned(SKIN_ALIGN)));
	static const vec3 edge[] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, -1, 0 }, { 0.70710678f, 0, -0.70710678f } };
	srand(11);
	m.vert_count = w.vert_count = N;
	for (int v = 0; v < N; v++) {
		m.pos[v] = vec3_make(frand(-3, 5), frand(10, 190), frand(-1, 2));
		m.normal[v] = v < 5 ? edge[v] : vec3_normalize(vec3_make(frand(-1, 1), frand(-1, 1), frand(-1, 1)));
		int n = 1 + v % SKP_MAX_INFLUENCES;
		float sum = 0;
		for (int k = 0; k < n; k++) {
			w.bone[v][k] = (uint16_t)(rand() % 40);
			sum += w.weight[v][k] = frand(0.01f, 1);
		}
		for (int k = 0; k < n; k++)
			w.weight[v][k] /= sum;
		w.count[v] = (uint8_t)n;
	}
	assert_true(skin_soa_bytes(N) <= sizeof soa_block && skin_compact_bytes(N) <= sizeof compact_block);
	skin_soa_attach(&soa, soa_block, N);
	skp_error err;
	assert_int_equal(skin_soa_load(&soa, &m, &w, 40, &err), SKP_OK);
	skin_compact_attach(&c, compact_block, N);
	skin_compact_load(&c, &soa);
}

static void test_streams_keep_the_mesh(void **state)
{
	(void)state;
	build();
	float bound = skin_compact_position_bound(&c), worst_p = 0, worst_n = 0;
	for (int v = 0; v < N; v++) {
		vec3 p = vec3_make(c.origin[0] + c.qx[v] * c.step[0], c.origin[1] + c.qy[v] * c.step[1],
				   c.origin[2] + c.qz[v] * c.step[2]);
		worst_p = fmaxf(worst_p, vec3_length(vec3_sub(p, m.pos[v])));
		vec3 n = vec3_normalize(skin_oct_decode(c.ox[v], c.oy[v]));
		worst_n = fmaxf(worst_n, vec3_length(vec3_sub(n, m.normal[v])));
		unsigned sum = 0;
		for (int k = 0; k < SKP_MAX_INFLUENCES - 1; k++) {
			sum += c.weight[k][v];
			assert_true(fabsf(c.weight[k][v] / 65535.0f - soa.weight[k + 1][v]) <= 0.5f / 65535.0f + 1e-7f);
		}
		assert_true(sum <= SKIN_COMPACT_WEIGHT_ONE);
		assert_true(SKIN_COMPACT_WEIGHT_ONE - sum >= c.weight[0][v]); /* the pivot stays the largest */
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
			assert_int_equal(c.bone[k][v], soa.bone[k][v]);
	}
	print_message("%d vertices: positions within %.3g (bound %.3g, box 8 x 180 x 3), normals within %.3g\n", N,
		      (double)worst_p, (double)bound, (double)worst_n);
	assert_true(worst_p <= bound + 2 * 190.0f * FLT_EPSILON); /* plus the decode's float rounding */
	assert_true(bound < 180.0f / 65535.0f);
	assert_true(worst_n < 5e-5f);
	/* the padding takes the identity slot with the whole weight */
	for (int v = N; v < c.padded; v++)
		assert_int_equal(c.bone[0][v], SKIN_IDENTITY_BONE);
}

/* A flat axis (every vertex at one height) has step 0 and decodes exactly. */
static void test_flat_axis(void **state)
{
	(void)state;
	build();
	for (int v = 0; v < N; v++)
		soa.py[v] = 7.25f;
	skin_compact_load(&c, &soa);
	assert_true(c.step[1] == 0.0f && c.origin[1] == 7.25f);
	for (int v = 0; v < N; v++)
		assert_int_equal(c.qy[v], 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_streams_keep_the_mesh),
		cmocka_unit_test(test_flat_axis),
	};
	return cmocka_run_group_tests_name("skin_compact", tests, NULL, NULL);
}
