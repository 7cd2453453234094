#include "play_blend.h"

static vec3 lerp3(vec3 a, vec3 b, float w)
{
	return vec3_make(a.x + (b.x - a.x) * w, a.y + (b.y - a.y) * w, a.z + (b.z - a.z) * w);
}

void play_blend(const skel *s, const skel_local *a, const skel_local *b, float w, skel_local *out)
{
	for (int i = 0; i < s->count; i++) {
		out->rot[i] = quat_slerp(a->rot[i], b->rot[i], w);
		out->trans[i] = lerp3(a->trans[i], b->trans[i], w);
		out->stretch[i] = a->stretch[i] + (b->stretch[i] - a->stretch[i]) * w;
	}
}

/* The weight's rate of change ramps up over the first RAMP of the fade,
 * holds, and ramps down over the last: no kink in the motion at either
 * end, and a steepest rate of 1 / (1 - RAMP) of the fade's length (a
 * smoothstep's is 1.5), which is what a seam adds to the motion at most. */
#define RAMP 0.15

float play_fade_weight(double x)
{
	const double v = 1.0 / (1.0 - RAMP);
	if (!(x > 0.0))
		return 0.0f;
	if (x >= 1.0)
		return 1.0f;
	if (x < RAMP)
		return (float)(v * x * x / (2.0 * RAMP));
	if (x > 1.0 - RAMP)
		return (float)(1.0 - v * (1.0 - x) * (1.0 - x) / (2.0 * RAMP));
	return (float)(v * (x - 0.5 * RAMP));
}
