/* The gate's range of motion (bind_rom.h) on the project's skeleton: the
 * moves it builds (hips, knees, ankles, shoulders, elbows, wrists, back,
 * neck), each a rigid turn of one bone and those below it about its head:
 * bones above stay, lengths stay, the turned bone ends up turned by the
 * move's angle; a knee bends backwards and a hip flexes forwards (the
 * feet say where front is). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "bind_rom.h"
#include "skel_roles.h"
#include "test_parse.h"

static skel s;
static skel_pose bind, posed;
static bind_rom rom;

static int setup(void **state)
{
	(void)state;
	skp_error err;
	if (test_parse_asf_file("assets/demo.asf", &s, &err) != SKP_OK)
		return -1;
	fk_pose(&s, NULL, &bind);
	bind_rom_build(&s, &bind, &rom);
	return 0;
}

static float len(const skel_pose *p, int b)
{
	return vec3_length(vec3_sub(p->tip[b], p->head[b]));
}

static const bind_rom_move *find(const char *bone, bind_rom_kind kind)
{
	int b = skel_find(&s, bone);
	for (int k = 0; k < rom.count; k++)
		if (rom.move[k].bone == b && rom.move[k].kind == kind)
			return &rom.move[k];
	fail_msg("no move '%s %s'", bone, bind_rom_kind_name(kind));
	return NULL;
}

static void test_moves_cover_the_body(void **state)
{
	(void)state;
	/* per leg 5, per arm 5, the back 2, the neck 2 */
	assert_int_equal(rom.count, 24);
	find("lfemur", BIND_ROM_FORWARD);
	find("rtibia", BIND_ROM_BEND);
	find("lowerback", BIND_ROM_TWIST);
	find("lowerneck", BIND_ROM_BEND);
	assert_string_equal(bind_rom_kind_name(BIND_ROM_TWIST), "twisted");
}

static void test_moves_are_rigid(void **state)
{
	(void)state;
	for (int k = 0; k < rom.count; k++) {
		const bind_rom_move *m = &rom.move[k];
		bind_rom_pose(&s, &bind, m, &posed);
		for (int b = 0; b < s.count; b++) {
			assert_true(fabsf(len(&posed, b) - len(&bind, b)) < 1e-4f * (1.0f + len(&bind, b)));
			if (!bind_rom_below(&s, b, m->bone))
				assert_memory_equal(&posed.tip[b], &bind.tip[b], sizeof(vec3));
		}
		vec3 a = vec3_normalize(vec3_sub(bind.tip[m->bone], bind.head[m->bone]));
		vec3 c = vec3_normalize(vec3_sub(posed.tip[m->bone], posed.head[m->bone]));
		float deg = acosf(fmaxf(-1.0f, fminf(1.0f, vec3_dot(a, c)))) * 57.29578f;
		if (m->kind != BIND_ROM_TWIST && fabsf(deg - (float)m->degrees) > 0.5f)
			fail_msg("move %d: turned %.2f degrees, not %d", k, (double)deg, m->degrees);
		assert_true(vec3_length(vec3_sub(posed.head[m->bone], bind.head[m->bone])) < 1e-5f);
	}
}

static void test_directions(void **state)
{
	(void)state;
	skel_roles r;
	skel_find_roles(&s, &bind, &r);
	int foot = skel_find(&s, "lfoot"), femur = skel_find(&s, "lfemur"), tibia = skel_find(&s, "ltibia");
	vec3 toes = vec3_sub(bind.tip[foot], bind.head[foot]);
	bind_rom_pose(&s, &bind, find("lfemur", BIND_ROM_FORWARD), &posed);
	/* the knee goes where the toes point */
	assert_true(vec3_dot(vec3_sub(posed.tip[femur], bind.tip[femur]), toes) > 0.0f);
	bind_rom_pose(&s, &bind, find("ltibia", BIND_ROM_BEND), &posed);
	assert_true(vec3_dot(vec3_sub(posed.tip[tibia], bind.tip[tibia]), toes) < 0.0f);
	assert_true(bind_rom_below(&s, foot, femur));
	assert_false(bind_rom_below(&s, femur, foot));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_moves_cover_the_body),
		cmocka_unit_test(test_moves_are_rigid),
		cmocka_unit_test(test_directions),
	};
	return cmocka_run_group_tests(tests, setup, NULL);
}
