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

void skin_lbs_vertex(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES],
		     const float w[SKP_MAX_INFLUENCES], vec3 p, vec3 n, vec3 *po, vec3 *no)
{
	float m[12] = { 0 };
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		const float *src = b->lbs12[idx[k]];
		for (int i = 0; i < 12; i++)
			m[i] += w[k] * src[i];
	}
	*po = vec3_make(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3],
			m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
			m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
	*no = vec3_normalize(vec3_make(m[0] * n.x + m[1] * n.y + m[2] * n.z,
				       m[4] * n.x + m[5] * n.y + m[6] * n.z,
				       m[8] * n.x + m[9] * n.y + m[10] * n.z));
}

void skin_dqbs_vertex(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES],
		      const float w[SKP_MAX_INFLUENCES], vec3 p, vec3 n, vec3 *po, vec3 *no)
{
	/* weights are stored largest first: influence 0 is the pivot */
	dq d = dq_blend_normalized(b->dq, idx, w, SKP_MAX_INFLUENCES, b->dq[idx[0]].real);
	*po = dq_transform_point(&d, p);
	*no = dq_transform_normal(&d, n);
}

typedef void (*vertex_fn)(const skin_bones *b, const uint16_t idx[SKP_MAX_INFLUENCES],
			  const float w[SKP_MAX_INFLUENCES], vec3 p, vec3 n, vec3 *po, vec3 *no);

static void run(vertex_fn fn, const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	for (int v = first; v < end; v++) {
		uint16_t idx[SKP_MAX_INFLUENCES];
		float w[SKP_MAX_INFLUENCES];
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			idx[k] = in->bone[k][v];
			w[k] = in->weight[k][v];
		}
		vec3 pp, nn;
		fn(b, idx, w, vec3_make(in->px[v], in->py[v], in->pz[v]), vec3_make(in->nx[v], in->ny[v], in->nz[v]),
		   &pp, &nn);
		store3(out->pos, v, pp);
		store3(out->nrm, v, nn);
	}
}

void skin_lbs_scalar(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run(skin_lbs_vertex, in, b, first, end, out);
}

void skin_dqbs_scalar(const skin_soa *in, const skin_bones *b, int first, int end, const skin_out *out)
{
	run(skin_dqbs_vertex, in, b, first, end, out);
}
