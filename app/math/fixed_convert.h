/* The only bridge between float (vec3.h, quat.h, dq.h) and the fixed-point
 * types of fixed.h, so that fixed.o stays free of floating point. Every
 * conversion to fixed rounds to nearest (ties away from zero) and saturates
 * to the int32 range; NaN becomes 0. */
#ifndef FIXED_CONVERT_H
#define FIXED_CONVERT_H

#include "dq.h"
#include "fixed.h"
#include "quat.h"
#include "skp_error.h"
#include "vec3.h"

fx_q30 fx_q30_from_float(float f);
fx_pos fx_pos_from_float(float f);
float fx_q30_to_float(fx_q30 v);
float fx_pos_to_float(fx_pos v);
/* Exact: every fx value is a double. For tests and tools measuring error. */
double fx_q30_to_double(fx_q30 v);
double fx_pos_to_double(fx_pos v);

/* Points and translations (fx_pos). */
fx_vec3 fx_vec3_from_vec3(vec3 v);
vec3 fx_vec3_to_vec3(fx_vec3 v);
/* Normals and other unit vectors (fx_q30). */
fx_vec3 fx_normal_from_vec3(vec3 n);
vec3 fx_normal_to_vec3(fx_vec3 n);

fx_quat fx_quat_from_quat(quat q);
quat fx_quat_to_quat(fx_quat q);
/* real in fx_q30, dual in fx_pos. */
fx_dq fx_dq_from_dq(const dq *d);
dq fx_dq_to_dq(const fx_dq *d);

/* One weight in [0, 1], saturated to [0, 32768]. */
fx_w15 fx_w15_from_float(float w);
/* Quantises count weights so that they sum to exactly 32768 (largest
 * remainder: each output is w/sum rounded down or up, never further off
 * than 1 LSB). Weights must be >= 0 with a positive sum; otherwise
 * returns SKP_ERR_RANGE and gives all weight to the first influence. */
skp_status fx_weights_from_float(const float *w, fx_w15 *out, int count);

#endif
