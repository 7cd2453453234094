#include <math.h>
#include <string.h>

#include "compare.h"

static double tet(vec3 apex, const float *a, const float *b, const float *c)
{
	double ax = a[0] - apex.x, ay = a[1] - apex.y, az = a[2] - apex.z;
	double bx = b[0] - apex.x, by = b[1] - apex.y, bz = b[2] - apex.z;
	double cx = c[0] - apex.x, cy = c[1] - apex.y, cz = c[2] - apex.z;
	return (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.0;
}

static void sum_regions(const compare_run *c, const float *pos, const skel_pose *pose, double *out)
{
	const mesh *m = &c->body.mesh;
	for (int g = 0; g < REGION_COUNT; g++)
		out[g] = 0.0;
	for (int t = 0; t < m->tri_count; t++) {
		int g = c->rv.tri_region[t];
		if (g < 0)
			continue;
		const uint32_t *k = m->tri[t];
		out[g] += tet(pose->head[c->rv.tri_joint[t]], pos + 3 * k[0], pos + 3 * k[1], pos + 3 * k[2]);
	}
}

/* Is triangle t one the body's volume is measured on? The measure keeps
 * the outer closed parts' triangles in mesh order (parts.h), so they are
 * matched in one pass; a mesh without a closed part keeps them all. */
static int in_volume(const compare_run *c, int t, int *next)
{
	const measure_state *ms = &c->meas;
	if (*next < ms->vol_tri_count && memcmp(ms->vol_tri[*next], c->body.mesh.tri[t], sizeof ms->vol_tri[0]) == 0) {
		++*next;
		return 1;
	}
	return 0;
}

void compare_region_volume_init(compare_run *c)
{
	const mesh *m = &c->body.mesh;
	int next = 0;
	for (int t = 0; t < m->tri_count; t++) {
		int v = (int)m->tri[t][0], counted = in_volume(c, t, &next);
		/* inner parts (joint balls, eyes) are left out as in the body's volume */
		c->rv.tri_region[t] = (int8_t)(counted ? c->region[v] : -1);
		c->rv.tri_joint[t] = (int16_t)(counted && c->region[v] >= 0 ? c->joint[v] : 0);
	}
	sum_regions(c, c->meas.bind_xyz, &c->body.pose, c->rv.bind);
}

void compare_region_volume(const compare_run *c, const float *pos, const skel_pose *pose,
			   double ratio[REGION_COUNT])
{
	double now[REGION_COUNT];
	sum_regions(c, pos, pose, now);
	for (int g = 0; g < REGION_COUNT; g++)
		ratio[g] = c->rv.bind[g] > 0.0 ? now[g] / c->rv.bind[g] : NAN;
}
