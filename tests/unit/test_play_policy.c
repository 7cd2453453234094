/* What playback decides around the engine (app/play): a posed body's
 * facing from its feet (play_extent.h), at every turn of the root; the
 * next playable clip, the slots in sequence order, and the slot chosen
 * from their checks (play_policy.h). The engine itself: test_play.c. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "play_extent.h"
#include "play_policy.h"
#include "test_parse.h"

#define DEG ((float)(M_PI / 180.0))

static skel s;

static void test_facing_follows_the_feet(void **state)
{
	(void)state;
	static const char *legs =
		":root\n order TX TY TZ RX RY RZ\n position 0 1 0\n:bonedata\n"
		" begin\n name leg\n direction 0 -1 0\n length 0.9\n axis 0 0 0 XYZ\n end\n"
		" begin\n name foot\n direction 0 0 1\n length 0.2\n axis 0 0 0 XYZ\n end\n"
		" begin\n name head\n direction 0 1 0\n length 0.8\n axis 0 0 0 XYZ\n end\n"
		":hierarchy\n begin\n root leg head\n leg foot\n end\n";
	static skel_pose p;
	skp_error err;
	assert_int_equal(test_parse_asf(legs, strlen(legs), &s, &err), SKP_OK);
	float v[SKP_MAX_DOF] = { 0 };
	for (int deg = -180; deg < 180; deg += 45) {
		v[4] = (float)deg * DEG; /* root RY */
		fk_pose(&s, v, &p);
		float sn = 0, cs = 0;
		assert_true(play_pose_facing(&s, &p, &sn, &cs) > 0.5f);
		float got = atan2f(sn, cs), err_rad = remainderf(got - (float)deg * DEG, 2.0f * (float)M_PI);
		if (fabsf(err_rad) > 1e-4f)
			fail_msg("root turned %d degrees: facing %g degrees", deg, got / DEG);
	}
}

static void test_policy_clips_and_slots(void **state)
{
	(void)state;
	const uint8_t playable[5] = { 0, 1, 0, 0, 1 };
	assert_int_equal(play_next_playable(playable, 5, 0), 1);
	assert_int_equal(play_next_playable(playable, 5, 2), 4);
	assert_int_equal(play_next_playable(playable, 5, 5), 1);
	const uint8_t none[2] = { 0, 0 };
	assert_int_equal(play_next_playable(none, 2, 0), -1);
	const uint64_t seq[4] = { 5, 9, 7, 9 };
	const uint8_t opened[4] = { 1, 1, 0, 1 };
	int order[4];
	assert_int_equal(play_slots_by_sequence(seq, opened, 4, order), 3);
	assert_int_equal(order[0], 1);
	assert_int_equal(order[1], 3);
	assert_int_equal(order[2], 0);
}

/* Slot checks from tables: accepted, blocks beyond repair. */
typedef struct slots {
	int accepted[4];
	long beyond[4];
	int last_accepted;
} slots;

static int slot_accept(void *ctx, int i)
{
	slots *t = ctx;
	t->last_accepted = i;
	return t->accepted[i];
}

static long slot_damaged(void *ctx, int i)
{
	return ((slots *)ctx)->beyond[i];
}

static void test_slot_choice(void **state)
{
	(void)state;
	int order[3] = { 2, 0, 1 };
	slots t = { { 1, 1, 1, 0 }, { 0, 0, 3, 0 }, -1 };
	play_slot_checks c = { &t, slot_accept, slot_damaged };
	assert_int_equal(play_slot_choose(order, 3, 3, &c), 0); /* the newest has a lost block: the next */
	t.beyond[0] = t.beyond[1] = 2;
	assert_int_equal(play_slot_choose(order, 3, 3, &c), 2); /* all damaged: the newest plays what it can */
	assert_int_equal(t.last_accepted, 2);
	assert_int_equal(play_slot_choose(order, 1, 1, &c), 2); /* one slot: damage is not asked */
	t.accepted[2] = 0;
	assert_int_equal(play_slot_choose(order, 3, 3, &c), 0);
	t.accepted[0] = t.accepted[1] = 0;
	assert_int_equal(play_slot_choose(order, 3, 3, &c), -1);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_facing_follows_the_feet),
		cmocka_unit_test(test_policy_clips_and_slots),
		cmocka_unit_test(test_slot_choice),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
