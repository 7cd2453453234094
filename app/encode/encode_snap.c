#include <stdlib.h>
#include <string.h>

#include "encode_work.h"

int enc_snap_alloc(enc_work *w)
{
	size_t n = (size_t)w->n, c = (size_t)w->s->count, d = (size_t)w->dofs;
	struct enc_snap *k = &w->snap;
	k->q = malloc(n * d * sizeof *k->q);
	k->dec = malloc(n * d * sizeof *k->dec);
	k->gdec = malloc(n * c * 9 * sizeof *k->gdec);
	k->pdec = malloc(n * c * 6 * sizeof *k->pdec);
	k->err = malloc(n * sizeof *k->err);
	k->got = malloc(n * c * sizeof *k->got);
	return k->q && k->dec && k->gdec && k->pdec && k->err && k->got ? 0 : -1;
}

void enc_snap_free(enc_work *w)
{
	struct enc_snap *k = &w->snap;
	free(k->q);
	free(k->dec);
	free(k->gdec);
	free(k->pdec);
	free(k->err);
	free(k->got);
}

/* Copies bone b's part of frame f from the work to the snapshot (save 1)
 * or back (save 0). */
static void copy_bone(enc_work *w, int b, long f, int save)
{
	struct enc_snap *k = &w->snap;
	const skel_bone *bone = &w->s->bone[b];
	size_t v = (size_t)f * (size_t)w->dofs + bone->dof_offset, nv = bone->channel_count;
	size_t g = (size_t)f * (size_t)w->s->count + (size_t)b;
	int32_t *q[2] = { w->q, k->q };
	float *dec[2] = { w->dec, k->dec };
	double *gdec[2] = { w->gdec, k->gdec }, *pdec[2] = { w->pdec, k->pdec };
	memcpy(q[save] + v, q[!save] + v, nv * sizeof *q[0]);
	memcpy(dec[save] + v, dec[!save] + v, nv * sizeof *dec[0]);
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
	const skel *s = w->s;
	int top = w->snap.top;
	for (int b = 0; b < s->count; b++) {
		if (!enc_above(s, top, b))
			continue;
		for (long f = 0; f < w->n; f++)
			copy_bone(w, b, f, save);
		codec_track *track[2] = { w->track, w->snap.track };
		int d = s->bone[b].dof_offset;
		memcpy(track[save] + d, track[!save] + d, s->bone[b].channel_count * sizeof *track[0]);
	}
	double *err[2] = { w->err, w->snap.err };
	if (top == 0)
		memcpy(err[save], err[!save], (size_t)w->n * sizeof *err[0]);
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
