#include "test_weights.h"

#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int test_weights_rows(const char *path, int n, void (*row)(void *ctx, long v, const char *bone, float w),
		      void *ctx)
{
	FILE *f = fopen(path, "r");
	assert_non_null(f);
	char line[256], name[TEST_BONE_NAME];
	int rows = 0;
	assert_non_null(fgets(line, sizeof line, f));
	while (fgets(line, sizeof line, f)) {
		long v;
		float w;
		assert_int_equal(sscanf(line, "%ld,%63[^,],%f", &v, name, &w), 3);
		assert_true(v >= 0 && v < n);
		row(ctx, v, name, w);
		rows++;
	}
	fclose(f);
	return rows;
}

typedef struct dominant {
	char (*bone)[TEST_BONE_NAME];
	float *best;
} dominant;

static void keep_largest(void *ctx, long v, const char *bone, float w)
{
	dominant *d = ctx;
	if (w > d->best[v]) {
		d->best[v] = w;
		snprintf(d->bone[v], TEST_BONE_NAME, "%s", bone);
	}
}

int test_load_dominant(const char *path, char (*bone)[TEST_BONE_NAME], int n)
{
	dominant d = { bone, malloc(sizeof(float) * (size_t)n) };
	assert_non_null(d.best);
	for (int v = 0; v < n; v++)
		d.best[v] = -1.0f;
	int rows = test_weights_rows(path, n, keep_largest, &d);
	for (int v = 0; v < n; v++)
		assert_true(d.best[v] > 0.0f);
	free(d.best);
	return rows;
}

const char *test_body_part(const char *bone)
{
	static const char *const hand[] = { "hand", "fingers", "thumb", "wrist" };
	static const char *const trunk[] = { "root", "lowerback", "upperback", "thorax", "lowerneck", "upperneck",
					     "head", "lhipjoint", "rhipjoint" };
	for (size_t i = 0; i < sizeof trunk / sizeof trunk[0]; i++)
		if (!strcmp(bone, trunk[i]))
			return "trunk";
	for (size_t i = 0; i < sizeof hand / sizeof hand[0]; i++)
		if (!strcmp(bone + 1, hand[i]))
			return bone[0] == 'l' ? "left hand" : "right hand";
	return bone;
}

int test_same_part(const char *a, const char *b, int n, int *same_bone)
{
	char (*ba)[TEST_BONE_NAME] = malloc(sizeof *ba * (size_t)n);
	char (*bb)[TEST_BONE_NAME] = malloc(sizeof *bb * (size_t)n);
	assert_true(ba && bb);
	test_load_dominant(a, ba, n);
	test_load_dominant(b, bb, n);
	int part = 0;
	*same_bone = 0;
	for (int v = 0; v < n; v++) {
		*same_bone += strcmp(ba[v], bb[v]) == 0;
		part += strcmp(test_body_part(ba[v]), test_body_part(bb[v])) == 0;
	}
	free(ba);
	free(bb);
	return part;
}
