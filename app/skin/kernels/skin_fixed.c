/* DQBS in fixed point: integer arithmetic only (checked by
 * tests/check_fixed_integer.sh). Output is Q16.16, which is GL_FIXED. */
#include "skin_kernels.h"

_Static_assert(FX_POS_FRAC <= 16, "positions are written as Q16.16");

static int32_t q30_to_q16(fx_q30 v)
{
	return (int32_t)fx_shr_round(v, 14);
}

static int32_t pos_to_q16(fx_pos v)
{
	return (int32_t)((int64_t)v * (1 << (16 - FX_POS_FRAC)));
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
		fx_dq d = fx_dq_blend(b->fdq, idx, w, SKP_MAX_INFLUENCES, b->fdq[idx[0]].real);
		fx_vec3 p = { in->fpx[v], in->fpy[v], in->fpz[v] };
		fx_vec3 n = { in->fnx[v], in->fny[v], in->fnz[v] };
		fx_vec3 pp, nn;
		fx_dq_transform_blend(&d, p, n, &pp, &nn);
		int32_t *po = out->fpos + 3 * v, *no = out->fnrm + 3 * v;
		po[0] = pos_to_q16(pp.x); po[1] = pos_to_q16(pp.y); po[2] = pos_to_q16(pp.z);
		no[0] = q30_to_q16(nn.x); no[1] = q30_to_q16(nn.y); no[2] = q30_to_q16(nn.z);
	}
}
