/* The constrained smooth solve of bind_balance (see bind_balance.h), on
 * the band work->band[0..m) with work->slot, work->arm, work->share and
 * the adjacency filled in. */
#ifndef BIND_BALANCE_SOLVE_H
#define BIND_BALANCE_SOLVE_H

#include "bind_balance.h"

/* Fills work->change[0..m) so that moment + sum change * arm is zero (as
 * near as the bounds 0 <= share + change <= 1 allow); returns the moment
 * left in left[3] and the largest |change|. */
double balance_solve(bind_balance_work *work, int m, const double moment[3], double left[3]);

#endif
