/* The rig corpus (issue 33's acceptance): every skinned model Debian's
 * assimp-testmodels ships, the rigs in tests/data/rigs (CesiumMan,
 * RiggedFigure), the shared CC0 glb, and every rig in $SKP_RIGS (public
 * Mixamo-rigged and Unity-named characters that may not be redistributed:
 * skipped, saying so, when unset), each bound with its own weights and
 * played in CMU's walk (02_01) and kick. Every one either plays (exit 0,
 * weights written) with no vertex leaving the posed skeleton by more than
 * 12% of its extent over the clip, or exits 1 with a last line naming the
 * file and the reason. The well-made humanoids must play: CesiumMan,
 * RiggedFigure, the shared glb, and of $SKP_RIGS the Mixamo characters
 * (Xbot, Soldier, Michelle, Mannequin, Ely) and the Unity-named one
 * (RobotExpressive). A table of the figures is printed. Under the
 * sanitizers or an emulator (test_slow) the samples are left out. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test_paths.h"
#include "test_run.h"

#define SAMPLES "/usr/share/assimp/models/"
#define DRIFT_LIMIT 12.0

/* The assimp-testmodels samples with a skin (joints and weights). */
static const char *const samples[] = {
	"X/BCN_Epileptic.X", "X/Testwuson.X", "X/anim_test.x", "X/test_cube_text.x", "X/test_cube_binary.x",
	"X/test_cube_compressed.x", "FBX/huesitos.fbx", "FBX/animation_with_skeleton.fbx",
	"glTF2/simple_skin/simple_skin.gltf", "Collada/box_nested_animation.dae", "Collada/cameras.dae",
	"Collada/lights.dae", "SMD/WusonSMD.smd", "SMD/holy_grailref.smd", "SMD/triangle.smd",
	"MD5/SimpleCube.md5mesh",
};

static const char *const must_play[] = {
	"CesiumMan.glb", "rigged-figure-test.dae", "male_base_mesh.glb", "Xbot.glb", "Soldier.glb", "Michelle.glb",
	"Mannequin.glb", "Ely.glb", "RobotExpressive.glb",
};

static int is_must_play(const char *path)
{
	const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
	for (size_t i = 0; i < sizeof must_play / sizeof must_play[0]; i++)
		if (strcmp(base, must_play[i]) == 0)
			return 1;
	return 0;
}

/* The number after "marker" in the file, or -1. */
static double figure_after(const char *path, const char *marker)
{
	size_t n;
	char *text = test_read_file(path, &n);
	double v = -1.0;
	const char *at = text ? strstr(text, marker) : NULL;
	if (at)
		v = atof(at + strlen(marker));
	free(text);
	return v;
}

/* The file's last line into out. */
static void last_line(const char *path, char *out, size_t cap)
{
	size_t n;
	char *text = test_read_file(path, &n);
	out[0] = '\0';
	if (!text)
		return;
	while (n > 0 && text[n - 1] == '\n')
		text[--n] = '\0';
	const char *nl = strrchr(text, '\n');
	snprintf(out, cap, "%s", nl ? nl + 1 : text);
	free(text);
}

static int failures, played, refused;

static void one(const char *rig, const char *asf, const char *amc, const char *clip)
{
	const char *log = test_scratch("corpus.log"), *w = test_scratch("corpus.csv");
	unlink(w);
	int rc = test_run("%s bind '%s' '%s' --weights mesh --motion '%s' --report -o %s 2> %s",
			  test_tool_path("skintool"), asf, rig, amc, w, log);
	const char *base = strrchr(rig, '/') ? strrchr(rig, '/') + 1 : rig;
	char why[4096];
	last_line(log, why, sizeof why);
	if (rc == 0) {
		double drift = figure_after(log, "grew by "), closer = figure_after(log, "and shrank by ");
		printf("corpus: %-28s %-6s plays: vertex-to-skeleton distance grew by %.2f%% of the extent at most "
		       "(shrank by %.2f%%)\n", base, clip, drift, closer);
		played++;
		if (!(drift >= 0.0 && drift <= DRIFT_LIMIT) || access(w, F_OK) != 0) {
			printf("corpus: FAILED %s %s: exit 0 with drift %.2f%% or no weights\n", base, clip, drift);
			failures++;
		}
		return;
	}
	printf("corpus: %-28s %-6s refused (exit %d): %s\n", base, clip, rc, why);
	refused++;
	if (rc != 1 || !strstr(why, base) || access(w, F_OK) == 0 || is_must_play(rig)) {
		printf("corpus: FAILED %s %s: %s\n", base, clip,
		       is_must_play(rig) ? "a well-made humanoid must play" : "not a clean refusal naming the file");
		failures++;
	}
}

static void run_rig(const char *rig)
{
	char walk_asf[4096], walk_amc[4096], kick_asf[4096], kick_amc[4096];
	snprintf(walk_asf, sizeof walk_asf, "%s", test_data_path("mocap/cmu/02.asf"));
	snprintf(walk_amc, sizeof walk_amc, "%s", test_data_path("mocap/cmu/02_01.amc"));
	snprintf(kick_asf, sizeof kick_asf, "%s", test_data_path("mocap/cmu/kick.asf"));
	snprintf(kick_amc, sizeof kick_amc, "%s", test_data_path("mocap/cmu/kick.amc"));
	one(rig, walk_asf, walk_amc, "walk");
	one(rig, kick_asf, kick_amc, "kick");
}

static int has_rig_extension(const char *name)
{
	static const char *const ext[] = { ".glb", ".gltf", ".fbx", ".dae", ".zae", ".x", ".blend" };
	const char *dot = strrchr(name, '.');
	for (size_t i = 0; dot && i < sizeof ext / sizeof ext[0]; i++)
		if (strcasecmp(dot, ext[i]) == 0)
			return 1;
	return 0;
}

static int cmp_str(const void *a, const void *b)
{
	return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Every rig file in dir, sorted; the names are the caller's to free. */
static int list_rigs(const char *dir, char **names, int cap)
{
	DIR *d = opendir(dir);
	int n = 0;
	struct dirent *e;
	while (d && (e = readdir(d)) != NULL && n < cap)
		if (e->d_name[0] != '.' && has_rig_extension(e->d_name))
			names[n++] = strdup(e->d_name);
	if (d)
		closedir(d);
	qsort(names, (size_t)n, sizeof names[0], cmp_str);
	return n;
}

static void test_corpus(void **state)
{
	(void)state;
	if (!test_data_path("mocap/cmu/kick.amc"))
		skip();
	char path[4096];
	failures = played = refused = 0;
	run_rig("tests/data/rigs/CesiumMan.glb");
	run_rig("tests/data/rigs/rigged-figure-test.dae");
	snprintf(path, sizeof path, "%s", test_data_path("mesh/orange_juice_male_base/male_base_mesh.glb"));
	run_rig(path);
	int sampled = 0;
	/* under the sanitizers or an emulator the rigs above only: `make
	 * import-sweep` binds every sample under ASan, and the native run
	 * plays them all */
	for (size_t i = 0; !test_slow() && i < sizeof samples / sizeof samples[0]; i++) {
		snprintf(path, sizeof path, SAMPLES "%s", samples[i]);
		if (access(path, R_OK) == 0) {
			run_rig(path);
			sampled++;
		}
	}
	if (test_slow())
		printf("corpus: under the sanitizers or an emulator: assimp-testmodels' samples left to the native run\n");
	else if (!sampled)
		printf("corpus: assimp-testmodels is not installed (apt-get install assimp-testmodels): its samples skipped\n");
	const char *rigs = getenv("SKP_RIGS");
	if (!rigs || !*rigs) {
		printf("corpus: SKP_RIGS is not set: the public rigs that may not be kept here (Mixamo, Unity-named) "
		       "skipped\n");
	} else {
		char *names[256];
		int n = list_rigs(rigs, names, 256);
		for (int i = 0; i < n; i++) {
			snprintf(path, sizeof path, "%s/%s", rigs, names[i]);
			run_rig(path);
			free(names[i]);
		}
		if (!n)
			printf("corpus: no rig files in SKP_RIGS=%s\n", rigs);
	}
	printf("corpus: %d plays, %d refusals, %d failures\n", played, refused, failures);
	assert_int_equal(failures, 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_corpus),
	};
	return cmocka_run_group_tests(tests, test_scratch_setup, test_scratch_teardown);
}
