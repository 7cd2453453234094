/* Every motion clip in ../shared/data/mocap with its skeleton and frame
 * count (SOURCES.md), for the tests that sweep all of them. */
#ifndef TEST_CLIPS_H
#define TEST_CLIPS_H

typedef struct test_clip {
	const char *asf, *amc;   /* relative to the shared data directory */
	long frames;
} test_clip;

extern const test_clip test_clips[];
extern const int test_clip_count;

/* 1 when clip i's source (its directory: cmu, hdm05, endorphin) is an
 * earlier clip's: the first of each is the sample that sweeps take under
 * the sanitizers or an emulator. */
int test_clip_source_seen(int i);

#endif
