/* The portable compact kernels: each vertex decoded to floats and skinned
 * as skin_scalar.c skins it. They define the results the SIMD compact
 * kernels must reproduce. */
#include "skin_kernels.h"

#include <math.h>

int16_t skin_snorm16_of(float x)
{
	float q = rintf(x * SKIN_COMPACT_NORMAL_ONE);
	return (int16_t)(q < -32767.0f ? -32767.0f : q > 32767.0f ? 32767.0f : q);
}

static void decode(const skin_compact *in, int v, uint16_t idx[SKP_MAX_INFLUENCES], float w[SKP_MAX_INFLUENCES],
		   vec3 *p, vec3 *n)
{
	unsigned rest = SKIN_COMPACT_WEIGHT_ONE;
	for (int k = 1; k < SKP_MAX_INFLUENCES; k++) {
		rest -= in->weight[k - 1][v];
		w[k] = (float)in->weight[k - 1][v] * (1.0f / (float)SKIN_COMPACT_WEIGHT_ONE);
	}
	w[0] = (float)rest * (1.0f / (float)SKIN_COMPACT_WEIGHT_ONE);
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++)
		idx[k] = in->bone[k][v];
	*p = vec3_make(fmaf((float)in->qx[v], in->step[0], in->origin[0]),
		       fmaf((float)in->qy[v], in->step[1], in->origin[1]),
		       fmaf((float)in->qz[v], in->step[2], in->origin[2]));
	*n = vec3_normalize(skin_oct_decode(in->ox[v], in->oy[v]));
}

static void run(int dqbs, const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v++) {
		uint16_t idx[SKP_MAX_INFLUENCES];
		float w[SKP_MAX_INFLUENCES];
		vec3 p, n, pp, nn;
		decode(in, v, idx, w, &p, &n);
		if (dqbs)
			skin_dqbs_vertex(b, idx, w, p, n, &pp, &nn);
		else
			skin_lbs_vertex(b, idx, w, p, n, &pp, &nn);
		float *po = out->pos + 3 * v;
		int16_t *no = out->nrm16 + 3 * v;
		po[0] = pp.x; po[1] = pp.y; po[2] = pp.z;
		no[0] = skin_snorm16_of(nn.x); no[1] = skin_snorm16_of(nn.y); no[2] = skin_snorm16_of(nn.z);
	}
}

void skin_lbs_compact_scalar(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run(0, in, b, first, end, out);
}

void skin_dqbs_compact_scalar(const skin_compact *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run(1, in, b, first, end, out);
}
