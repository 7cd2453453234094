/* board.ini: the real board files parse; every kind of mistake is a
 * problem naming the line and the key, the key keeping its default and
 * the reading going on (a kiosk never stops over its config); a UTF-8 byte
 * order mark is no mistake. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "board_config.h"
#include "test_paths.h"

static board_config cfg;

static skp_status parse(const char *text, skp_error *err)
{
	skp_mem_source src;
	return board_config_read(&cfg, skp_mem_reader(&src, text, strlen(text)), err);
}

static void parse_file(const char *path)
{
	size_t n;
	char *text = test_read_file(path, &n);
	assert_non_null(text);
	skp_mem_source src;
	skp_error err;
	skp_status st = board_config_read(&cfg, skp_mem_reader(&src, text, n), &err);
	free(text);
	if (st != SKP_OK)
		fail_msg("%s:%ld: %s", path, err.line, err.msg);
	if (cfg.problem_count)
		fail_msg("%s:%ld: %s", path, cfg.problem[0].line, cfg.problem[0].msg);
}

static void test_rpi4_board(void **state)
{
	(void)state;
	parse_file("board/rpi4/board.ini");
	static const unsigned lines[CONTROL_BTN_COUNT] = { 17, 27, 22, 23 };
	assert_string_equal(cfg.platform, "kms");
	assert_string_equal(cfg.input, "gpio");
	assert_string_equal(cfg.chip, "pinctrl-bcm2711");
	assert_int_equal(cfg.width, 1920);
	assert_int_equal(cfg.height, 1080);
	assert_int_equal(cfg.rotation, 0);
	assert_int_equal(cfg.hud, BOARD_HUD_VISITOR);
	assert_int_equal(cfg.algo, SKIN_COMPARE);
	assert_int_equal(cfg.view, RENDER_VIEW_BODY);
	for (int b = 0; b < CONTROL_BTN_COUNT; b++) {
		assert_true(cfg.button[b].present);
		assert_int_equal(cfg.button[b].line, lines[b]);
		assert_true(cfg.button[b].active_low);
		assert_int_equal(cfg.button[b].bias, BOARD_BIAS_PULL_UP);
		assert_int_equal(cfg.button[b].deb.debounce_ms, 30);
		assert_int_equal(cfg.button[b].deb.long_press_ms, 800);
	}
	assert_int_equal(cfg.slot_count, 3);
	assert_string_equal(cfg.slot[1], "/var/lib/skinplay/show-b.skn");
	assert_string_equal(cfg.slot[2], "/usr/share/skinplay/demo.skn");
	assert_int_equal(cfg.max_fps, 60);
	assert_int_equal(cfg.threads, 0);
	assert_int_equal(cfg.split_verts, BOARD_SPLIT_AUTO);
	assert_int_equal(cfg.streams, BOARD_STREAMS_COMPACT);
}

static void test_host_board(void **state)
{
	(void)state;
	parse_file("board/host/board.ini");
	assert_string_equal(cfg.input, "keyboard");
	assert_false(cfg.button[CONTROL_BTN_ALGO].present);
	assert_int_equal(cfg.slot_count, 3);
	assert_string_equal(cfg.slot[2], "/usr/share/skinplay/demo.skn");
	assert_int_equal(cfg.threads, 0); /* not given: auto */
	assert_int_equal(cfg.algo, -1);   /* commented out: the program's */
	assert_int_equal(cfg.view, -1);
}

/* [display] algo and view: the starting method and view, by modes.h'
 * names in any case, like the other keys; not given: -1 (the program's
 * default). */
static void test_display_algo_and_view(void **state)
{
	(void)state;
	skp_error err;
	assert_int_equal(parse("[display]\nhud = off\n", &err), SKP_OK);
	assert_int_equal(cfg.algo, -1);
	assert_int_equal(cfg.view, -1);
	assert_int_equal(parse("[display]\nalgo = compare\nview = difference\n", &err), SKP_OK);
	assert_int_equal(cfg.problem_count, 0);
	assert_int_equal(cfg.algo, SKIN_COMPARE);
	assert_int_equal(cfg.view, RENDER_VIEW_DIFFERENCE);
	assert_int_equal(parse("[Display]\nALGO = DQBS-Fixed\nView = Weights\n", &err), SKP_OK);
	assert_int_equal(cfg.problem_count, 0);
	assert_int_equal(cfg.algo, SKIN_DQBS_FIXED);
	assert_int_equal(cfg.view, RENDER_VIEW_WEIGHTS);
	/* every name modes.h has is taken */
	for (int i = 0; i < SKIN_SHOW_COUNT; i++) {
		char text[64];
		snprintf(text, sizeof text, "[display]\nalgo = %s\n", skin_algo_name(i));
		assert_int_equal(parse(text, &err), SKP_OK);
		assert_int_equal(cfg.algo, i);
	}
	for (int i = 0; i < RENDER_VIEW_COUNT; i++) {
		char text[64];
		snprintf(text, sizeof text, "[display]\nview = %s\n", render_view_name(i));
		assert_int_equal(parse(text, &err), SKP_OK);
		assert_int_equal(cfg.view, i);
	}
	/* a bad one: one problem, the other keys still taken, the default kept */
	assert_int_equal(parse("[display]\nview = skeleton\nalgo = fast\nhud = off\n", &err), SKP_OK);
	assert_int_equal(cfg.problem_count, 1);
	assert_int_equal(cfg.problem[0].line, 3);
	assert_int_equal(cfg.algo, -1);
	assert_int_equal(cfg.view, RENDER_VIEW_SKELETON);
	assert_int_equal(cfg.hud, BOARD_HUD_OFF);
	assert_int_equal(parse("[display]\nalgo = lbs\nview = xray\n", &err), SKP_OK);
	assert_int_equal(cfg.problem_count, 1);
	assert_int_equal(cfg.problem[0].line, 3);
	assert_int_equal(cfg.algo, SKIN_LBS);
	assert_int_equal(cfg.view, -1);
}

static void test_skin_section(void **state)
{
	(void)state;
	skp_error err;
	assert_int_equal(parse("[skin]\nthreads = 3\nsplit_verts = 20000\nstreams = compact\n", &err), SKP_OK);
	assert_int_equal(cfg.threads, 3);
	assert_int_equal(cfg.split_verts, 20000);
	assert_int_equal(cfg.streams, BOARD_STREAMS_COMPACT);
	assert_int_equal(parse("[Skin]\nthreads = AUTO\n", &err), SKP_OK);
	assert_int_equal(cfg.threads, 0);
	assert_int_equal(cfg.split_verts, BOARD_SPLIT_VERTS);
	assert_int_equal(parse("[skin]\nsplit_verts = Auto\n", &err), SKP_OK);
	assert_int_equal(cfg.split_verts, BOARD_SPLIT_AUTO);
}

static void test_show_section_and_yaw(void **state)
{
	(void)state;
	skp_error err;
	assert_int_equal(parse("[display]\nplatform = kms\n", &err), SKP_OK);
	assert_int_equal(cfg.yaw_mode, -1); /* not given: the program's default (auto) */
	assert_true(cfg.speed == 1.0);
	assert_int_equal(cfg.blend_ms, BOARD_BLEND_MS);
	assert_int_equal(cfg.root, BOARD_ROOT_IN_PLACE);
	assert_int_equal(cfg.loop, BOARD_LOOP_SHOW);
	assert_int_equal(parse("[show]\nspeed = 0.5\nblend_ms = 0\nroot = Travel\nloop = clip\n[display]\nyaw = -90\n", &err),
			 SKP_OK);
	assert_true(cfg.speed == 0.5);
	assert_int_equal(cfg.blend_ms, 0);
	assert_int_equal(cfg.root, BOARD_ROOT_TRAVEL);
	assert_int_equal(cfg.loop, BOARD_LOOP_CLIP);
	assert_int_equal(cfg.yaw_mode, 1);
	assert_true(cfg.yaw_deg == -90.0f);
	assert_int_equal(cfg.sync, 0);
	assert_int_equal(cfg.show_buttons, 1);
	assert_int_equal(parse("[show]\nsync = clock\nepoch = 2026-01-01T00:00:10.5Z\nbuttons = off\n", &err), SKP_OK);
	assert_int_equal(cfg.sync, 1);
	assert_true(cfg.epoch_ns == 1767225610500000000LL);
	assert_int_equal(cfg.show_buttons, 0);
	assert_int_equal(parse("[display]\nyaw = AUTO\n", &err), SKP_OK);
	assert_int_equal(cfg.yaw_mode, 0);
	parse_file("board/rpi4/board.ini");
	assert_int_equal(cfg.yaw_mode, 0);
	assert_true(cfg.speed == 1.0);
	assert_int_equal(cfg.root, BOARD_ROOT_IN_PLACE);
}

static void test_inheritance_and_syntax(void **state)
{
	(void)state;
	skp_error err;
	const char *text = "; comment\r\n"
			   "[input]\n"
			   "debounce_ms = 12\n"
			   "[button.view]   # trailing comment\n"
			   "line=4\n"
			   "active = HIGH\n"
			   "bias = pull-down\n"
			   "long_press_ms = 1500\n"
			   "[Button.Algo]\n"
			   "  line = 5  \n"
			   "debounce_ms = 0\n"
			   "[storage]\n"
			   "slot = /data/a#1.skn\n"
			   "[input]\n"
			   "long_press_ms = 600\n";
	assert_int_equal(parse(text, &err), SKP_OK);
	board_button *v = &cfg.button[CONTROL_BTN_VIEW], *a = &cfg.button[CONTROL_BTN_ALGO];
	assert_int_equal(v->line, 4);
	assert_false(v->active_low);
	assert_int_equal(v->bias, BOARD_BIAS_PULL_DOWN);
	assert_int_equal(v->deb.debounce_ms, 12);     /* from [input] */
	assert_int_equal(v->deb.long_press_ms, 1500); /* its own, over [input]'s later 600 */
	assert_int_equal(a->deb.debounce_ms, 0);
	assert_int_equal(a->deb.long_press_ms, 600);
	assert_false(cfg.button[CONTROL_BTN_PLAY].present);
	assert_string_equal(cfg.slot[0], "/data/a#1.skn");
	assert_int_equal(cfg.rotation, -1);            /* not given */
	assert_int_equal(cfg.hud, -1);
}

typedef struct bad_case {
	const char *text;
	long line;
	const char *needle;
} bad_case;

static void test_mistakes_name_line_and_key(void **state)
{
	(void)state;
	static const bad_case cases[] = {
		{ "[display]\nrotation = 45\n", 2, "key 'rotation' in [display]: expected 0, 90, 180 or 270, found '45'" },
		{ "[display]\nsize = 1280*720\n", 2, "key 'size' in [display]: expected WxH" },
		{ "[display]\nplatform = wayland\n", 2, "key 'platform'" },
		{ "[display]\ncolour = red\n", 2, "unknown key 'colour' in [display]" },
		{ "[display]\n\nhud = tourist\n", 3, "key 'hud' in [display]: expected visitor, engineer or off, found 'tourist'" },
		{ "\n\n[button.play]\nline = seventeen\n", 4, "key 'line' in [button.play]: expected a line offset" },
		{ "[button.play]\nactive = sideways\n", 2, "key 'active' in [button.play]: expected high or low" },
		{ "[button.play]\nbias = strong\n", 2, "key 'bias'" },
		{ "[button.menu]\nline = 3\n", 2, "unknown section [button.menu]" },
		{ "[input]\nbackend = joystick\n", 2, "key 'backend' in [input]: expected gpio, keyboard, none or script:FILE" },
		{ "[input]\ndebounce_ms = -5\n", 2, "key 'debounce_ms'" },
		{ "[limits]\nmax_fps = fast\n", 2, "key 'max_fps' in [limits]" },
		{ "[skin]\nthreads = 0\n", 2, "key 'threads' in [skin]: expected auto or a thread count of 1..16, found '0'" },
		{ "[skin]\nsplit_verts = many\n", 2, "key 'split_verts' in [skin]: expected auto or a vertex count" },
		{ "[skin]\ncores = 4\n", 2, "unknown key 'cores' in [skin] (threads, split_verts, streams)" },
		{ "[skin]\nstreams = tiny\n", 2, "key 'streams' in [skin]: expected float or compact, found 'tiny'" },
		{ "[show]\nspeed = 5\n", 2, "key 'speed' in [show]: expected a speed from 0.1 to 4" },
		{ "[show]\nspeed = fast\n", 2, "key 'speed' in [show]" },
		{ "[show]\nblend_ms = 20000\n", 2, "key 'blend_ms' in [show]: expected a crossfade of 0..10000 ms" },
		{ "[show]\nroot = walking\n", 2, "key 'root' in [show]: expected in-place or travel, found 'walking'" },
		{ "[show]\nloop = yes\n", 2, "key 'loop' in [show]: expected show or clip, found 'yes'" },
		{ "[show]\nshuffle = on\n", 2, "unknown key 'shuffle' in [show] (speed, blend_ms, root, loop, sync, epoch, buttons)" },
		{ "[show]\nsync = ntp\n", 2, "key 'sync' in [show]: expected off or clock, found 'ntp'" },
		{ "[show]\nepoch = 2026-01-01 00:00\n", 2,
		  "key 'epoch' in [show]: expected an ISO 8601 UTC time such as 2026-01-01T00:00:00Z" },
		{ "[show]\nbuttons = maybe\n", 2, "key 'buttons' in [show]: expected on or off, found 'maybe'" },
		{ "[display]\nyaw = north\n", 2, "key 'yaw' in [display]: expected auto or degrees" },
		{ "[display]\n\nalgo = fast\n", 3,
		  "key 'algo' in [display]: expected lbs, dqbs, dqbs-fixed or compare, found 'fast'" },
		{ "[display]\nview = xray\n", 2,
		  "key 'view' in [display]: expected body, skeleton, weights or difference, found 'xray'" },
		{ "[display]\nmethod = lbs\n", 2,
		  "unknown key 'method' in [display] (platform, device, rotation, size, hud, yaw, algo, view)" },
		{ "[storage]\nslot = a\nslot = b\nslot = c\nslot = d\n", 5, "SKP_MAX_SLOTS" },
		{ "line = 3\n", 1, "key 'line' before any [section]" },
		{ "[display\n", 1, "expected ']'" },
		{ "[display]\njust words\n", 2, "expected 'key = value', found 'just words'" },
		{ "[display]\n= 3\n", 2, "missing key" },
		{ "[display]\ndevice = a\0b\n", 2, "NUL" },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		skp_error err;
		skp_mem_source src;
		const char *t = cases[i].text;
		size_t n = strlen(t);
		if (strstr(cases[i].needle, "NUL"))
			n += 1 + strlen(t + n + 1);
		skp_status st = board_config_read(&cfg, skp_mem_reader(&src, t, n), &err);
		const board_problem *p = &cfg.problem[0];
		if (st != SKP_OK || cfg.problem_count != 1 || p->line != cases[i].line || !strstr(p->msg, cases[i].needle))
			fail_msg("case %zu: status %d, %d problems, line %ld, '%s'", i, st, cfg.problem_count, p->line, p->msg);
	}
}

/* After a mistake the file goes on, the bad key keeps its default. */
static void test_mistakes_keep_defaults(void **state)
{
	(void)state;
	skp_error err;
	assert_int_equal(parse("[display]\nrotation = 45\nhud = engineer\n[skin]\nthreads = 0\nstreams = compact\n"
			       "[input]\ndebounce_ms = -5\n[storage]\nslot = a\nslot = b\nslot = c\nslot = d\n", &err), SKP_OK);
	assert_int_equal(cfg.problem_count, 4);
	assert_int_equal(cfg.rotation, -1);
	assert_int_equal(cfg.hud, BOARD_HUD_ENGINEER);
	assert_int_equal(cfg.threads, 0);
	assert_int_equal(cfg.streams, BOARD_STREAMS_COMPACT);
	assert_int_equal(cfg.button[CONTROL_BTN_PLAY].deb.debounce_ms, BOARD_DEBOUNCE_MS);
	assert_int_equal(cfg.slot_count, 3);
	assert_string_equal(cfg.slot[2], "c");
	/* a header that does not close: its keys belong nowhere; then on */
	assert_int_equal(parse("[display\nhud = off\n[skin]\nthreads = 2\n", &err), SKP_OK);
	assert_int_equal(cfg.problem_count, 2);
	assert_int_equal(cfg.problem[1].line, 2);
	assert_non_null(strstr(cfg.problem[1].msg, "unknown section [?]"));
	assert_int_equal(cfg.hud, -1);
	assert_int_equal(cfg.threads, 2);
	/* a Windows editor's byte order mark and CRLF: no mistake */
	assert_int_equal(parse("\xef\xbb\xbf[display]\r\nhud = visitor\r\n", &err), SKP_OK);
	assert_int_equal(cfg.problem_count, 0);
	assert_int_equal(cfg.hud, BOARD_HUD_VISITOR);
	/* past the list, counted */
	assert_int_equal(parse("[x]\na=1\nb=1\nc=1\nd=1\ne=1\nf=1\ng=1\nh=1\ni=1\nj=1\n", &err), SKP_OK);
	assert_int_equal(cfg.problem_count, 10);
	assert_int_equal(cfg.problem[BOARD_MAX_PROBLEMS - 1].line, 9);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_rpi4_board),
		cmocka_unit_test(test_host_board),
		cmocka_unit_test(test_show_section_and_yaw),
		cmocka_unit_test(test_display_algo_and_view),
		cmocka_unit_test(test_skin_section),
		cmocka_unit_test(test_inheritance_and_syntax),
		cmocka_unit_test(test_mistakes_name_line_and_key),
		cmocka_unit_test(test_mistakes_keep_defaults),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
