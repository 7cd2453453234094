/* The test body's fixed-point skinning input, as a skin_soa pointing into
 * the host-made tables (emb_tables.h, included before this): shared by the
 * test (emb_skin.c) and the benchmark (emb_bench.c). The kernel only reads
 * through these pointers (skin_soa has no const variant), so the tables
 * stay in flash. */
#ifndef EMB_SOA_H
#define EMB_SOA_H

#include <string.h>

#include "skin.h"

static void emb_table_soa(skin_soa *s)
{
	memset(s, 0, sizeof *s);
	s->count = EMB_VERTS;
	s->padded = EMB_PADDED;
	s->fpx = (int32_t *)emb_fpx; s->fpy = (int32_t *)emb_fpy; s->fpz = (int32_t *)emb_fpz;
	s->fnx = (int32_t *)emb_fnx; s->fny = (int32_t *)emb_fny; s->fnz = (int32_t *)emb_fnz;
	const uint16_t *bone[4] = { emb_bone0, emb_bone1, emb_bone2, emb_bone3 };
	const uint16_t *fw[4] = { emb_fw0, emb_fw1, emb_fw2, emb_fw3 };
	_Static_assert(SKP_MAX_INFLUENCES == 4, "emb_gen writes 4 influences");
	for (int k = 0; k < SKP_MAX_INFLUENCES; k++) {
		s->bone[k] = (uint16_t *)bone[k];
		s->fweight[k] = (uint16_t *)fw[k];
	}
}

#endif
