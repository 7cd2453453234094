#include "report.h"

#include <math.h>
#include <string.h>

static const char *const region_names[REGION_COUNT] = { "elbows", "knees", "shoulders", "hips",
							  "wrists" };

const char *report_region_name(int region)
{
	return region >= 0 && region < REGION_COUNT ? region_names[region] : "other";
}

int report_region_of_bone(const char *name)
{
	static const struct { const char *name; report_region region; } cmu[] = {
		{ "lhumerus", REGION_SHOULDERS }, { "rhumerus", REGION_SHOULDERS },
		{ "lradius", REGION_ELBOWS },     { "rradius", REGION_ELBOWS },
		{ "lwrist", REGION_WRISTS },      { "rwrist", REGION_WRISTS },
		{ "lhand", REGION_WRISTS },       { "rhand", REGION_WRISTS },
		{ "lfemur", REGION_HIPS },        { "rfemur", REGION_HIPS },
		{ "ltibia", REGION_KNEES },       { "rtibia", REGION_KNEES },
	};
	/* endorphin's capitalised joint names; CMU's lhipjoint stays out */
	static const struct { const char *part; report_region region; } parts[] = {
		{ "Shoulder", REGION_SHOULDERS }, { "Elbow", REGION_ELBOWS }, { "Wrist", REGION_WRISTS },
		{ "Hip", REGION_HIPS },           { "Knee", REGION_KNEES },
	};
	for (size_t i = 0; i < sizeof cmu / sizeof cmu[0]; i++)
		if (strcmp(name, cmu[i].name) == 0)
			return (int)cmu[i].region;
	for (size_t i = 0; i < sizeof parts / sizeof parts[0]; i++)
		if (strstr(name, parts[i].part))
			return (int)parts[i].region;
	return -1;
}

void report_classify(const skel *s, const skel_pose *bind, const float *xyz, int n, int *joint,
		     int *region)
{
	int bone_region[SKP_MAX_BONES];
	for (int b = 0; b < s->count; b++)
		bone_region[b] = b ? report_region_of_bone(s->bone[b].name) : -1;
	for (int v = 0; v < n; v++) {
		vec3 p = vec3_make(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
		float best = INFINITY;
		int at = 0;
		for (int b = 0; b < s->count; b++) {
			vec3 d = vec3_sub(p, bind->head[b]);
			float d2 = vec3_dot(d, d);
			if (d2 < best)
				best = d2, at = b;
		}
		joint[v] = at;
		region[v] = bone_region[at];
	}
}
