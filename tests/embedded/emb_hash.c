#include "emb_hash.h"

#include "skin_kernels.h" /* the fixed kernel itself: skin_run would link the float ones */

#define CHUNK 64 /* vertices skinned per call: a multiple of SKIN_LANES */

skin_bones emb_bones;
void emb_fnv_i32(fnv *f, int32_t v)
{
	uint32_t u = (uint32_t)v;
	for (int i = 0; i < 4; i++) {
		f->h ^= (u >> (8 * i)) & 0xffu;
		f->h *= 16777619u;
	}
}

static int32_t out_pos[3 * CHUNK], out_nrm[3 * CHUNK];

/* Skins vertices [0, in->count) into the hash in chunks of CHUNK. */
void emb_skin_hash(const skin_soa *in, fnv *f)
{
	skin_out o = { NULL, NULL, out_pos, out_nrm, NULL };
	for (int first = 0; first < in->count; first += CHUNK) {
		int n = in->count - first < CHUNK ? in->count - first : CHUNK;
		skin_soa view = *in;
		view.count = n;
		view.fpx = in->fpx + first; view.fpy = in->fpy + first; view.fpz = in->fpz + first;
		view.fnx = in->fnx + first; view.fny = in->fny + first; view.fnz = in->fnz + first;
		for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
			view.bone[k] = in->bone[k] + first;
			view.fweight[k] = in->fweight[k] + first;
		}
		skin_dqbs_fixed(&view, &emb_bones, 0, n, &o);
		for (int i = 0; i < 3 * n; i++)
			emb_fnv_i32(f, out_pos[i]);
		for (int i = 0; i < 3 * n; i++)
			emb_fnv_i32(f, out_nrm[i]);
	}
}

