#include <math.h>
#include <stddef.h>

#include "encode_error.h"
#include "encode_work.h"

double enc_measure(enc_work *w, int top, double limit)
{
	const skel *s = w->s;
	int below[SKP_MAX_BONES], count = 0;
	for (int k = 0; k < s->count; k++)
		if (enc_above(s, top, s->eval_order[k]))
			below[count++] = s->eval_order[k];
	double worst = 0;
	for (long f = 0; f < w->n && worst <= limit; f++) {
		const float *values = w->dec + (size_t)f * (size_t)w->dofs;
		double e = 0;
		for (int k = 0; k < count; k++) {
			fk_pose_bone(s, below[k], values, &w->got[f]);
			e = fmax(e, encode_joint_error(&w->ref[f], &w->got[f], below[k], w->shell));
		}
		if (top == 0)
			w->err[f] = e;
		worst = fmax(worst, e);
	}
	return worst;
}
