/* A user's own mesh with no flags, through the real command line: the
 * MakeHuman base mesh (an A-pose in decimetres, with 138 groups of helper
 * geometry) binds to the CMU skeleton like the hand-flagged command
 * (--group body --fit --bind-pose tests/data/makehuman_apose.amc); a
 * wrong --group lists the groups; --no-fit and --bind-pose rest keep what
 * they say; a file without a body group keeps its largest closed part.
 * (skinplay drawing that mesh: test_user_mesh_play.c, which needs GL.) */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_paths.h"
#include "test_run.h"
#include "test_weights.h"

#define MH_VERTS 13380
#define MAX_BONES 64
#define TIE       1e-6f  /* weights this close are equal */

/* Dense weights: w[vertex][bone], bones by name in first-seen order. */
typedef struct dense {
	char bone[MAX_BONES][TEST_BONE_NAME];
	int bones;
	float w[MH_VERTS][MAX_BONES];
} dense;

static dense auto_w, hand_w;

static int bone_index(dense *d, const char *name)
{
	for (int i = 0; i < d->bones; i++)
		if (!strcmp(d->bone[i], name))
			return i;
	assert_true(d->bones < MAX_BONES);
	snprintf(d->bone[d->bones], sizeof d->bone[0], "%s", name);
	return d->bones++;
}

static void dense_row(void *ctx, long v, const char *bone, float w)
{
	dense *d = ctx;
	d->w[v][bone_index(d, bone)] = w;
}

static void load_dense(const char *path, dense *d)
{
	memset(d, 0, sizeof *d);
	test_weights_rows(path, MH_VERTS, dense_row, d);
}

static int dominant(const dense *d, long v)
{
	int best = 0;
	for (int b = 1; b < d->bones; b++)
		if (d->w[v][b] > d->w[v][best])
			best = b;
	return best;
}

static float weight_of(const dense *d, long v, const char *name)
{
	for (int b = 0; b < d->bones; b++)
		if (!strcmp(d->bone[b], name))
			return d->w[v][b];
	return 0.0f;
}

/* Is bone `name` among vertex v's top weights in d (tied ones included)? */
static int in_top(const dense *d, long v, const char *name)
{
	return weight_of(d, v, name) >= d->w[v][dominant(d, v)] - TIE;
}

/* Does vertex v keep its dominant bone? Where the top weights tie (0.5 on
 * the hand and 0.5 on the thumb), the tied bones must be the same in both
 * binds: which of them is listed first says nothing. */
static int keeps_dominant(long v)
{
	for (int b = 0; b < hand_w.bones; b++)
		if (in_top(&hand_w, v, hand_w.bone[b]) != in_top(&auto_w, v, hand_w.bone[b]))
			return 0;
	for (int b = 0; b < auto_w.bones; b++)
		if (in_top(&hand_w, v, auto_w.bone[b]) != in_top(&auto_w, v, auto_w.bone[b]))
			return 0;
	return 1;
}

static int is_extremity(const char *bone)
{
	static const char *const part[] = { "wrist", "hand", "finger", "thumb", "foot", "toes" };
	for (size_t i = 0; i < sizeof part / sizeof part[0]; i++)
		if (strstr(bone, part[i]))
			return 1;
	return 0;
}

static char *run_bind(const char *extra, const char *csv)
{
	const char *err = test_scratch("bind.err");
	int st = test_run("%s bind %s %s %s -o %s 2>%s", test_tool_path("skintool"),
			  test_data_path("mocap/cmu/02.asf"), test_data_path("mesh/makehuman/base.obj"),
			  extra, csv, err);
	char *text = test_read_file(err, NULL);
	assert_non_null(text);
	if (st != 0)
		fail_msg("skintool bind %s: exit %d\n%s", extra, st, text);
	return text;
}

/* The tolerance: over the torso, head and limbs (the vertices the
 * hand-flagged run gives to a bone that is not a hand's or a foot's), at
 * least 96% keep their dominant bone and the mean weight change (half the
 * L1 distance) stays within 0.04; over every vertex, 90% (issue 33). */
static void test_makehuman_without_flags(void **state)
{
	(void)state;
	if (!test_data_path("mesh/makehuman/base.obj"))
		skip();
	char *notes = run_bind("", test_scratch("auto.csv"));
	const char *want[] = { "using group 'body' (13380 vertices); left out 138 other groups",
			       "the mesh is 16.66 units tall", "fitted (scale", "--no-fit keeps it",
			       "bound in the mesh's own pose", "'lhumerus' from 0 to -", "'rhumerus' from 0 to -" };
	for (size_t i = 0; i < sizeof want / sizeof want[0]; i++)
		if (!strstr(notes, want[i]))
			fail_msg("the notes lack '%s':\n%s", want[i], notes);
	/* the upper arms end near the hand-made pose's 64 degrees below */
	float elev = 0.0f;
	assert_int_equal(sscanf(strstr(notes, "'lhumerus' from 0 to ") + 21, "%f", &elev), 1);
	assert_true(elev < -54.0f && elev > -74.0f);
	free(notes);
	free(run_bind("--group body --fit --bind-pose tests/data/makehuman_apose.amc", test_scratch("hand.csv")));
	load_dense(test_scratch("auto.csv"), &auto_w);
	load_dense(test_scratch("hand.csv"), &hand_w);
	long n = 0, same = 0, all_same = 0, foot[2] = { 0, 0 }, hand[2] = { 0, 0 };
	double change = 0;
	for (long v = 0; v < MH_VERTS; v++) {
		const char *dom = hand_w.bone[dominant(&hand_w, v)];
		int kept = keeps_dominant(v);
		all_same += kept;
		if (is_extremity(dom)) {
			long *part = strstr(dom, "foot") || strstr(dom, "toes") ? foot : hand;
			part[0]++;
			part[1] += kept;
			continue;
		}
		n++;
		same += kept;
		double d = 0;
		for (int b = 0; b < hand_w.bones; b++)
			d += fabs(hand_w.w[v][b] - weight_of(&auto_w, v, hand_w.bone[b]));
		for (int b = 0; b < auto_w.bones; b++)
			if (weight_of(&hand_w, v, auto_w.bone[b]) == 0.0f)
				d += auto_w.w[v][b];
		change += d / 2;
	}
	print_message("MakeHuman without flags against the hand-flagged run: %ld body vertices, %.1f%% keep "
		      "their dominant bone, mean weight change %.3f\n", n, 100.0 * (double)same / (double)n,
		      change / (double)n);
	/* every vertex, hands and feet included: 65.6% before the guess turned
	 * hands, thumbs, feet and toes (bind_pose_ends.h), 83.1% after, 85.4%
	 * with each limb's chain fitted to the limb (bind_pose_chain.h) and
	 * the mesh fitted again to the guessed pose, 88.7% with the forearm's
	 * end pulled to the arm's thinnest section (bind_pose_narrow.h), 91.7%
	 * with the thumb square to the hand (those with the first-listed of
	 * tied bones taken as dominant; with ties judged as keeps_dominant
	 * does, 87.9% before the thumb, 90.6% after) */
	print_message("and of all %d vertices %.1f%% (hands %.1f%% of %ld, feet %.1f%% of %ld)\n", MH_VERTS,
		      100.0 * (double)all_same / MH_VERTS, 100.0 * (double)hand[1] / (double)hand[0], hand[0],
		      100.0 * (double)foot[1] / (double)foot[0], foot[0]);
	assert_true((double)all_same >= 0.90 * MH_VERTS);
	assert_true(n > 7000);
	assert_true((double)same >= 0.96 * (double)n);
	assert_true(change / (double)n <= 0.04);
}

static void test_flags_keep_what_they_say(void **state)
{
	(void)state;
	if (!test_data_path("mesh/makehuman/base.obj"))
		skip();
	char *notes = run_bind("--no-fit --bind-pose rest", test_scratch("plain.csv"));
	assert_null(strstr(notes, "fitted"));
	assert_null(strstr(notes, "own pose"));
	assert_non_null(strstr(notes, "using group 'body'"));
	free(notes);
	/* under the sanitizers or an emulator in the rest pose, unfitted (the
	 * guessed pose took 6 s of the bind under qemu, 2 s so) */
	notes = run_bind(test_slow() ? "--group body --no-fit --bind-pose rest" : "--group body", test_scratch("group.csv"));
	assert_null(strstr(notes, "left out"));
	free(notes);
	/* a wrong group name: the error, then the groups there are */
	const char *err = test_scratch("nosuch.err");
	assert_int_equal(test_run("%s bind %s %s --group nosuch -o %s 2>%s", test_tool_path("skintool"),
				  test_data_path("mocap/cmu/02.asf"), test_data_path("mesh/makehuman/base.obj"),
				  test_scratch("x.csv"), err), 1);
	char *text = test_read_file(err, NULL);
	assert_non_null(strstr(text, "no faces in group 'nosuch'"));
	assert_non_null(strstr(text, "its groups: body (13378 faces), helper-"));
	free(text);
}

/* No group named body: the largest closed part, not the bigger open one. */
static void test_largest_closed_part(void **state)
{
	(void)state;
	const char *obj = test_scratch("parts.obj"), *asf = test_scratch("parts.asf");
	FILE *f = fopen(asf, "w");
	assert_non_null(f);
	fputs(":root\n position 0 0 0\n:bonedata\n begin\n name a\n direction 0 1 0\n length 2\n"
	      " axis 0 0 0 XYZ\n dof rx\n end\n:hierarchy\n begin\n root a\n end\n", f);
	fclose(f);
	f = fopen(obj, "w");
	assert_non_null(f);
	/* a closed tetrahedron, a bigger open fan, a small closed tetrahedron */
	fputs("v 0 0 0\nv 1 0 0\nv 0 2 0\nv 0 0 1\n"
	      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
	      "v 5 0 0\nv 6 0 0\nv 6 1 0\nv 5 1 0\nv 5.5 2 0\nv 5 3 0\n"
	      "f 5 6 7\nf 5 7 8\nf 8 7 9\nf 8 9 10\n"
	      "v 9 0 0\nv 9.1 0 0\nv 9 0.1 0\nv 9 0 0.1\n"
	      "f 11 13 12\nf 11 12 14\nf 11 14 13\nf 12 13 14\n", f);
	fclose(f);
	const char *err = test_scratch("parts.err"), *csv = test_scratch("parts.csv");
	assert_int_equal(test_run("%s bind %s %s --no-fit --bind-pose rest -o %s 2>%s", test_tool_path("skintool"),
				  asf, obj, csv, err), 0);
	char *text = test_read_file(err, NULL);
	if (!strstr(text, "using its largest closed connected part (4 vertices); left out 2 other parts (10 vertices)"))
		fail_msg("notes: %s", text);
	free(text);
	assert_int_equal(test_run("test $(grep -c '^[0-9]' %s) -ge 4 && ! grep -q '^4,' %s", csv, csv), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_makehuman_without_flags),
		cmocka_unit_test(test_flags_keep_what_they_say),
		cmocka_unit_test(test_largest_closed_part),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
