/* DQBS in fixed point: integer arithmetic only (checked by
 * tests/check_fixed_integer.sh). Output is Q16.16, which is GL_FIXED.
 *
 * This is the reference every fixed kernel matches bit for bit, and the
 * kernel of the boards without SIMD: the Cortex-M0 and M4 run it. So its
 * blend avoids 64-bit arithmetic where it can (a Cortex-M0 has no 32 x 32
 * -> 64 multiply at all): fx_dq_blend's exact sums, from 32-bit ones. */
#include "skin_kernels.h"

_Static_assert(FX_POS_FRAC <= 16, "positions are written as Q16.16");

/* fx_shr_round(v, 14) in 32 bits: v = q 2^14 + r rounds to q + (r >= 2^13). */
static int32_t q30_to_q16(fx_q30 v)
{
	return (v >> 14) + ((v >> 13) & 1);
}

static int32_t pos_to_q16(fx_pos v)
{
	return (int32_t)((int64_t)v * (1 << (16 - FX_POS_FRAC)));
}

#if FX_NARROW_MUL
/* fx_dq_blend's sums, split at bit 16: every component c of a bone's dq
 * is hi 2^16 + lo (hi = c >> 16 signed, lo in [0, 2^16): the rows of
 * skin_bones.fdq_split), so sum w c = 2^16 H + L with H = sum w hi and
 * L = sum w lo. With weights (negated or not) whose magnitudes add up to
 * at most 2^15, |H| <= 2^30 and |L| < 2^31: both fit int32, as each
 * product does. And fx_shr_round(2^16 H + L, 15) = 2 H + (L + 2^14) >>
 * 15, 2^16 H being a multiple of 2^15. One component of four influences,
 * split rows q[k] weighted w[k]: */
static int32_t blend_component(const int32_t *const q[4], const int32_t w[4], int c)
{
	int32_t h = w[0] * q[0][c] + w[1] * q[1][c] + w[2] * q[2][c] + w[3] * q[3][c];
	int32_t l = w[0] * q[0][8 + c] + w[1] * q[1][8 + c] + w[2] * q[2][8 + c] + w[3] * q[3][8 + c];
	int32_t t = (l + (1 << 14)) >> 15; /* |t| <= 2^16 */
	if (h > -(1 << 30) + (1 << 16) && h < (1 << 30) - (1 << 16))
		return 2 * h + t; /* cannot leave int32 */
	return fx_sat32(2 * (int64_t)h + t);
}

static const int32_t *row(const skin_bones *b, int bone)
{
	return &b->fdq_split[bone][0][0];
}
#else
/* Where a 32 x 32 -> 64 multiply-add is one instruction: fx_dq_blend's
 * sum itself, rounding included. */
static int32_t blend_component(const int32_t *const q[4], const int32_t w[4], int c)
{
	return fx_sat32(((int64_t)(1 << 14) + fx_mul_wide(w[0], q[0][c]) + fx_mul_wide(w[1], q[1][c]) +
			 fx_mul_wide(w[2], q[2][c]) + fx_mul_wide(w[3], q[3][c])) >> 15);
}

static const int32_t *row(const skin_bones *b, int bone)
{
	return &b->fdq[bone].real.w;
}
#endif

#if FX_NARROW_MUL
/* fx_quat_dot(a, p) < 0 (1 or 0), decided from the products of the high
 * halves where they are clear, else -1. The low halves move the dot by
 * less than 2^32 (sum |a hi| + sum |p hi| + 4) <= 2^32 (2^18 + 4), so
 * beyond that the high halves' sum A (the dot in units of 2^32) has its
 * sign. A is taken as 4 B + e, B the sum of the products shifted right by
 * 2 (each below 2^28 in magnitude: B fits int32) and e in [0, 12]. For
 * unit quaternions only bones within a thousandth of opposite rotations
 * are left undecided. */
static int opposite(const int32_t *a, const int32_t *p) /* the rows' high halves */
{
	const int32_t bound = (1 << 18) + 4; /* a multiple of 4 */
	int32_t b = (a[0] * p[0] >> 2) + (a[1] * p[1] >> 2) + (a[2] * p[2] >> 2) + (a[3] * p[3] >> 2);
	return b >= bound / 4 ? 0 : b <= (-bound - 12) / 4 ? 1 : -1;
}
#else
static int opposite(const int32_t *a, const int32_t *p)
{
	(void)a;
	(void)p;
	return -1; /* the exact dot costs as little */
}
#endif

/* fx_dq_blend's weights with its sign fix: negated where the bone's real
 * part has a negative dot product with the pivot's. An unused slot
 * (weight 0) needs no test. */
static void signed_weights(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES],
			   const int32_t *const rows[SKP_MAX_INFLUENCES], const fx_w15 w[SKP_MAX_INFLUENCES],
			   int32_t sw[SKP_MAX_INFLUENCES])
{
	sw[0] = w[0];
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		int flip = w[k] ? opposite(rows[k], rows[0]) : 0;
		if (flip < 0)
			flip = fx_quat_dot(b->fdq[idx[k]].real, b->fdq[idx[0]].real) < 0;
		sw[k] = flip ? -(int32_t)w[k] : (int32_t)w[k];
	}
}

/* fx_dq_blend(b->fdq, idx, w, 4, pivot) for weights summing to at most 1;
 * 0 (and d untouched) when they do not. */
static int blend(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES], const fx_w15 w[SKP_MAX_INFLUENCES],
		 fx_dq *d)
{
	_Static_assert(SKP_MAX_INFLUENCES == 4 && sizeof(fx_dq) == 8 * sizeof(int32_t), "a row of 8 int32");
	if ((uint32_t)w[0] + w[1] + w[2] + w[3] > FX_W15_ONE)
		return 0;
	const int32_t *const rows[4] = { row(b, idx[0]), row(b, idx[1]), row(b, idx[2]), row(b, idx[3]) };
	int32_t sw[4], r[8];
	signed_weights(b, idx, rows, w, sw);
	for (int c = 0; c < 8; c++) /* one call site: inlined */
		r[c] = blend_component(rows, sw, c);
	fx_dq out = { { r[0], r[1], r[2], r[3] }, { r[4], r[5], r[6], r[7] } };
	*d = out;
	return 1;
}

void skin_dqbs_fixed(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v++) {
		uint16_t idx[SKP_MAX_INFLUENCES];
		fx_w15 w[SKP_MAX_INFLUENCES];
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			idx[k] = in->bone[k][v];
			w[k] = in->fweight[k][v];
		}
		fx_dq d;
		if (!blend(b, idx, w, &d))
			d = fx_dq_blend(b->fdq, idx, w, SKP_MAX_INFLUENCES, b->fdq[idx[0]].real);
		fx_vec3 p = { in->fpx[v], in->fpy[v], in->fpz[v] };
		fx_vec3 n = { in->fnx[v], in->fny[v], in->fnz[v] };
		fx_vec3 pp, nn;
		fx_dq_transform_blend(&d, p, n, &pp, &nn);
		int32_t *po = out->fpos + 3 * v, *no = out->fnrm + 3 * v;
		po[0] = pos_to_q16(pp.x); po[1] = pos_to_q16(pp.y); po[2] = pos_to_q16(pp.z);
		no[0] = q30_to_q16(nn.x); no[1] = q30_to_q16(nn.y); no[2] = q30_to_q16(nn.z);
	}
}
