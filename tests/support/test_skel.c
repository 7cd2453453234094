#include "test_skel.h"

#include <stdio.h>
#include <string.h>

int test_skel_add_bone(skel *s, skel_pose *p, const char *name, int parent, vec3 head, vec3 tip)
{
	int b = s->count++;
	memset(&s->bone[b], 0, sizeof s->bone[b]);
	snprintf(s->bone[b].name, sizeof s->bone[b].name, "%s", name);
	s->bone[b].parent = parent;
	s->bone[b].length = vec3_length(vec3_sub(tip, head));
	p->head[b] = head;
	p->tip[b] = tip;
	return b;
}
