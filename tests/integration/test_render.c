/* Rendering for real, headless (surfaceless EGL and OSMesa on Mesa's
 * llvmpipe): golden images, CPU against GPU skinning, and the compare
 * view of a twisted joint. Images come from the built skinplay. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "png_writer.h"
#include "test_paths.h"

#define MAX_PIXELS (640 * 360)

typedef struct image {
	int w, h;
	uint8_t px[MAX_PIXELS * 4];
} image;

static image got, want, diff;

static void make_tube(const char *path)
{
	FILE *f = fopen(path, "w");
	const int rings = 41, seg = 24;
	assert_non_null(f);
	for (int i = 0; i < rings; i++)
		for (int j = 0; j < seg; j++) {
			double a = 2 * M_PI * j / seg;
			fprintf(f, "v %.6f %.6f %.6f\n", 4.0 * i / (rings - 1), 0.3 * cos(a), 0.3 * sin(a));
		}
	fprintf(f, "v 0 0 0\nv 4 0 0\n");
	int c0 = rings * seg + 1, c1 = c0 + 1, last = (rings - 1) * seg;
	for (int i = 0; i < rings - 1; i++)
		for (int j = 0; j < seg; j++) {
			int a = i * seg + j + 1, b = i * seg + (j + 1) % seg + 1;
			int c = (i + 1) * seg + (j + 1) % seg + 1, d = (i + 1) * seg + j + 1;
			fprintf(f, "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d);
		}
	for (int j = 0; j < seg; j++)
		fprintf(f, "f %d %d %d\nf %d %d %d\n", c0, (j + 1) % seg + 1, j + 1, c1, last + j + 1,
			last + (j + 1) % seg + 1);
	fclose(f);
}

/* Runs skinplay with args writing one frame into dir; loads it into img. */
static void render(const char *args, const char *dir, image *img)
{
	char cmd[2048];
	skp_error err;
	/* Under ASan, LeakSanitizer's exit scan can crash on llvmpipe's worker
	 * threads; memory errors are still checked, and skinplay's own code
	 * allocates nothing. */
	snprintf(cmd, sizeof cmd, "ASAN_OPTIONS=detect_leaks=0 %s %s --hud-fps off --frames 1 --out %s 2>/dev/null",
		 test_tool_path("skinplay"), args, dir);
	int status = system(cmd);
	if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
		fail_msg("failed: %s", cmd);
	snprintf(cmd, sizeof cmd, "%s/frame_000001.png", dir);
	if (png_read_rgba(cmd, img->px, sizeof img->px, &img->w, &img->h, &err) != 0)
		fail_msg("%s: %s", cmd, err.msg);
	unlink(cmd);
}

static const char *tmpdir(void)
{
	static char dir[64];
	if (!dir[0]) {
		strcpy(dir, "/tmp/skp_render_XXXXXX");
		assert_non_null(mkdtemp(dir));
	}
	return dir;
}

/* Pixels differing by more than 3 levels in a channel; the diff image
 * marks them (red) over a dimmed copy. */
static double bad_fraction(const image *a, const image *b, image *d)
{
	long bad = 0, n = (long)a->w * a->h;
	d->w = a->w;
	d->h = a->h;
	for (long i = 0; i < n; i++) {
		int worst = 0;
		for (int c = 0; c < 3; c++) {
			int e = abs(a->px[4 * i + c] - b->px[4 * i + c]);
			worst = e > worst ? e : worst;
		}
		bad += worst > 3;
		uint8_t g = (uint8_t)(a->px[4 * i + 1] / 3);
		d->px[4 * i] = worst > 3 ? 255 : g;
		d->px[4 * i + 1] = worst > 3 ? 0 : g;
		d->px[4 * i + 2] = worst > 3 ? 0 : g;
		d->px[4 * i + 3] = 255;
	}
	return (double)bad / (double)n;
}

static void golden(const char *platform)
{
	char args[1024], path[256], dpath[256];
	skp_error err;
	snprintf(args, sizeof args,
		 "--asf assets/demo.asf --amc %s/assets/demo.amc --algo compare --platform %s --size 320x180 --start 641",
		 getenv("SKP_BUILD") ? getenv("SKP_BUILD") : "build", platform);
	render(args, tmpdir(), &got);
	snprintf(path, sizeof path, "tests/golden/compare_641_%s.png", platform);
	if (getenv("SKP_UPDATE_GOLDEN")) {
		assert_int_equal(png_write_rgba(path, got.px, got.w, got.h, 0, &err), 0);
		print_message("wrote %s\n", path);
	}
	if (png_read_rgba(path, want.px, sizeof want.px, &want.w, &want.h, &err) != 0)
		fail_msg("%s: %s (SKP_UPDATE_GOLDEN=1 make test writes it)", path, err.msg);
	assert_int_equal(got.w, want.w);
	assert_int_equal(got.h, want.h);
	double bad = bad_fraction(&got, &want, &diff);
	print_message("%s: %.3f%% of pixels off by more than 3 levels\n", platform, 100 * bad);
	if (bad > 0.005) {
		snprintf(dpath, sizeof dpath, "%s/golden_diff_%s.png",
			 getenv("SKP_BUILD") ? getenv("SKP_BUILD") : "build", platform);
		png_write_rgba(dpath, diff.px, diff.w, diff.h, 0, &err);
		fail_msg("%s differs from the golden image: diff in %s", platform, dpath);
	}
}

static void test_golden_surfaceless(void **state)
{
	(void)state;
	golden("surfaceless");
}

static void test_golden_osmesa(void **state)
{
	(void)state;
	golden("osmesa");
}

static double psnr(const image *a, const image *b)
{
	double se = 0;
	long n = (long)a->w * a->h;
	for (long i = 0; i < n; i++)
		for (int c = 0; c < 3; c++) {
			double e = a->px[4 * i + c] - b->px[4 * i + c];
			se += e * e;
		}
	double mse = se / (3.0 * (double)n);
	return mse == 0 ? 99.0 : 10.0 * log10(255.0 * 255.0 / mse);
}

static void test_cpu_and_gpu_skinning_agree(void **state)
{
	(void)state;
	static const char *const algos[] = { "lbs", "dqbs" };
	for (int a = 0; a < 2; a++) {
		char args[1024];
		const char *b = getenv("SKP_BUILD") ? getenv("SKP_BUILD") : "build";
		snprintf(args, sizeof args,
			 "--asf assets/demo.asf --amc %s/assets/demo.amc --algo %s --platform surfaceless --size 640x360 --start 641 --skin cpu",
			 b, algos[a]);
		render(args, tmpdir(), &want);
		snprintf(args, sizeof args,
			 "--asf assets/demo.asf --amc %s/assets/demo.amc --algo %s --platform surfaceless --size 640x360 --start 641 --skin gpu",
			 b, algos[a]);
		render(args, tmpdir(), &got);
		/* the HUD says CPU or GPU: compare below it */
		long skip = (long)got.w * 40 * 4;
		image *x = &got, *y = &want;
		memset(x->px + (size_t)(x->w * x->h * 4 - skip), 0, (size_t)skip);
		memset(y->px + (size_t)(y->w * y->h * 4 - skip), 0, (size_t)skip);
		double p = psnr(x, y);
		print_message("%s: CPU vs GPU skinning PSNR %.1f dB\n", algos[a], p);
		assert_true(p >= 40.0);
	}
}

/* mean difference between the two halves over columns [x0, x1) of a panel
 * and rows [y0, y1) (rows counted from the top) */
static double halves_diff(const image *im, int x0, int x1, int y0, int y1)
{
	int half = im->w / 2;
	double s = 0;
	long n = 0;
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++)
			for (int c = 0; c < 3; c++, n++)
				s += abs(im->px[((size_t)y * im->w + x) * 4 + c] -
					 im->px[((size_t)y * im->w + half + x) * 4 + c]);
	return s / (double)n;
}

static void test_compare_view_of_a_twist(void **state)
{
	(void)state;
	char args[1024], tube[128];
	snprintf(tube, sizeof tube, "%s/tube.obj", tmpdir());
	make_tube(tube);
	for (int frame = 1; frame <= 2; frame++) {
		snprintf(args, sizeof args,
			 "--asf tests/data/twist.asf --amc tests/data/twist.amc --mesh %s --algo compare --platform surfaceless --size 640x360 --yaw 0 --start %d",
			 tube, frame);
		render(args, tmpdir(), &got);
		/* panel columns: the joint is in the middle of each half, the
		 * tube's ends towards its sides; rows between the HUD and labels */
		double joint = halves_diff(&got, 140, 180, 120, 230);
		double ends = (halves_diff(&got, 70, 115, 120, 230) + halves_diff(&got, 215, 260, 120, 230)) / 2;
		print_message("lower arm twisted %d deg: LBS vs DQBS mean difference %.2f at the joint, %.2f at the ends\n",
			      frame == 2 ? 170 : 0, joint, ends);
		if (frame == 1) {
			assert_true(joint < 1.0 && ends < 1.0); /* no twist: the same picture */
		} else {
			assert_true(joint > 10.0);  /* LBS collapses, DQBS does not */
			assert_true(ends < 3.0);    /* away from the joint they agree */
		}
	}
	unlink(tube);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_golden_surfaceless),
		cmocka_unit_test(test_golden_osmesa),
		cmocka_unit_test(test_cpu_and_gpu_skinning_agree),
		cmocka_unit_test(test_compare_view_of_a_twist),
	};
	int rc = cmocka_run_group_tests_name("render", tests, NULL, NULL);
	rmdir(tmpdir());
	return rc;
}
