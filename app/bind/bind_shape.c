#include "bind_shape.h"

#include <math.h>
#include <string.h>

static void extent(const vec3 *pos, int n, float below, vec3 *lo, vec3 *hi)
{
	*lo = vec3_make(INFINITY, INFINITY, INFINITY);
	*hi = vec3_make(-INFINITY, -INFINITY, -INFINITY);
	for (int v = 0; v < n; v++) {
		vec3 p = pos[v];
		if (!(p.y <= below))
			continue;
		*lo = vec3_make(fminf(lo->x, p.x), fminf(lo->y, p.y), fminf(lo->z, p.z));
		*hi = vec3_make(fmaxf(hi->x, p.x), fmaxf(hi->y, p.y), fmaxf(hi->z, p.z));
	}
}

void bind_shape_measure(const vec3 *pos, int n, bind_shape *out)
{
	vec3 lo, hi, flo, fhi;
	memset(out, 0, sizeof *out);
	extent(pos, n, INFINITY, &lo, &hi);
	if (n <= 0 || !(hi.y > lo.y))
		return;
	out->height = hi.y - lo.y;
	out->width = fmaxf(hi.x - lo.x, hi.z - lo.z);
	out->depth = fminf(hi.x - lo.x, hi.z - lo.z);
	extent(pos, n, lo.y + BIND_SHAPE_FOOT * out->height, &flo, &fhi);
	out->foot_x = fhi.x - flo.x;
	out->foot_z = fhi.z - flo.z;
	out->biped = fmaxf(out->foot_x, out->foot_z) <= BIND_SHAPE_SPAN * out->height &&
		     fminf(out->foot_x, out->foot_z) <= BIND_SHAPE_FEET * out->height &&
		     out->width >= BIND_SHAPE_WIDE * out->height;
}
