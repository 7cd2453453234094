#include "skel.h"

#include <string.h>

int skel_find(const skel *s, const char *name)
{
	for (int i = 0; i < s->count; i++)
		if (strcmp(s->bone[i].name, name) == 0)
			return i;
	return -1;
}

float skel_angle_to_rad(const skel *s, float value)
{
	return s->angle_in_degrees ? value * (3.14159265358979323846f / 180.0f) : value;
}

double skel_length_factor(const skel *s)
{
	return 1.0 / (double)s->length_scale;
}
