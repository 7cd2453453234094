/* The portable kernels: one vertex at a time. They define the results the
 * SIMD kernels must reproduce. */
#include "skin_kernels.h"

#include <math.h>

static void store3(float *dst, int v, vec3 a)
{
	dst[3 * v + 0] = a.x;
	dst[3 * v + 1] = a.y;
	dst[3 * v + 2] = a.z;
}

void skin_lbs_scalar(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v++) {
		float m[12] = { 0 };
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			float w = in->weight[k][v];
			const float *src = b->lbs12[in->bone[k][v]];
			for (int i = 0; i < 12; i++)
				m[i] += w * src[i];
		}
		vec3 p = vec3_make(in->px[v], in->py[v], in->pz[v]);
		vec3 n = vec3_make(in->nx[v], in->ny[v], in->nz[v]);
		vec3 pp = vec3_make(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3],
				    m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
				    m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
		vec3 nn = vec3_make(m[0] * n.x + m[1] * n.y + m[2] * n.z,
				    m[4] * n.x + m[5] * n.y + m[6] * n.z,
				    m[8] * n.x + m[9] * n.y + m[10] * n.z);
		store3(out->pos, v, pp);
		store3(out->nrm, v, vec3_normalize(nn));
	}
}

void skin_dqbs_scalar(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v++) {
		uint16_t idx[SKP_MAX_INFLUENCES];
		float w[SKP_MAX_INFLUENCES];
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			idx[k] = in->bone[k][v];
			w[k] = in->weight[k][v];
		}
		/* weights are stored largest first: influence 0 is the pivot */
		dq d = dq_blend_normalized(b->dq, idx, w, SKP_MAX_INFLUENCES, b->dq[idx[0]].real);
		vec3 p = vec3_make(in->px[v], in->py[v], in->pz[v]);
		vec3 n = vec3_make(in->nx[v], in->ny[v], in->nz[v]);
		store3(out->pos, v, dq_transform_point(&d, p));
		store3(out->nrm, v, dq_transform_normal(&d, n));
	}
}
