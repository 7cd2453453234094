#include <math.h>
#include <stddef.h>

#include "encode_error.h"
#include "encode_work.h"

double enc_measure(enc_work *w, double limit)
{
	static skel_pose got;
	double worst = 0;
	for (long f = 0; f < w->n && worst <= limit; f++) {
		fk_pose(w->s, w->dec + (size_t)f * (size_t)w->dofs, &got);
		w->err[f] = encode_shell_error(w->s, &w->ref[f], &got, w->shell);
		worst = fmax(worst, w->err[f]);
	}
	return worst;
}
