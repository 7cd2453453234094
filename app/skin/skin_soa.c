#include "skin.h"

#include <string.h>

#include "fixed_convert.h"

size_t skin_soa_bytes(int count)
{
	return SKIN_SOA_BYTES(count);
}

void skin_soa_attach(skin_soa *s, void *mem, int count)
{
	char *c = mem;
	size_t n = SKIN_SOA_PADDED(count);
	s->count = count;
	s->padded = (int)n;
	s->px = skin_carve(&c, n * 4); s->py = skin_carve(&c, n * 4); s->pz = skin_carve(&c, n * 4);
	s->nx = skin_carve(&c, n * 4); s->ny = skin_carve(&c, n * 4); s->nz = skin_carve(&c, n * 4);
	s->fpx = skin_carve(&c, n * 4); s->fpy = skin_carve(&c, n * 4); s->fpz = skin_carve(&c, n * 4);
	s->fnx = skin_carve(&c, n * 4); s->fny = skin_carve(&c, n * 4); s->fnz = skin_carve(&c, n * 4);
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		s->weight[k] = skin_carve(&c, n * 4);
		s->bone[k] = skin_carve(&c, n * 2);
		s->fweight[k] = skin_carve(&c, n * 2);
	}
}

/* Influences of one vertex, largest weight first (the DQBS pivot), unused
 * slots weight 0 on the identity slot. */
static skp_status load_influences(skin_soa *s, int v, const skin_weights *w, int bone_count,
				  skp_error *err)
{
	uint16_t bone[SKP_MAX_INFLUENCES];
	float weight[SKP_MAX_INFLUENCES];
	int n = w && v < w->vert_count ? w->count[v] : 0;
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		bone[k] = k < n ? w->bone[v][k] : SKIN_IDENTITY_BONE;
		weight[k] = k < n ? w->weight[v][k] : 0.0f;
		if (k < n && bone[k] >= bone_count)
			return skp_fail(err, SKP_ERR_RANGE, 0, "vertex %d: bone index %d out of range",
					v, bone[k]);
	}
	if (n == 0)
		weight[0] = 1.0f; /* no influence: stay in the bind pose */
	for (int i = 1; i < SKP_MAX_INFLUENCES; i++)
		for (int j = i; j > 0 && weight[j] > weight[j - 1]; j--) {
			float tw = weight[j]; weight[j] = weight[j - 1]; weight[j - 1] = tw;
			uint16_t tb = bone[j]; bone[j] = bone[j - 1]; bone[j - 1] = tb;
		}
	fx_w15 fw[SKP_MAX_INFLUENCES];
	if (fx_weights_from_float(weight, fw, SKP_MAX_INFLUENCES) != SKP_OK)
		return skp_fail(err, SKP_ERR_RANGE, 0, "vertex %d: weights do not sum to 1", v);
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		s->bone[k][v] = bone[k];
		s->weight[k][v] = weight[k];
		s->fweight[k][v] = fw[k];
	}
	return SKP_OK;
}

static void load_vertex(skin_soa *s, int v, vec3 p, vec3 n)
{
	s->px[v] = p.x; s->py[v] = p.y; s->pz[v] = p.z;
	s->nx[v] = n.x; s->ny[v] = n.y; s->nz[v] = n.z;
	fx_vec3 fp = fx_vec3_from_vec3(p), fn = fx_normal_from_vec3(n);
	s->fpx[v] = fp.x; s->fpy[v] = fp.y; s->fpz[v] = fp.z;
	s->fnx[v] = fn.x; s->fny[v] = fn.y; s->fnz[v] = fn.z;
}

skp_status skin_soa_load(skin_soa *s, const mesh *m, const skin_weights *w, int bone_count,
			 skp_error *err)
{
	const float limit = 32767.0f; /* fx_pos range */
	for (int v = 0; v < s->padded; v++) {
		int real = v < m->vert_count;
		vec3 p = real ? m->pos[v] : vec3_make(0, 0, 0);
		vec3 n = real ? m->normal[v] : vec3_make(0, 1, 0);
		if (!(p.x > -limit && p.x < limit && p.y > -limit && p.y < limit && p.z > -limit &&
		      p.z < limit))
			return skp_fail(err, SKP_ERR_RANGE, 0,
					"vertex %d lies outside +-32767 units (fixed-point range)", v);
		load_vertex(s, v, p, n);
		skp_status rc = load_influences(s, v, real ? w : NULL, bone_count, err);
		if (rc)
			return rc;
	}
	return SKP_OK;
}
