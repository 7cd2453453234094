/* Rendering for real, headless (surfaceless EGL and OSMesa on Mesa's
 * llvmpipe): golden images, CPU against GPU skinning, the compare view of
 * a twisted joint, and the default show framed whole above its captions on
 * a landscape, a portrait and a rotated screen. Images come from the built
 * skinplay. */
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
#include "render_internal.h"
#include "test_paths.h"
#include "test_run.h"

#define MAX_PIXELS (960 * 540)

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
		/* panel columns: the body in the panel's left 36%, the joint in
		 * its middle, the tube's ends towards its sides; the close-up in
		 * the rest (rows between the HUD and the labels) */
		double joint = halves_diff(&got, 48, 68, 165, 195);
		double ends = (halves_diff(&got, 12, 34, 165, 195) + halves_diff(&got, 82, 104, 165, 195)) / 2;
		double inset = halves_diff(&got, 135, 310, 90, 255);
		print_message("lower arm twisted %d deg: LBS vs DQBS mean difference %.2f at the joint, %.2f at the ends, "
			      "%.2f in the close-up\n", frame == 2 ? 170 : 0, joint, ends, inset);
		if (frame == 1) {
			/* no twist: the same picture, and no close-up of nothing */
			assert_true(joint < 1.0 && ends < 1.0 && inset < 1.0);
		} else {
			assert_true(joint > 10.0);  /* LBS collapses, DQBS does not */
			assert_true(ends < 3.0);    /* away from the joint they agree */
			assert_true(inset > 30.0);  /* and the close-up shows it large */
		}
	}
	unlink(tube);
}

/* ---- the default show's layout ---- */

/* The visitor's text colours (render_draw.c): the methods' names white,
 * the sentences above them gold; exact, the font being drawn unfiltered. */
static int near(const uint8_t *p, int r, int g, int b)
{
	return abs(p[0] - r) <= 2 && abs(p[1] - g) <= 2 && abs(p[2] - b) <= 2;
}

static int is_label(const uint8_t *p)
{
	return near(p, 255, 255, 255);
}

static int is_caption(const uint8_t *p)
{
	return near(p, 242, 217, 140);
}

/* The body, lit or in shade: red well over blue (the floor, the grid, the
 * shadow and the background are blue-grey), and not caption text. */
static int is_body(const uint8_t *p)
{
	return p[0] > 40 && p[0] > p[2] + 15 && !is_caption(p);
}

typedef struct rows {
	int top, bottom;  /* first and last row from the top; top > bottom: none */
} rows;

typedef struct panel_check {
	int x0, y0, x1, y1;      /* the panel, rows from the top, [x0, x1) x [y0, y1) */
	int bx0, by0, bx1, by1;  /* the body's box (inclusive); bx0 > bx1: no body */
	rows label, caption;     /* the text's rows */
	long body;               /* body pixels */
} panel_check;

static const uint8_t *px(const image *im, int x, int y)
{
	return im->px + ((size_t)y * im->w + x) * 4;
}

static void measure_panel(const image *im, panel_check *c)
{
	c->bx0 = c->by0 = INT32_MAX;
	c->bx1 = c->by1 = -1;
	c->label = c->caption = (rows){ INT32_MAX, -1 };
	c->body = 0;
	for (int y = c->y0; y < c->y1; y++)
		for (int x = c->x0; x < c->x1; x++) {
			const uint8_t *p = px(im, x, y);
			rows *t = is_label(p) ? &c->label : is_caption(p) ? &c->caption : NULL;
			if (t) {
				t->top = y < t->top ? y : t->top;
				t->bottom = y > t->bottom ? y : t->bottom;
			} else if (is_body(p)) {
				c->body++;
				c->bx0 = x < c->bx0 ? x : c->bx0;
				c->bx1 = x > c->bx1 ? x : c->bx1;
				c->by0 = y < c->by0 ? y : c->by0;
				c->by1 = y > c->by1 ? y : c->by1;
			}
		}
}

typedef struct show_stats {
	int frames;
	double worst_gap;     /* the least room between the feet and the captions, rows */
	double least_edge;    /* the least room between the body and its panel's edge */
	double least_height;  /* the smallest body, as a share of its panel's height */
} show_stats;

/* One frame of the compare view: in each panel the body lies inside, clear
 * of the edges, and wholly above the captions and names (so no caption
 * pixel covers a body pixel), and both panels' texts are in one size. */
static void check_frame(const image *im, int portrait, int n, show_stats *st)
{
	panel_check c[2];
	for (int i = 0; i < 2; i++) {
		memset(&c[i], 0, sizeof c[i]);
		c[i].x0 = portrait ? 0 : i * im->w / 2;
		c[i].x1 = portrait ? im->w : (i + 1) * im->w / 2;
		c[i].y0 = portrait ? i * im->h / 2 : 0;
		c[i].y1 = portrait ? (i + 1) * im->h / 2 : im->h;
		/* the divider's line is the panels' border: left out */
		c[i].x0 += !portrait && i;
		c[i].y0 += portrait && i;
		measure_panel(im, &c[i]);
		if (c[i].body < 200 || c[i].caption.top > c[i].caption.bottom || c[i].label.top > c[i].label.bottom)
			fail_msg("frame %d panel %d: %ld body pixels, caption rows %d..%d, label rows %d..%d", n, i, c[i].body,
				 c[i].caption.top, c[i].caption.bottom, c[i].label.top, c[i].label.bottom);
		int text_top = c[i].caption.top < c[i].label.top ? c[i].caption.top : c[i].label.top;
		int edge = c[i].bx0 - c[i].x0;
		edge = c[i].x1 - 1 - c[i].bx1 < edge ? c[i].x1 - 1 - c[i].bx1 : edge;
		edge = c[i].by0 - c[i].y0 < edge ? c[i].by0 - c[i].y0 : edge;
		if (edge < 1 || c[i].by1 >= text_top)
			fail_msg("frame %d panel %d (%dx%d from %d,%d): body box x %d..%d y %d..%d, the text from row %d", n, i,
				 c[i].x1 - c[i].x0, c[i].y1 - c[i].y0, c[i].x0, c[i].y0, c[i].bx0, c[i].bx1, c[i].by0,
				 c[i].by1, text_top);
		st->worst_gap = fmin(st->worst_gap, text_top - 1 - c[i].by1);
		st->least_edge = fmin(st->least_edge, edge);
		st->least_height = fmin(st->least_height, (double)(c[i].by1 - c[i].by0 + 1) / (c[i].y1 - c[i].y0));
	}
	/* one size per role: the same rows in both panels, offset by the panel */
	int dy = portrait ? im->h / 2 : 0;
	if (c[1].caption.bottom - c[1].caption.top != c[0].caption.bottom - c[0].caption.top ||
	    c[1].label.bottom - c[1].label.top != c[0].label.bottom - c[0].label.top ||
	    c[1].label.top - dy != c[0].label.top || c[1].caption.top - dy != c[0].caption.top)
		fail_msg("frame %d: caption rows %d..%d and %d..%d, label rows %d..%d and %d..%d: not one size", n,
			 c[0].caption.top, c[0].caption.bottom, c[1].caption.top, c[1].caption.bottom, c[0].label.top,
			 c[0].label.bottom, c[1].label.top, c[1].label.bottom);
	st->frames++;
}

static void load_frame(const char *dir, int n, image *im)
{
	char path[512];
	skp_error err;
	snprintf(path, sizeof path, "%s/frame_%06d.png", dir, n);
	if (png_read_rgba(path, im->px, sizeof im->px, &im->w, &im->h, &err) != 0)
		fail_msg("%s: %s", path, err.msg);
}

static void show_layout(const char *size, int portrait)
{
	char dir[128];
	/* under the sanitizers or an emulator a frame a second of show, not
	 * two (the 96 frames of a size took 6 to 11 s there) */
	const double hz = test_slow() ? 1 : 2;
	snprintf(dir, sizeof dir, "%s/show", tmpdir());
	test_show_compare(size, hz, "", dir);
	show_stats st = { 0, 1e9, 1e9, 1e9 };
	for (int n = 1;; n++) {
		char path[512];
		snprintf(path, sizeof path, "%s/frame_%06d.png", dir, n);
		if (access(path, R_OK) != 0)
			break;
		load_frame(dir, n, &got);
		check_frame(&got, portrait, n, &st);
	}
	print_message("default show at %s: %d frames, each panel's body inside it (%.0f px from its edge at least) and "
		      "above the captions (%.0f rows at least), at least %.0f%% of the panel's height\n", size, st.frames,
		      st.least_edge, st.worst_gap, 100 * st.least_height);
	assert_true(st.frames >= 45 * hz); /* 47 s of show: 02_01, lambada, kick and the tour */
	char cmd[256];
	snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
	assert_int_equal(system(cmd), 0);
}

static void test_show_landscape(void **state)
{
	(void)state;
	show_layout("960x540", 0);
}

static void test_show_portrait(void **state)
{
	(void)state;
	show_layout("540x960", 1);
}

/* A landscape panel turned a quarter (--rotation 90) shows what a portrait
 * screen of its size shows, turned. */
static void test_show_rotated(void **state)
{
	(void)state;
	char a[128], b[128];
	snprintf(a, sizeof a, "%s/upright", tmpdir());
	snprintf(b, sizeof b, "%s/turned", tmpdir());
	test_show_compare("540x960", 2, "--frames 20 --every 19", a);
	test_show_compare("960x540", 2, "--rotation 90 --frames 20 --every 19", b);
	load_frame(a, 20, &want);
	load_frame(b, 20, &got);
	assert_int_equal(got.w, want.h);
	assert_int_equal(got.h, want.w);
	long off = 0;
	show_stats st = { 0, 1e9, 1e9, 1e9 };
	check_frame(&want, 1, 20, &st);
	for (int y = 0; y < want.h; y++)
		for (int x = 0; x < want.w; x++) {
			/* mat4_rotate_z90 turns the picture a quarter counter-clockwise:
			 * logical column x, row y to physical column y, row h - 1 - x */
			const uint8_t *p = px(&want, x, y), *q = px(&got, y, got.h - 1 - x);
			off += abs(p[0] - q[0]) > 3 || abs(p[1] - q[1]) > 3 || abs(p[2] - q[2]) > 3;
		}
	print_message("--rotation 90: %ld of %d pixels differ from the portrait picture turned\n", off, want.w * want.h);
	assert_true(off < want.w * want.h / 200);
}

/* The weights view names its colours: over the body, in the band at the
 * top, each bone that carries skin written in the colour the body takes
 * where that bone alone moves it (20 of the CMU skeleton's 31 bones carry
 * the MakeHuman body's own weights). */
static void test_weights_legend(void **state)
{
	(void)state;
	char dir[128];
	snprintf(dir, sizeof dir, "%s/weights", tmpdir());
	test_show_compare("960x540", 2, "--view weights --frames 1", dir);
	load_frame(dir, 1, &got);
	int named = 0, lowest = 0;
	for (int b = 0; b < 31; b++) {
		vec3 c = render_bone_color(b);
		int r = (int)lroundf(c.x * 255), g = (int)lroundf(c.y * 255), bl = (int)lroundf(c.z * 255);
		long n = 0;
		for (int y = 0; y < 48; y++)
			for (int x = 0; x < got.w; x++)
				if (near(px(&got, x, y), r, g, bl)) {
					n++;
					lowest = y > lowest ? y : lowest;
				}
		named += n >= 20;
	}
	print_message("weights view: %d of 31 bones named in their colour in the top 48 rows (down to row %d)\n", named,
		      lowest);
	assert_true(named >= 18);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_weights_legend),
		cmocka_unit_test(test_show_landscape),
		cmocka_unit_test(test_show_portrait),
		cmocka_unit_test(test_show_rotated),
		cmocka_unit_test(test_golden_surfaceless),
		cmocka_unit_test(test_golden_osmesa),
		cmocka_unit_test(test_cpu_and_gpu_skinning_agree),
		cmocka_unit_test(test_compare_view_of_a_twist),
	};
	int rc = cmocka_run_group_tests_name("render", tests, NULL, NULL);
	rmdir(tmpdir());
	return rc;
}
