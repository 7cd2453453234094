/* The kiosk's controls (controls.h): every button, short and long, and the log
 * line each action produces. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <string.h>

#include "controls.h"

static control_action ev(controls_state *s, int b, int kind, char *log)
{
	control_event e = { (uint8_t)b, (uint8_t)kind, 0 };
	return controls_handle(s, &e, log, 96);
}

/* A short press: press then release. Returns the action of whichever did
 * something; log gets that line. */
static control_action tap(controls_state *s, int b, char *log)
{
	char l1[96], l2[96];
	control_action a = ev(s, b, CONTROL_PRESS, l1);
	control_action r = ev(s, b, CONTROL_RELEASE, l2);
	assert_true(a == CONTROL_ACT_NONE || r == CONTROL_ACT_NONE); /* one action per tap */
	strcpy(log, a != CONTROL_ACT_NONE ? l1 : l2);
	return a != CONTROL_ACT_NONE ? a : r;
}

static void test_algo_cycles_on_press(void **state)
{
	(void)state;
	static const char *const want[] = { "input: ALGO -> dqbs", "input: ALGO -> dqbs-fixed",
					    "input: ALGO -> compare", "input: ALGO -> lbs" };
	controls_state s;
	char log[96];
	controls_init(&s, SKIN_LBS, RENDER_VIEW_BODY, 0, 1);
	for (int i = 0; i < 4; i++) {
		assert_int_equal(ev(&s, CONTROL_BTN_ALGO, CONTROL_PRESS, log), CONTROL_ACT_ALGO);
		assert_string_equal(log, want[i]);
		assert_int_equal(s.algo, (i + 1) % 4);
		assert_int_equal(ev(&s, CONTROL_BTN_ALGO, CONTROL_RELEASE, log), CONTROL_ACT_NONE);
		assert_string_equal(log, "");
	}
	/* a long press of ALGO does nothing more */
	ev(&s, CONTROL_BTN_ALGO, CONTROL_PRESS, log);
	assert_int_equal(ev(&s, CONTROL_BTN_ALGO, CONTROL_LONG, log), CONTROL_ACT_NONE);
	assert_int_equal(s.algo, SKIN_DQBS);
}

static void test_play_short_and_long(void **state)
{
	(void)state;
	controls_state s;
	char log[96];
	controls_init(&s, SKIN_DQBS, RENDER_VIEW_BODY, 0, 1);
	assert_int_equal(s.playing, 1);
	/* nothing on press: it may become a long press */
	assert_int_equal(ev(&s, CONTROL_BTN_PLAY, CONTROL_PRESS, log), CONTROL_ACT_NONE);
	assert_int_equal(ev(&s, CONTROL_BTN_PLAY, CONTROL_RELEASE, log), CONTROL_ACT_PLAY);
	assert_string_equal(log, "input: PLAY -> pause");
	assert_int_equal(s.playing, 0);
	assert_int_equal(tap(&s, CONTROL_BTN_PLAY, log), CONTROL_ACT_PLAY);
	assert_string_equal(log, "input: PLAY -> play");
	/* long: restart, and the release after it does not also toggle */
	ev(&s, CONTROL_BTN_PLAY, CONTROL_PRESS, log);
	assert_int_equal(ev(&s, CONTROL_BTN_PLAY, CONTROL_LONG, log), CONTROL_ACT_RESTART);
	assert_string_equal(log, "input: PLAY long -> restart");
	assert_int_equal(ev(&s, CONTROL_BTN_PLAY, CONTROL_LONG, log), CONTROL_ACT_NONE);
	assert_int_equal(ev(&s, CONTROL_BTN_PLAY, CONTROL_RELEASE, log), CONTROL_ACT_NONE);
	assert_int_equal(s.playing, 1);
}

static void test_next_wraps_over_clips(void **state)
{
	(void)state;
	controls_state s;
	char log[96];
	controls_init(&s, SKIN_DQBS, RENDER_VIEW_BODY, 0, 3);
	assert_int_equal(tap(&s, CONTROL_BTN_NEXT, log), CONTROL_ACT_CLIP);
	assert_string_equal(log, "input: NEXT -> clip 2/3");
	tap(&s, CONTROL_BTN_NEXT, log);
	assert_int_equal(tap(&s, CONTROL_BTN_NEXT, log), CONTROL_ACT_CLIP);
	assert_string_equal(log, "input: NEXT -> clip 1/3");
	assert_int_equal(s.clip, 0);
	controls_init(&s, SKIN_DQBS, RENDER_VIEW_BODY, 0, 0); /* no clip count: one */
	tap(&s, CONTROL_BTN_NEXT, log);
	assert_string_equal(log, "input: NEXT -> clip 1/1");
}

static void test_view_and_gpu(void **state)
{
	(void)state;
	controls_state s;
	char log[96];
	controls_init(&s, SKIN_DQBS, RENDER_VIEW_BODY, 0, 1);
	assert_int_equal(tap(&s, CONTROL_BTN_VIEW, log), CONTROL_ACT_VIEW);
	assert_string_equal(log, "input: VIEW -> skeleton");
	tap(&s, CONTROL_BTN_VIEW, log);
	assert_string_equal(log, "input: VIEW -> weights");
	tap(&s, CONTROL_BTN_VIEW, log);
	assert_string_equal(log, "input: VIEW -> difference");
	tap(&s, CONTROL_BTN_VIEW, log);
	assert_string_equal(log, "input: VIEW -> body");
	ev(&s, CONTROL_BTN_VIEW, CONTROL_PRESS, log);
	assert_int_equal(ev(&s, CONTROL_BTN_VIEW, CONTROL_LONG, log), CONTROL_ACT_GPU);
	assert_string_equal(log, "input: VIEW long -> gpu skinning");
	assert_int_equal(ev(&s, CONTROL_BTN_VIEW, CONTROL_RELEASE, log), CONTROL_ACT_NONE);
	assert_int_equal(s.view, RENDER_VIEW_BODY);
	ev(&s, CONTROL_BTN_VIEW, CONTROL_PRESS, log);
	ev(&s, CONTROL_BTN_VIEW, CONTROL_LONG, log);
	assert_string_equal(log, "input: VIEW long -> cpu skinning");
	assert_int_equal(s.gpu, 0);
}

/* Releases or long presses without a press seen (a button held when the
 * controls started), unknown buttons and kinds: nothing happens. */
static void test_stray_events(void **state)
{
	(void)state;
	controls_state s, before;
	char log[96];
	controls_init(&s, SKIN_COMPARE, RENDER_VIEW_WEIGHTS, 1, 2);
	before = s;
	for (int b = 0; b < CONTROL_BTN_COUNT; b++) {
		assert_int_equal(ev(&s, b, CONTROL_RELEASE, log), CONTROL_ACT_NONE);
		assert_int_equal(ev(&s, b, CONTROL_LONG, log), CONTROL_ACT_NONE);
	}
	assert_int_equal(ev(&s, CONTROL_BTN_COUNT, CONTROL_PRESS, log), CONTROL_ACT_NONE);
	assert_int_equal(ev(&s, CONTROL_BTN_ALGO, 7, log), CONTROL_ACT_NONE);
	assert_string_equal(log, "");
	assert_memory_equal(&s, &before, sizeof s);
	/* two buttons held together act independently */
	ev(&s, CONTROL_BTN_PLAY, CONTROL_PRESS, log);
	assert_int_equal(ev(&s, CONTROL_BTN_ALGO, CONTROL_PRESS, log), CONTROL_ACT_ALGO);
	assert_string_equal(log, "input: ALGO -> lbs");
	assert_int_equal(ev(&s, CONTROL_BTN_PLAY, CONTROL_RELEASE, log), CONTROL_ACT_PLAY);
	/* a small log buffer is cut, not overrun */
	char tiny[8];
	memset(tiny, 'x', sizeof tiny);
	control_event e = { CONTROL_BTN_ALGO, CONTROL_PRESS, 0 };
	controls_handle(&s, &e, tiny, 6);
	assert_string_equal(tiny, "input");
	assert_int_equal(tiny[6], 'x');
}

static void test_names(void **state)
{
	(void)state;
	assert_int_equal(control_button_find("algo"), CONTROL_BTN_ALGO);
	assert_int_equal(control_button_find("View"), CONTROL_BTN_VIEW);
	assert_int_equal(control_button_find("menu"), -1);
	assert_string_equal(control_button_name(CONTROL_BTN_NEXT), "NEXT");
	assert_string_equal(control_button_name(9), "?");
	assert_string_equal(skin_algo_name(SKIN_DQBS_FIXED), "dqbs-fixed");
	assert_string_equal(render_view_name(RENDER_VIEW_SKELETON), "skeleton");
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_algo_cycles_on_press),
		cmocka_unit_test(test_play_short_and_long),
		cmocka_unit_test(test_next_wraps_over_clips),
		cmocka_unit_test(test_view_and_gpu),
		cmocka_unit_test(test_stray_events),
		cmocka_unit_test(test_names),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
