#include <string.h>

#include "test_clips.h"

const test_clip test_clips[] = {
	{ "mocap/cmu/02.asf", "mocap/cmu/02_01.amc", 343 },
	{ "mocap/cmu/07.asf", "mocap/cmu/07_05.amc", 517 },
	{ "mocap/cmu/09.asf", "mocap/cmu/09_06.amc", 141 },
	{ "mocap/cmu/131.asf", "mocap/cmu/131_04.amc", 1086 },
	{ "mocap/cmu/135.asf", "mocap/cmu/135_06.amc", 3261 },
	{ "mocap/cmu/lambada.asf", "mocap/cmu/lambada.amc", 2180 },
	{ "mocap/cmu/kick.asf", "mocap/cmu/kick.amc", 801 },
	{ "mocap/cmu/backflip.asf", "mocap/cmu/backflip.amc", 247 },
	{ "mocap/hdm05/HDM_dg.asf", "mocap/hdm05/HDM_dg_06-03_03_120.amc", 202 },
	{ "mocap/endorphin/skeleton.asf", "mocap/endorphin/walking.amc", 1741 },
};

const int test_clip_count = (int)(sizeof test_clips / sizeof test_clips[0]);

int test_clip_source_seen(int i)
{
	const char *a = test_clips[i].asf;
	size_t n = (size_t)(strrchr(a, '/') - a) + 1;
	for (int k = 0; k < i; k++)
		if (!strncmp(test_clips[k].asf, a, n))
			return 1;
	return 0;
}
