#include "bind_pose_narrow.h"

#include <math.h>

#define NARROW_FROM      0.5f
#define NARROW_TO        1.3f
#define NARROW_STEP      0.04f  /* of the bone's length, between sections */
#define NARROW_HALF      0.02f  /* a section's half thickness */
#define NARROW_ACROSS    0.6f   /* how far from the axis a section reaches: the axis may be off the limb */
#define NARROW_MIN_VERTS 12

/* The section at t (of len) along d from head: its centroid and spread
 * (mean squared distance across the axis from the centroid). */
static int section(const mesh *m, vec3 head, vec3 d, float len, float t, vec3 *mid, float *spread)
{
	vec3 sum = vec3_make(0.0f, 0.0f, 0.0f);
	double sq = 0.0;
	int n = 0;
	for (int v = 0; v < m->vert_count; v++) {
		vec3 q = vec3_sub(m->pos[v], head);
		float along = vec3_dot(q, d);
		vec3 across = vec3_madd(q, d, -along);
		if (fabsf(along - t * len) > NARROW_HALF * len || vec3_length(across) > NARROW_ACROSS * len)
			continue;
		sum = vec3_add(sum, across);
		sq += vec3_dot(across, across);
		n++;
	}
	if (n < NARROW_MIN_VERTS)
		return 0;
	vec3 c = vec3_scale(sum, 1.0f / (float)n);
	*spread = (float)(sq / n) - vec3_dot(c, c);
	*mid = vec3_add(vec3_add(head, vec3_scale(d, t * len)), c);
	return 1;
}

int bind_guess_narrowest(const mesh *m, const skel_pose *p, int l, vec3 *at)
{
	vec3 head = p->head[l], d = vec3_sub(p->tip[l], head);
	float len = vec3_length(d), best = INFINITY, best_t = 0.0f;
	if (!(len > 0.0f))
		return 0;
	d = vec3_scale(d, 1.0f / len);
	for (float t = NARROW_FROM; t <= NARROW_TO + 1e-4f; t += NARROW_STEP) {
		vec3 mid;
		float spread;
		if (section(m, head, d, len, t, &mid, &spread) && spread < best) {
			best = spread;
			best_t = t;
			*at = mid;
		}
	}
	/* the thinnest at either end: no waist between them */
	return best_t > NARROW_FROM && best_t < NARROW_TO - NARROW_STEP / 2;
}
