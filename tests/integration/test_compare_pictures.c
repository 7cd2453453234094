/* The pictures of `skintool compare`'s report, through the real command
 * line, on backflip with the generated body and on 131_04 with the
 * MakeHuman body:
 *   - the renders are real pictures whose LBS and DQBS halves differ, on
 *     the page: the twist scene's close-up shows LBS's candy wrapper and
 *     DQBS's whole cylinder, each worst frame's close-up rings where the
 *     two differ, the difference view colours the body;
 *   - on the MakeHuman body the summary names where DQBS keeps more volume
 *     around a joint than LBS and where it swells more, the renders are of
 *     different joint regions, the page's total time is the command's;
 *   - the page renders in headless Chromium (skipped without it).
 * The tables and verdicts are test_compare_report's. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "png_writer.h"
#include "test_paths.h"
#include "test_report.h"
#include "test_run.h"

static char last_report[1024]; /* backflip's report, for the page in Chromium */

static uint8_t img[2000 * 1400 * 4], img2[2000 * 1400 * 4];

typedef struct picture {
	const uint8_t *px;
	int w, h;
} picture;

static picture load_png(const char *dir, const char *name, uint8_t *buf)
{
	char path[1200];
	skp_error err;
	picture p = { buf, 0, 0 };
	snprintf(path, sizeof path, "%s/%s", dir, name);
	if (png_read_rgba(path, buf, (int)sizeof img, &p.w, &p.h, &err) != 0)
		fail_msg("%s: %s", path, err.msg);
	return p;
}

static const uint8_t *pixel(const picture *p, int x, int y)
{
	return p->px + 4 * ((size_t)y * (size_t)p->w + (size_t)x);
}

static int colour_distance(const uint8_t *a, const uint8_t *b)
{
	return abs(a[0] - b[0]) + abs(a[1] - b[1]) + abs(a[2] - b[2]);
}

/* The renderer's gold (the inset's outline and title, its ring on the
 * body: 1.0, 0.78, 0.15) and the report's ring (255, 196, 0, opaque at
 * its core). */
static int is_gold(const uint8_t *p)
{
	return abs(p[0] - 255) <= 10 && abs(p[1] - 199) <= 12 && abs(p[2] - 38) <= 14;
}

static int is_ring(const uint8_t *p)
{
	return p[0] >= 245 && p[1] >= 182 && p[1] <= 206 && p[2] <= 22;
}

/* Lit skin: red over green over blue, none far below the red (the
 * backgrounds are bluish grey; the difference view's yellow and red are
 * saturated). */
static int is_skin(const uint8_t *p)
{
	return !is_gold(p) && !is_ring(p) && p[0] > p[2] + 35 && p[0] >= p[1] && p[1] > p[2] &&
	       100 * p[2] > 45 * p[0] && 100 * p[1] > 65 * p[0];
}

/* The difference view's colours: dark blue (no difference) and cyan;
 * green, yellow, red (they part by 15 mm and more). */
static int is_diff_blue(const uint8_t *p)
{
	return p[2] > p[0] + 50 && p[2] > 90;
}

static int is_diff_warm(const uint8_t *p)
{
	return !is_gold(p) && (p[1] > p[2] + 40 || p[0] > p[2] + 90) && !is_skin(p);
}

typedef struct rect {
	int x, y, w, h;
} rect;

/* The close-up inset between columns x0 and x1: the square outlined in
 * gold (rows and columns with long gold runs). 0 when there is none. */
static int find_inset(const picture *p, int x0, int x1, rect *r)
{
	int top = -1, bottom = -1, left = -1, right = -1;
	for (int y = 0; y < p->h; y++) {
		int n = 0;
		for (int x = x0; x < x1; x++)
			n += is_gold(pixel(p, x, y));
		if (n >= 80) {
			top = top < 0 ? y : top;
			bottom = y;
		}
	}
	if (top < 0 || bottom - top < 40)
		return 0;
	for (int x = x0; x < x1; x++) {
		int n = 0;
		for (int y = top; y <= bottom; y++)
			n += is_gold(pixel(p, x, y));
		if (n >= 80) {
			left = left < 0 ? x : left;
			right = x;
		}
	}
	if (left < 0 || right - left < 40)
		return 0;
	/* inside the outline */
	*r = (rect){ left + 4, top + 4, right - left - 7, bottom - top - 7 };
	return 1;
}

/* Both halves' insets, the same size, one half-width apart. */
static void find_insets(const picture *p, const char *name, rect in[2])
{
	int hw = p->w / 2;
	for (int i = 0; i < 2; i++)
		if (!find_inset(p, i * hw + hw / 3, (i + 1) * hw, &in[i]))
			fail_msg("%s: no close-up inset in the %s half", name, i ? "right" : "left");
	assert_true(abs(in[1].x - in[0].x - hw) <= 1 && abs(in[1].y - in[0].y) <= 1);
	assert_true(abs(in[1].w - in[0].w) <= 1 && abs(in[1].h - in[0].h) <= 1);
}

typedef struct counts {
	long total, skin[2], blue[2], warm[2], differ;
} counts;

/* Inside r (left half) and the same place in the right half. */
static counts count_in(const picture *p, rect r)
{
	counts c = { 0 };
	int hw = p->w / 2;
	for (int y = r.y; y < r.y + r.h; y++)
		for (int x = r.x; x < r.x + r.w; x++) {
			const uint8_t *a = pixel(p, x, y), *b = pixel(p, x + hw, y);
			c.total++;
			c.differ += colour_distance(a, b) > 60;
			for (int i = 0; i < 2; i++) {
				const uint8_t *q = i ? b : a;
				c.skin[i] += is_skin(q);
				c.blue[i] += is_diff_blue(q);
				c.warm[i] += is_diff_warm(q);
			}
		}
	return c;
}

/* The page shows the picture. */
static void assert_on_page(const char *html, const char *png)
{
	char key[160];
	snprintf(key, sizeof key, "<img src=\"%s\"", png);
	if (!strstr(html, key))
		fail_msg("index.html does not show %s", png);
}

/* Real pictures (not flat) whose halves differ on the body; a whole-body
 * one (not near) equal where the body is not (same camera, same floor). */
static void check_halves(const picture *p, const char *name, int near)
{
	int hw = p->w / 2;
	double sd = test_report_luminance_stddev(p->px, p->w, 0, p->w, 0, p->h);
	long differ = 0, total = 0;
	for (int y = p->h / 8; y < p->h * 7 / 8; y++) /* between the HUD and the panel labels */
		for (int x = 0; x < hw - 1; x++) {
			differ += colour_distance(pixel(p, x, y), pixel(p, x + hw, y)) > 30;
			total++;
		}
	print_message("%s: %dx%d, luminance stddev %.1f, %ld of %ld pixels differ between the halves\n", name, p->w,
		      p->h, sd, differ, total);
	assert_true(sd > 10.0);
	assert_true(differ > 100);           /* the skinning differs */
	if (!near)
		assert_true(differ < total / 3); /* but it is the same pose and camera */
}

/* The twist scene at 180 degrees: in the close-ups the LBS cylinder is
 * pinched to a point at the joint (the candy wrapper), DQBS's whole. */
static void check_twist_scene(const char *dir)
{
	picture p = load_png(dir, "scene_twist.png", img);
	check_halves(&p, "scene_twist.png", 0);
	rect in[2];
	find_insets(&p, "scene_twist.png", in);
	counts c = count_in(&p, in[0]);
	/* the thinnest column of skin near the middle of each inset: the joint
	 * ring, which the close-up is centred on */
	long thin[2] = { in[0].h, in[0].h };
	for (int i = 0; i < 2; i++)
		for (int x = in[i].x + in[i].w * 2 / 5; x < in[i].x + in[i].w * 3 / 5; x++) {
			long n = 0;
			for (int y = in[i].y; y < in[i].y + in[i].h; y++)
				n += is_skin(pixel(&p, x, y));
			thin[i] = n < thin[i] ? n : thin[i];
		}
	print_message("scene_twist.png: insets %dx%d at x %d and %d; skin %.0f%% (LBS) and %.0f%% (DQBS) of them, "
		      "%.0f%% of their pixels differ; the joint's column of skin %ld px (LBS), %ld px (DQBS)\n",
		      in[0].w, in[0].h, in[0].x, in[1].x, 100.0 * c.skin[0] / c.total, 100.0 * c.skin[1] / c.total,
		      100.0 * c.differ / c.total, thin[0], thin[1]);
	assert_true(c.skin[0] > c.total / 10 && c.skin[1] > c.total / 10); /* both show the cylinder */
	assert_true(c.differ > c.total / 7);                               /* and differ substantially */
	assert_true(c.skin[1] > c.skin[0] + c.total / 10);                 /* LBS lost skin at the joint */
	assert_true(thin[1] > in[1].h * 3 / 10);                           /* DQBS: the cylinder's diameter */
	assert_true(thin[0] < in[0].h / 10);                               /* LBS: the candy wrapper's waist */
}

/* The bend scene: a real picture, its close-ups differing. */
static void check_bend_scene(const char *dir)
{
	picture p = load_png(dir, "scene_bend.png", img);
	check_halves(&p, "scene_bend.png", 0);
	rect in[2];
	find_insets(&p, "scene_bend.png", in);
	counts c = count_in(&p, in[0]);
	print_message("scene_bend.png: skin %.0f%% (LBS) and %.0f%% (DQBS) of the insets, %.0f%% of their pixels "
		      "differ\n", 100.0 * c.skin[0] / c.total, 100.0 * c.skin[1] / c.total, 100.0 * c.differ / c.total);
	assert_true(c.skin[0] > c.total / 10 && c.skin[1] > c.total / 10);
	assert_true(c.differ > c.total / 20);
	assert_true(c.skin[1] > c.skin[0]); /* DQBS's knuckle bulges where LBS's elbow is flat */
}

/* A worst frame's close-up: the report's ring, at the same place in both
 * halves, encloses where the two pictures differ. */
static void check_ring_encloses(const char *dir, const char *name)
{
	picture p = load_png(dir, name, img);
	int hw = p.w / 2;
	double cx[2] = { 0, 0 }, cy[2] = { 0, 0 }, n[2] = { 0, 0 };
	for (int y = 0; y < p.h; y++)
		for (int x = 0; x < p.w; x++)
			if (is_ring(pixel(&p, x, y))) {
				int i = x >= hw;
				cx[i] += x, cy[i] += y, n[i]++;
			}
	if (n[0] < 200 || n[1] < 200)
		fail_msg("%s: no ring (%.0f and %.0f ring pixels)", name, n[0], n[1]);
	for (int i = 0; i < 2; i++)
		cx[i] /= n[i], cy[i] /= n[i];
	assert_true(fabs(cx[1] - cx[0] - hw) < 2.0 && fabs(cy[1] - cy[0]) < 2.0);
	double radius = 0;
	for (int y = 0; y < p.h; y++)
		for (int x = 0; x < hw; x++)
			if (is_ring(pixel(&p, x, y)))
				radius += hypot(x - cx[0], y - cy[0]);
	radius /= n[0];
	/* where the halves differ, the ring's band and the HUD and labels
	 * left out: how densely inside the ring and outside, and their
	 * centre, weighted by how much they differ */
	long inside = 0, outside = 0, area_in = 0, area_out = 0;
	double wx = 0, wy = 0, wsum = 0;
	for (int y = p.h / 10; y < p.h * 9 / 10; y++)
		for (int x = 0; x < hw - 1; x++) {
			double d = hypot(x - cx[0], y - cy[0]);
			if (fabs(d - radius) < 8.0)
				continue;
			int dist = colour_distance(pixel(&p, x, y), pixel(&p, x + hw, y)), differ = dist > 60;
			area_in += d < radius;
			area_out += d > radius;
			inside += differ && d < radius;
			outside += differ && d > radius;
			if (differ)
				wx += (double)dist * x, wy += (double)dist * y, wsum += dist;
		}
	double dens_in = (double)inside / (double)area_in, dens_out = area_out ? (double)outside / (double)area_out : 0;
	double off = wsum > 0 ? hypot(wx / wsum - cx[0], wy / wsum - cy[0]) : INFINITY;
	print_message("%s: ring at (%.0f, %.0f) radius %.0f px; %.0f%% of it differs between the halves, %.0f%% "
		      "outside it; where they differ centred %.0f px (%.2f radii) from the ring's centre\n", name, cx[0],
		      cy[0], radius, 100.0 * dens_in, 100.0 * dens_out, off, off / radius);
	assert_true(radius > 20.0 && radius < p.h / 2);
	assert_true(inside > 200);                 /* the two differ in the ring */
	assert_true(dens_in > 1.5 * dens_out);     /* more than elsewhere */
	assert_true(off < 0.75 * radius);          /* and centred inside the ring */
}

/* The difference view: the body coloured (no skin), blue where LBS and
 * DQBS agree, warm somewhere in the close-up where they part; the body
 * view of the same frame shows skin there. */
static void check_difference(const char *dir, const char *body_png, const char *diff_png)
{
	picture b = load_png(dir, body_png, img), d = load_png(dir, diff_png, img2);
	assert_int_equal(b.w, d.w);
	assert_int_equal(b.h, d.h);
	rect ib[2], id[2];
	find_insets(&b, body_png, ib);
	find_insets(&d, diff_png, id);
	counts cb = count_in(&b, ib[0]), cd = count_in(&d, id[0]);
	print_message("%s: in the close-up %.1f%% blue, %.1f%% warm, %.1f%% skin (LBS; DQBS %.1f%%, %.1f%%, %.1f%%); "
		      "%s: %.1f%% skin, %.1f%% blue\n", diff_png, 100.0 * cd.blue[0] / cd.total,
		      100.0 * cd.warm[0] / cd.total, 100.0 * cd.skin[0] / cd.total, 100.0 * cd.blue[1] / cd.total,
		      100.0 * cd.warm[1] / cd.total, 100.0 * cd.skin[1] / cd.total, body_png,
		      100.0 * cb.skin[0] / cb.total, 100.0 * cb.blue[0] / cb.total);
	assert_true(cb.skin[0] > cb.total / 20 && cb.blue[0] < cb.total / 100);
	/* (the ramp's red, shaded, passes for skin in a few pixels) */
	assert_true(cd.skin[0] < cd.total / 25 && cd.skin[1] < cd.total / 25);
	assert_true(cd.blue[0] + cd.warm[0] > cd.total / 20 && cd.blue[1] + cd.warm[1] > cd.total / 20);
	assert_true(cd.warm[0] > 50 && cd.warm[1] > 50);
}

/* The report's pictures: on disk, on the page, and showing what they
 * say they show. */
static void check_pictures(const char *dir, int stills)
{
	char path[1200], name[64];
	snprintf(path, sizeof path, "%s/index.html", dir);
	char *html = test_report_slurp(path);
	assert_on_page(html, "scene_twist.png");
	assert_on_page(html, "scene_bend.png");
	for (int i = 1; i <= stills; i++) {
		static const char *const kinds[3] = { "", "_closeup", "_difference" };
		for (int k = 0; k < 3; k++) {
			snprintf(name, sizeof name, "worst_%d%s.png", i, kinds[k]);
			assert_on_page(html, name);
		}
		snprintf(name, sizeof name, "worst_%d_closeup.png", i);
		check_ring_encloses(dir, name);
	}
	/* the scenes' pictures beside their tables */
	const char *twist_table = strstr(html, "id=\"scene-twist\""), *bend_table = strstr(html, "id=\"scene-bend\"");
	const char *twist_pic = strstr(html, "src=\"scene_twist.png\""), *bend_pic = strstr(html, "src=\"scene_bend.png\"");
	assert_true(twist_table && bend_table && twist_pic && bend_pic);
	assert_true(twist_table < twist_pic && twist_pic < bend_table && bend_table < bend_pic);
	assert_non_null(strstr(twist_pic, "the candy wrapper"));
	free(html);
	picture p = load_png(dir, "worst_1.png", img);
	check_halves(&p, "worst_1.png", 0);
	p = load_png(dir, "worst_1_closeup.png", img);
	check_halves(&p, "worst_1_closeup.png", 1);
	check_difference(dir, "worst_1.png", "worst_1_difference.png");
	check_twist_scene(dir);
	check_bend_scene(dir);
}

static void test_renders(void **state)
{
	(void)state;
	if (!test_data_path("mocap/cmu/backflip.asf"))
		skip();
	char asf[1024], amc[1024];
	snprintf(asf, sizeof asf, "%s", test_data_path("mocap/cmu/backflip.asf"));
	snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/backflip.amc"));
	snprintf(last_report, sizeof last_report, "%s", test_report_compare(asf, amc, "", "backflip"));
	check_pictures(last_report, 4);
}

/* The text of the paragraph with this id, tags stripped. */
static void paragraph(const char *page, const char *id, char *out, size_t cap)
{
	char key[96];
	snprintf(key, sizeof key, "id=\"%s\">", id);
	const char *p = strstr(page, key);
	assert_non_null(p);
	p += strlen(key);
	const char *end = strstr(p, "</p>");
	assert_non_null(end);
	size_t n = 0;
	for (int tag = 0; p < end && n + 1 < cap; p++) {
		if (*p == '<')
			tag = 1;
		else if (*p == '>')
			tag = 0;
		else if (!tag)
			out[n++] = *p;
	}
	out[n] = '\0';
}

/* The MakeHuman body on 131_04: the summary names where DQBS keeps more
 * volume around a joint than LBS and where it swells more, with figures;
 * the renders are of different joint regions; the page's total time is
 * the command's last line's. */
static void test_joint_truths(void **state)
{
	(void)state;
	const char *asf = test_data_path("mocap/cmu/131.asf");
	if (!asf)
		skip();
	char cmd[8192], dir[1100], asf_path[1024], amc[1024], mesh[1024];
	snprintf(asf_path, sizeof asf_path, "%s", asf);
	snprintf(amc, sizeof amc, "%s", test_data_path("mocap/cmu/131_04.amc"));
	snprintf(mesh, sizeof mesh, "%s", test_data_path("mesh/makehuman/base.obj"));
	snprintf(dir, sizeof dir, "%s/truths", test_report_dir());
	/* under the sanitizers or an emulator its first 3 s (at 120 Hz), under
	 * its name: the measurement's time grows with the frames (131_04's
	 * 1,086 took 13 s there), the renders' and the page's does not */
	if (test_slow())
		snprintf(amc, sizeof amc, "%s", test_clip_head(amc, 3 * 120, test_report_dir()));
	snprintf(cmd, sizeof cmd, "%s compare %s %s --mesh %s --renders 3 -o %s", test_tool_path("skintool"), asf_path,
		 amc, mesh, dir);
	assert_int_equal(test_report_sh(cmd, NULL), 0);
	char path[1200], keeps[2048], swells[2048];
	snprintf(path, sizeof path, "%s/index.html", dir);
	char *page = test_report_slurp(path);
	paragraph(page, "verdict-dqbs-keeps", keeps, sizeof keeps);
	paragraph(page, "verdict-dqbs-bulges", swells, sizeof swells);
	print_message("%s\n%s\n", keeps, swells);
	/* a region named with DQBS's and LBS's figures */
	assert_non_null(strstr(keeps, "% against "));
	assert_non_null(strstr(swells, "% against "));
	/* three renders, three joint regions */
	char region[3][32];
	const char *p = page;
	for (int i = 0; i < 3; i++) {
		p = strstr(p, "<h3>");
		assert_non_null(p);
		p = strstr(p, "&mdash; ");
		assert_non_null(p);
		assert_int_equal(sscanf(p, "&mdash; %31s", region[i]), 1);
	}
	assert_true(strcmp(region[0], region[1]) && strcmp(region[0], region[2]) && strcmp(region[1], region[2]));
	/* the close-ups ringed where LBS and DQBS part, the difference view */
	check_pictures(dir, 3);
	/* the timings agree */
	snprintf(path, sizeof path, "%s/stderr.txt", test_report_dir());
	char *err = test_report_slurp(path);
	const char *t = strstr(err, "total ");
	double total = 0, page_total = 0;
	assert_non_null(t);
	assert_int_equal(sscanf(t, "total %lf s", &total), 1);
	const char *q = strstr(page, "this page included, took ");
	assert_non_null(q);
	assert_int_equal(sscanf(q, "this page included, took %lf s", &page_total), 1);
	assert_true(total == page_total);
	free(err);
	free(page);
}

/* Headless Chromium's screenshot of the page: a real, mostly light page
 * with text, tables and pictures in it. */
static void test_page_in_chromium(void **state)
{
	(void)state;
	if (access("/usr/bin/chromium", X_OK) != 0 || !last_report[0])
		skip();
	char cmd[4096], shot[1200], profile[1200], url[1200];
	snprintf(shot, sizeof shot, "%s/screenshot.png", test_report_dir());
	snprintf(profile, sizeof profile, "%s/chromium-profile", test_report_dir());
	if (last_report[0] == '/')
		snprintf(url, sizeof url, "file://%s/index.html", last_report);
	else
		snprintf(url, sizeof url, "file://%s/%s/index.html", getcwd(cmd, sizeof cmd), last_report);
	snprintf(cmd, sizeof cmd, "timeout 120 /usr/bin/chromium --headless --no-sandbox --disable-gpu "
		 "--disable-background-networking --disable-component-update --disable-sync --no-first-run "
		 "--hide-scrollbars --user-data-dir=%s --screenshot=%s --window-size=1200,2000 %s",
		 profile, shot, url);
	double t0 = test_report_now();
	assert_int_equal(test_report_sh(cmd, NULL), 0);
	skp_error err;
	int w, h;
	if (png_read_rgba(shot, img, sizeof img, &w, &h, &err) != 0)
		fail_msg("%s: %s", shot, err.msg);
	assert_int_equal(w, 1200);
	assert_int_equal(h, 2000);
	long dark = 0, light = 0, colour = 0;
	for (long i = 0; i < (long)w * h; i++) {
		const uint8_t *p = img + 4 * i;
		int mx = p[0] > p[1] ? (p[0] > p[2] ? p[0] : p[2]) : (p[1] > p[2] ? p[1] : p[2]);
		int mn = p[0] < p[1] ? (p[0] < p[2] ? p[0] : p[2]) : (p[1] < p[2] ? p[1] : p[2]);
		dark += mx < 90;
		light += mn > 220;
		colour += mx - mn > 60;
	}
	double sd = test_report_luminance_stddev(img, w, 0, w, 0, h);
	print_message("chromium screenshot %dx%d in %.1f s: stddev %.1f, %ld dark, %ld light, %ld coloured pixels\n",
		      w, h, test_report_now() - t0, sd, dark, light, colour);
	assert_true(sd > 20.0);
	assert_true(light > (long)w * h / 4);  /* the page, not a blank or error screen */
	assert_true(dark > 2000);              /* text and the renders' backgrounds */
	assert_true(colour > 2000);            /* the skin and the chart lines */
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_renders),
		cmocka_unit_test(test_joint_truths),
		cmocka_unit_test(test_page_in_chromium),
	};
	return cmocka_run_group_tests_name("compare_pictures", tests, test_report_setup, test_report_teardown);
}
