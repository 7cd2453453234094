#include <stdlib.h>
#include <string.h>

#include "encode_work.h"

int enc_snap_alloc(enc_work *w)
{
	size_t n = (size_t)w->n, c = (size_t)w->s->count;
	struct enc_snap *k = &w->snap;
	k->gdec = malloc(n * c * 9 * sizeof *k->gdec);
	k->pdec = malloc(n * c * 6 * sizeof *k->pdec);
	k->got = malloc(n * c * sizeof *k->got);
	return k->gdec && k->pdec && k->got ? 0 : -1;
}

void enc_snap_free(enc_work *w)
{
	free(w->snap.gdec);
	free(w->snap.pdec);
	free(w->snap.got);
}

/* Copies bone b's part of frame f from the work to the snapshot (save 1)
 * or back (save 0). */
static void copy_bone(enc_work *w, int b, long f, int save)
{
	struct enc_snap *k = &w->snap;
	size_t g = (size_t)f * (size_t)w->s->count + (size_t)b;
	double *gdec[2] = { w->gdec, k->gdec }, *pdec[2] = { w->pdec, k->pdec };
	memcpy(gdec[save] + g * 9, gdec[!save] + g * 9, 9 * sizeof *gdec[0]);
	memcpy(pdec[save] + g * 6, pdec[!save] + g * 6, 6 * sizeof *pdec[0]);
	skel_pose *p = &w->got[f];
	if (save) {
		k->got[g] = (struct enc_snap_joint){ p->rot[b], p->head[b], p->tip[b] };
	} else {
		p->rot[b] = k->got[g].rot;
		p->head[b] = k->got[g].head;
		p->tip[b] = k->got[g].tip;
	}
}

static void copy_subtree(enc_work *w, int save)
{
	for (int b = 0; b < w->s->count; b++)
		if (enc_above(w->s, w->snap.top, b))
			for (long f = 0; f < w->n; f++)
				copy_bone(w, b, f, save);
}

void enc_snap_save(enc_work *w, int top)
{
	w->snap.top = top;
	copy_subtree(w, 1);
}

void enc_snap_restore(enc_work *w)
{
	copy_subtree(w, 0);
}
