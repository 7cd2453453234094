#include "runtime_body.h"

#include <stddef.h>

const float *bound_pose_values(const bound_body *body)
{
	if (body->pose_frame >= 0)
		return body->pose_value;
	/* a derived pose (arms raised, the mesh's own) differs from the rest's zeros */
	for (int i = 0; i < body->skel.dof_count; i++)
		if (body->pose_value[i] != 0.0f)
			return body->pose_value;
	return NULL;
}
