/* skinplay --background=transparent: headless frames of the character
 * alone, for compositing and checking. The PNG's alpha is 0 round the
 * body and 255 on it, nothing in between (no blended shadow, text or
 * close-up), the corners and the HUD's place are see-through, the body
 * keeps its lit skin colour; one panel and the compare view alike. The
 * usual frames stay opaque everywhere; the option without --out, or with
 * a name it does not know, is refused. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <string.h>

#include "png_writer.h"
#include "test_paths.h"
#include "test_run.h"

#define W 480
#define H 270

static uint8_t px[W * H * 4];

typedef struct alpha_count {
	long clear, opaque, between;
	double r, g, b; /* mean colour of the opaque pixels */
} alpha_count;

static alpha_count count_alpha(const char *path)
{
	skp_error err;
	int w, h;
	alpha_count c = { 0, 0, 0, 0, 0, 0 };
	assert_int_equal(png_read_rgba(path, px, sizeof px, &w, &h, &err), SKP_OK);
	assert_int_equal(w, W);
	assert_int_equal(h, H);
	for (long i = 0; i < (long)W * H; i++) {
		const uint8_t *p = px + 4 * i;
		if (p[3] == 0) {
			c.clear++;
		} else if (p[3] == 255) {
			c.opaque++;
			c.r += p[0], c.g += p[1], c.b += p[2];
		} else {
			c.between++;
		}
	}
	if (c.opaque)
		c.r /= c.opaque, c.g /= c.opaque, c.b /= c.opaque;
	return c;
}

/* The frame skinplay wrote with these options into <scratch>/name/. */
static const char *render(const char *name, const char *options)
{
	const char *dir = test_scratch(name);
	int rc = test_run("%s --image %s --platform surfaceless --size %dx%d --frames 1 %s "
			  "--out '%s' 2>/dev/null", test_tool_path("skinplay"), test_tool_path("assets/demo.skn"),
			  W, H, options, dir);
	assert_int_equal(rc, 0);
	static char path[1200];
	snprintf(path, sizeof path, "%s/frame_000001.png", dir);
	return path;
}

static int all_clear(int x0, int y0, int x1, int y1)
{
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++)
			if (px[4 * (y * W + x) + 3] != 0)
				return 0;
	return 1;
}

static void check_alone(const char *what, const char *path)
{
	alpha_count c = count_alpha(path);
	long total = (long)W * H;
	print_message("%s: %.1f%% of the pixels opaque (the body), %.1f%% see-through, %ld between; the body's mean "
		      "colour %.0f %.0f %.0f\n", what, 100.0 * c.opaque / total, 100.0 * c.clear / total, c.between,
		      c.r, c.g, c.b);
	assert_int_equal(c.between, 0);
	assert_true(c.opaque > total / 100 && c.opaque < total / 3);
	assert_true(c.r > c.g && c.g > c.b && c.r > 80); /* lit skin, not black or the backdrop */
	assert_true(all_clear(0, 0, W / 10, H / 20));    /* where the HUD begins */
	assert_true(all_clear(0, H - 4, W, H));          /* no floor, labels or captions at the foot */
	assert_true(all_clear(W - 4, 0, W, H));
}

static void test_character_alone(void **state)
{
	(void)state;
	check_alone("dqbs", render("one", "--algo dqbs --hud engineer --background=transparent"));
	check_alone("compare", render("two", "--algo compare --hud visitor --background=transparent"));
}

static void test_scene_stays_opaque(void **state)
{
	(void)state;
	alpha_count c = count_alpha(render("scene", "--algo compare --hud engineer"));
	assert_int_equal(c.clear + c.between, 0);
}

static void test_refused(void **state)
{
	(void)state;
	const char *err = test_scratch("err.txt");
	assert_int_equal(test_run("%s --image %s --platform surfaceless --frames 1 --background=transparent 2>'%s'",
				  test_tool_path("skinplay"), test_tool_path("assets/demo.skn"), err),
			 1);
	static const char *const no_out[] = { "--background=transparent", "give --out too", NULL };
	test_assert_contains_all(err, no_out);
	assert_int_equal(test_run("%s --image %s --background=glass -o '%s' 2>'%s'", test_tool_path("skinplay"),
				  test_tool_path("assets/demo.skn"), test_scratch("x"), err),
			 1);
	static const char *const bad[] = { "glass", "scene", "transparent", NULL };
	test_assert_contains_all(err, bad);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_character_alone),
		cmocka_unit_test(test_scene_stays_opaque),
		cmocka_unit_test(test_refused),
	};
	return cmocka_run_group_tests_name("background", tests, test_scratch_setup, test_scratch_teardown);
}
