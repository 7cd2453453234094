#include "fixed_convert.h"

/* x * 2^frac rounded to nearest, saturated. In double: a float's 24-bit
 * mantissa scaled by 2^30 is exact, so only the final rounding errs. */
static int32_t to_fixed(double x, int frac)
{
	double s = x * (double)((int64_t)1 << frac);

	if (s != s)
		return 0;
	if (s >= (double)INT32_MAX)
		return INT32_MAX;
	if (s <= (double)INT32_MIN)
		return INT32_MIN;
	return (int32_t)(s < 0.0 ? s - 0.5 : s + 0.5);
}

static double from_fixed(int32_t v, int frac)
{
	return (double)v / (double)((int64_t)1 << frac);
}

fx_q30 fx_q30_from_float(float f) { return to_fixed(f, 30); }
fx_pos fx_pos_from_float(float f) { return to_fixed(f, FX_POS_FRAC); }
float fx_q30_to_float(fx_q30 v) { return (float)from_fixed(v, 30); }
float fx_pos_to_float(fx_pos v) { return (float)from_fixed(v, FX_POS_FRAC); }
double fx_q30_to_double(fx_q30 v) { return from_fixed(v, 30); }
double fx_pos_to_double(fx_pos v) { return from_fixed(v, FX_POS_FRAC); }

fx_vec3 fx_vec3_from_vec3(vec3 v)
{
	fx_vec3 r = { fx_pos_from_float(v.x), fx_pos_from_float(v.y), fx_pos_from_float(v.z) };
	return r;
}

vec3 fx_vec3_to_vec3(fx_vec3 v)
{
	return vec3_make(fx_pos_to_float(v.x), fx_pos_to_float(v.y), fx_pos_to_float(v.z));
}

fx_vec3 fx_normal_from_vec3(vec3 n)
{
	fx_vec3 r = { fx_q30_from_float(n.x), fx_q30_from_float(n.y), fx_q30_from_float(n.z) };
	return r;
}

vec3 fx_normal_to_vec3(fx_vec3 n)
{
	return vec3_make(fx_q30_to_float(n.x), fx_q30_to_float(n.y), fx_q30_to_float(n.z));
}

static fx_quat quat_to_fixed(quat q, int frac)
{
	fx_quat r = { to_fixed(q.w, frac), to_fixed(q.x, frac), to_fixed(q.y, frac),
		      to_fixed(q.z, frac) };
	return r;
}

static quat quat_from_fixed(fx_quat q, int frac)
{
	quat r = { (float)from_fixed(q.w, frac), (float)from_fixed(q.x, frac),
		   (float)from_fixed(q.y, frac), (float)from_fixed(q.z, frac) };
	return r;
}

fx_quat fx_quat_from_quat(quat q) { return quat_to_fixed(q, 30); }
quat fx_quat_to_quat(fx_quat q) { return quat_from_fixed(q, 30); }

fx_dq fx_dq_from_dq(const dq *d)
{
	fx_dq r = { quat_to_fixed(d->real, 30), quat_to_fixed(d->dual, FX_POS_FRAC) };
	return r;
}

dq fx_dq_to_dq(const fx_dq *d)
{
	dq r = { quat_from_fixed(d->real, 30), quat_from_fixed(d->dual, FX_POS_FRAC) };
	return r;
}

fx_w15 fx_w15_from_float(float w)
{
	int32_t v = to_fixed(w, 15);

	return (fx_w15)(v < 0 ? 0 : v > (int32_t)FX_W15_ONE ? FX_W15_ONE : (uint32_t)v);
}

skp_status fx_weights_from_float(const float *w, fx_w15 *out, int count)
{
	double sum = 0.0;
	int32_t left = FX_W15_ONE;

	for (int i = 0; i < count; i++) {
		if (!(w[i] >= 0.0f))
			sum = -1.0;
		else if (sum >= 0.0)
			sum += w[i];
	}
	if (!(sum > 0.0)) {
		for (int i = 0; i < count; i++)
			out[i] = i == 0 ? FX_W15_ONE : 0;
		return SKP_ERR_RANGE;
	}
	/* Round everything down, then hand the missing LSBs to the largest
	 * remainders: the sum is exact and no weight moves by 1 LSB or more. */
	for (int i = 0; i < count; i++) {
		out[i] = (fx_w15)(w[i] / sum * FX_W15_ONE);
		left -= out[i];
	}
	for (; left > 0; left--) {
		int best = -1;
		double best_rem = -1.0;

		for (int i = 0; i < count; i++) {
			double rem = w[i] / sum * FX_W15_ONE - out[i];
			if (rem > best_rem) {
				best_rem = rem;
				best = i;
			}
		}
		out[best]++;
	}
	return SKP_OK;
}
