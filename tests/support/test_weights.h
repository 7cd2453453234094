/* Weights CSV files (vertex,bone,weight rows) as the rig tests compare
 * them: each vertex's dominant bone, and the body part it belongs to. */
#ifndef TEST_WEIGHTS_H
#define TEST_WEIGHTS_H

#define TEST_BONE_NAME 64

/* Calls row for each row of the weights CSV at path, after checking it is
 * vertex,bone,weight with 0 <= vertex < n; returns the rows read. Fails the
 * test on a malformed file. */
int test_weights_rows(const char *path, int n, void (*row)(void *ctx, long v, const char *bone, float w),
		      void *ctx);

/* Fills bone[v] with vertex v's largest-weight bone for n vertices, every
 * one of which must have a weight; returns the rows read. Fails the test
 * on a malformed file. */
int test_load_dominant(const char *path, char (*bone)[TEST_BONE_NAME], int n);

/* Compares two weights files of n vertices by dominant bone: *same_bone
 * vertices have the same one, the return value the same body part. */
int test_same_part(const char *a, const char *b, int n, int *same_bone);

/* Body parts as skinning sees them: a hand with its fingers is one part
 * (an artist's fingers follow the hand, the computed weights give CMU's
 * finger bones theirs), so is the trunk; any other bone is its own. */
const char *test_body_part(const char *bone);

#endif
