#include "emb_stress.h"

#include <string.h>

#include "emb_hash.h"
#include "fixed.h"

/* Stress: the fixed kernel on made-up inputs meant to reach every path
 * of every board's arithmetic (on a Cortex-M0 the split sums of
 * skin_fixed.c and fixed_move.c, elsewhere 64-bit multiply-adds; in both
 * the sign test left to the exact dot, saturation, the definition taken
 * again when a fast path gives up): near-unit and arbitrary quaternions,
 * bones a quarter turn apart, translations and positions near the
 * format's ends, weights summing to 1 and past it; rotations within
 * fx_quat_dot's domain. The same LCG on every
 * board, so the checksums must be equal. */
#define STRESS_VERTS 64
#define STRESS_ROUNDS 48

static uint32_t lcg_state;

static uint32_t lcg(void)
{
	lcg_state = lcg_state * 1664525u + 1013904223u;
	return lcg_state ^ (lcg_state >> 15);
}

/* A value in [-range, range] (range < 2^31), or any int32 for range 0. */
static int32_t lcg_in(uint32_t range)
{
	uint32_t u = lcg();
	return range ? (int32_t)(u % (2 * range + 1)) - (int32_t)range : (int32_t)u;
}

static void stress_bones(int mode, int bone_count)
{
	/* rotations within fx_quat_dot's domain (shorter than 2: its int64
	 * sums would wrap past it) */
	const uint32_t rot = (1u << 30) - 1, dual = mode == 1 ? 0 : mode == 3 ? (1u << 31) - 1 : 1u << 26;
	emb_bones.count = bone_count;
	for (int b = 0; b <= bone_count; b++) {
		fx_dq d = { { lcg_in(rot), lcg_in(rot), lcg_in(rot), lcg_in(rot) },
			    { lcg_in(dual), lcg_in(dual), lcg_in(dual), lcg_in(dual) } };
		if (mode == 2) { /* a quarter turn from bone 0, give or take 2^-20 */
			fx_quat q = { lcg_in(1024), (int32_t)(1 << 30) + lcg_in(1024), lcg_in(1024), lcg_in(1024) };
			if (b > 0 && b % 2)
				d.real = q;
			else
				d.real = (fx_quat){ (int32_t)(1 << 30) + lcg_in(1024), lcg_in(1024), lcg_in(1024), lcg_in(1024) };
		}
		emb_bones.fdq[b == bone_count ? SKIN_IDENTITY_BONE : b] = d;
	}
	if (mode == 3) {
		/* bone 2 opposite bone 1 with a dual component at INT32_MIN:
		 * stress_vertex's vertex 0 (all its weight on bone 2, pivot bone
		 * 1) negates it, and the blend's exact sum, 2^46, leaves int32:
		 * the definition saturates it, and the kernels of skin_fixed.c
		 * must hand that vertex to the definition */
		fx_dq *o = &emb_bones.fdq[2];
		const fx_quat *r = &emb_bones.fdq[1].real;
		o->real = (fx_quat){ -r->w, -r->x, -r->y, -r->z };
		o->dual.x = INT32_MIN;
		/* the same overflow where nothing after the blend would catch a
		 * blend that wrapped instead (vertices 1 and 2): bone 3 nearly a half
		 * turn about x (w 0.2, y = z = 0), so the dual's x moves the
		 * point by 0.4 of it and the move fits either way; -2^31 for
		 * the definition's 2^31 - 1 lands 2^32 x 0.4 LSB away */
		emb_bones.fdq[3] = (fx_dq){ { 214748365, 1052047834, 0, 0 }, { 0, 0, 0, 0 } };
		emb_bones.fdq[4] = (fx_dq){ { -214748365, -1052047834, 0, 0 }, { 0, INT32_MIN, 0, 0 } };
	}
	skin_bones_derive(&emb_bones);
}

static int32_t st_p[6][STRESS_VERTS];
static uint16_t st_bone[SKP_MAX_INFLUENCES][STRESS_VERTS], st_w[SKP_MAX_INFLUENCES][STRESS_VERTS];

static void stress_vertex(int v, int mode, int bone_count)
{
	const uint32_t pos = mode == 3 ? 0 : 1u << 27;
	for (int i = 0; i < 3; i++) {
		st_p[i][v] = lcg_in(pos);
		st_p[3 + i][v] = lcg_in(1u << 30);
	}
	uint32_t left = FX_W15_ONE + (lcg() % 8 == 0 ? lcg() % 40000 : 0); /* past 1 now and then */
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		uint32_t w = k == SKP_MAX_INFLUENCES - 1 ? left : lcg() % (left + 1);
		w = w > 65535 ? 65535 : w;
		st_w[k][v] = (uint16_t)w;
		left -= w < left ? w : left;
		st_bone[k][v] = (uint16_t)(lcg() % 9 == 0 ? SKIN_IDENTITY_BONE : lcg() % bone_count);
	}
	if (mode == 3 && v <= 1) /* see stress_bones */
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			st_w[k][v] = k == 1 ? FX_W15_ONE : 0;
			st_bone[k][v] = (uint16_t)(k == 1 ? 2 + 2 * v : 1 + 2 * v);
		}
	if (mode == 3 && v == 2) /* vertex 1's blend over three slots (the 4-slot sums) */
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			st_w[k][v] = (uint16_t)(k == 0 ? 0 : k == 1 ? FX_W15_ONE / 2 : FX_W15_ONE / 4);
			st_bone[k][v] = (uint16_t)(k == 0 ? 3 : 4);
		}
}

uint32_t emb_stress_checksum(int bone_count)
{
	skin_soa s;
	fnv f = { EMB_FNV_START };
	lcg_state = 12345u;
	memset(&s, 0, sizeof s);
	s.count = s.padded = STRESS_VERTS;
	s.fpx = st_p[0]; s.fpy = st_p[1]; s.fpz = st_p[2];
	s.fnx = st_p[3]; s.fny = st_p[4]; s.fnz = st_p[5];
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		s.bone[k] = st_bone[k];
		s.fweight[k] = st_w[k];
	}
	for (int round = 0; round < STRESS_ROUNDS; round++) {
		stress_bones(round % 4, bone_count);
		for (int v = 0; v < STRESS_VERTS; v++)
			stress_vertex(v, round % 4, bone_count);
		emb_skin_hash(&s, &f);
	}
	return f.h;
}

