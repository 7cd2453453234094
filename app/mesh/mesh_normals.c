#include "mesh_normals.h"

#include <math.h>

vec3 mesh_unit(vec3 n)
{
	float big = fmaxf(fabsf(n.x), fmaxf(fabsf(n.y), fabsf(n.z)));
	if (!(big > 0.0f) || !isfinite(big))
		return vec3_make(0.0f, 0.0f, 0.0f);
	/* divided, not multiplied by 1/big: that could overflow */
	return vec3_normalize(vec3_make(n.x / big, n.y / big, n.z / big));
}

void mesh_compute_normals(mesh *m)
{
	for (int v = 0; v < m->vert_count; v++)
		m->normal[v] = vec3_make(0.0f, 0.0f, 0.0f);
	for (int t = 0; t < m->tri_count; t++) {
		const uint32_t *i = m->tri[t];
		vec3 a = m->pos[i[0]];
		/* |cross| is twice the area: the weighting comes for free */
		vec3 n = vec3_cross(vec3_sub(m->pos[i[1]], a), vec3_sub(m->pos[i[2]], a));
		for (int j = 0; j < 3; j++)
			m->normal[i[j]] = vec3_add(m->normal[i[j]], n);
	}
	for (int v = 0; v < m->vert_count; v++) {
		vec3 n = mesh_unit(m->normal[v]);
		m->normal[v] = vec3_dot(n, n) > 0.5f ? n : vec3_make(0.0f, 1.0f, 0.0f);
	}
}
