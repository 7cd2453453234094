/* The input backends without hardware. The gpio backend runs for real with
 * its chip and line requests replaced by pipes: the kernel's own event
 * structs written into a pipe are decoded by the build's libgpiod seam
 * exactly as a line's event fd would be on the board (struct gpioevent_data
 * through gpiod_line_event_read_fd() with libgpiod 1.6, struct
 * gpio_v2_line_event with 2.x; SKP_GPIOD_API says which). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <linux/gpio.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "input.h"

/* the backends themselves, not only through input_find() */
extern const input_backend input_gpio, input_keyboard, input_script, input_none;

/* The fake chip: one pipe per requested line. */
typedef struct fake_line {
	unsigned int offset;
	int flags;
	int pipe[2];
	int value;
	int released;
} fake_line;

static struct {
	char chip_name[64];
	int chip_open, fail_offset;
	fake_line line[8];
	int count;
} fake;

static int chip_token;

static void *f_open_chip(const char *chip)
{
	if (!strcmp(chip, "missing")) {
		errno = ENOENT;
		return NULL;
	}
	snprintf(fake.chip_name, sizeof fake.chip_name, "%s", chip);
	fake.chip_open = 1;
	return &chip_token;
}

static void *f_request(void *chip, unsigned int offset, int flags, const char *consumer)
{
	assert_ptr_equal(chip, &chip_token);
	assert_string_equal(consumer, "skinplay");
	if ((int)offset == fake.fail_offset) {
		errno = EBUSY;
		return NULL;
	}
	fake_line *l = &fake.line[fake.count++];
	l->offset = offset;
	l->flags = flags;
	l->released = 0;
	assert_int_equal(pipe(l->pipe), 0);
	return l;
}

static int f_event_fd(void *line)
{
	return ((fake_line *)line)->pipe[0];
}

static int f_get_value(void *line)
{
	return ((fake_line *)line)->value;
}

static void f_release(void *line)
{
	fake_line *l = line;
	close(l->pipe[0]);
	close(l->pipe[1]);
	l->released = 1;
}

static void f_close_chip(void *chip)
{
	assert_ptr_equal(chip, &chip_token);
	fake.chip_open = 0;
}

static const input_gpio_ops fake_ops = { f_open_chip, f_request, f_event_fd, f_get_value, f_release, f_close_chip };

static board_config board;

static int setup(void **state)
{
	(void)state;
	memset(&fake, 0, sizeof fake);
	fake.fail_offset = -1;
	board_config_defaults(&board);
	snprintf(board.chip, sizeof board.chip, "gpiochip0");
	static const unsigned lines[CONTROL_BTN_COUNT] = { 17, 27, 22, 23 };
	for (int b = 0; b < CONTROL_BTN_COUNT; b++) {
		board.button[b].present = 1;
		board.button[b].line = lines[b];
	}
	input_gpio_set_ops(&fake_ops);
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	input_gpio_set_ops(NULL);
	return 0;
}

/* A kernel line event: an edge of the active level at t_ms. */
static void edge(int button, int rising, uint64_t t_ms)
{
#if SKP_GPIOD_API >= 2
	struct gpio_v2_line_event e;
	memset(&e, 0, sizeof e);
	e.timestamp_ns = t_ms * 1000000u + 123456u;
	e.id = rising ? GPIO_V2_LINE_EVENT_RISING_EDGE : GPIO_V2_LINE_EVENT_FALLING_EDGE;
	e.offset = fake.line[button].offset;
#else
	struct gpioevent_data e;
	memset(&e, 0, sizeof e);
	e.timestamp = t_ms * 1000000u + 123456u;
	e.id = rising ? GPIOEVENT_EVENT_RISING_EDGE : GPIOEVENT_EVENT_FALLING_EDGE;
#endif
	assert_int_equal(write(fake.line[button].pipe[1], &e, sizeof e), (ssize_t)sizeof e);
}

static int read_at(uint64_t now, control_event *ev)
{
	skp_error err;
	int n = input_gpio.read(now, ev, INPUT_MAX_EVENTS, &err);
	if (n < 0)
		fail_msg("read: %s", err.msg);
	return n;
}

static void test_gpio_requests_lines_with_flags(void **state)
{
	(void)state;
	skp_error err;
	board.button[CONTROL_BTN_NEXT].active_low = 0;
	board.button[CONTROL_BTN_NEXT].bias = BOARD_BIAS_DISABLE;
	board.button[CONTROL_BTN_VIEW].present = 0;
	assert_int_equal(input_gpio.init(&board, NULL, 1000, &err), 0);
	assert_string_equal(fake.chip_name, "gpiochip0");
	assert_int_equal(fake.count, 3);
	assert_int_equal(fake.line[0].offset, 17);
	assert_int_equal(fake.line[0].flags, INPUT_GPIO_ACTIVE_LOW | INPUT_GPIO_PULL_UP);
	assert_int_equal(fake.line[2].offset, 22);
	assert_int_equal(fake.line[2].flags, INPUT_GPIO_BIAS_DISABLE);
	input_gpio.shutdown();
	assert_true(fake.line[0].released && fake.line[2].released);
	assert_false(fake.chip_open);
}

/* A bouncing press through the real decoder: one press after the debounce
 * time, then a long press, then one release. */
static void test_gpio_bouncing_press_through_libgpiod(void **state)
{
	(void)state;
	skp_error err;
	control_event ev[INPUT_MAX_EVENTS];
	assert_int_equal(input_gpio.init(&board, NULL, 1000, &err), 0);
	edge(CONTROL_BTN_PLAY, 1, 1100);
	edge(CONTROL_BTN_PLAY, 0, 1102);
	edge(CONTROL_BTN_PLAY, 1, 1105);
	edge(CONTROL_BTN_PLAY, 0, 1106);
	edge(CONTROL_BTN_PLAY, 1, 1110);
	assert_int_equal(read_at(1120, ev), 0);
	assert_int_equal(read_at(1139, ev), 0);
	assert_int_equal(read_at(1140, ev), 1);
	assert_int_equal(ev[0].button, CONTROL_BTN_PLAY);
	assert_int_equal(ev[0].kind, CONTROL_PRESS);
	assert_int_equal(ev[0].t_ms, 1140);
	assert_int_equal(read_at(1909, ev), 0);
	assert_int_equal(read_at(1910, ev), 1);
	assert_int_equal(ev[0].kind, CONTROL_LONG);
	edge(CONTROL_BTN_PLAY, 0, 2500);
	edge(CONTROL_BTN_PLAY, 1, 2501);
	edge(CONTROL_BTN_PLAY, 0, 2503);
	assert_int_equal(read_at(2520, ev), 0);
	assert_int_equal(read_at(2540, ev), 1);
	assert_int_equal(ev[0].kind, CONTROL_RELEASE);
	input_gpio.shutdown();
}

/* Two buttons at once; a whole press read in one go (a slow frame); an
 * event stamped far from now (another clock) is taken at now. */
static void test_gpio_two_buttons_and_late_reads(void **state)
{
	(void)state;
	skp_error err;
	control_event ev[INPUT_MAX_EVENTS];
	assert_int_equal(input_gpio.init(&board, NULL, 0, &err), 0);
	edge(CONTROL_BTN_ALGO, 1, 100);
	edge(CONTROL_BTN_VIEW, 1, 101);
	edge(CONTROL_BTN_ALGO, 0, 200);
	edge(CONTROL_BTN_VIEW, 0, 250);
	int n = read_at(400, ev);
	assert_int_equal(n, 4);
	int seen[CONTROL_BTN_COUNT][3] = { { 0 } };
	for (int i = 0; i < n; i++)
		seen[ev[i].button][ev[i].kind]++;
	assert_int_equal(seen[CONTROL_BTN_ALGO][CONTROL_PRESS], 1);
	assert_int_equal(seen[CONTROL_BTN_ALGO][CONTROL_RELEASE], 1);
	assert_int_equal(seen[CONTROL_BTN_VIEW][CONTROL_PRESS], 1);
	assert_int_equal(seen[CONTROL_BTN_VIEW][CONTROL_RELEASE], 1);
	assert_int_equal(seen[CONTROL_BTN_ALGO][CONTROL_LONG] + seen[CONTROL_BTN_VIEW][CONTROL_LONG], 0);
	/* press stamped in 1970 wall-clock terms: counted at the read time */
	edge(CONTROL_BTN_NEXT, 1, 1700000000000ull);
	assert_int_equal(read_at(500, ev), 0);
	assert_int_equal(read_at(530, ev), 1);
	assert_int_equal(ev[0].button, CONTROL_BTN_NEXT);
	assert_int_equal(ev[0].kind, CONTROL_PRESS);
	input_gpio.shutdown();
}

static void test_gpio_errors_release_everything(void **state)
{
	(void)state;
	skp_error err;
	snprintf(board.chip, sizeof board.chip, "missing");
	assert_int_equal(input_gpio.init(&board, NULL, 0, &err), -1);
	assert_non_null(strstr(err.msg, "cannot open GPIO chip 'missing'"));
	snprintf(board.chip, sizeof board.chip, "gpiochip0");
	fake.fail_offset = 22;
	assert_int_equal(input_gpio.init(&board, NULL, 0, &err), -1);
	assert_non_null(strstr(err.msg, "line 22 (NEXT button)"));
	assert_true(fake.line[0].released && fake.line[1].released);
	assert_false(fake.chip_open);
	fake.fail_offset = -1;
	for (int b = 0; b < CONTROL_BTN_COUNT; b++)
		board.button[b].present = 0;
	assert_int_equal(input_gpio.init(&board, NULL, 0, &err), -1);
	assert_non_null(strstr(err.msg, "no [button.*]"));
	assert_false(fake.chip_open);
	/* a truncated event from the fd is an I/O error, not garbage */
	setup(NULL);
	assert_int_equal(input_gpio.init(&board, NULL, 0, &err), 0);
	assert_int_equal(write(fake.line[0].pipe[1], "abc", 3), 3);
	control_event ev[INPUT_MAX_EVENTS];
	assert_int_equal(input_gpio.read(10, ev, INPUT_MAX_EVENTS, &err), -1);
	assert_non_null(strstr(err.msg, "ALGO"));
	input_gpio.shutdown();
}

static const char *write_script(const char *text)
{
	static char path[] = "/tmp/skp_script_XXXXXX";
	strcpy(path, "/tmp/skp_script_XXXXXX");
	int fd = mkstemp(path);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, text, strlen(text)), (ssize_t)strlen(text));
	close(fd);
	return path;
}

static void test_script_events_at_their_times(void **state)
{
	(void)state;
	skp_error err;
	control_event ev[INPUT_MAX_EVENTS];
	const char *path = write_script("# demo\n"
					"100 ALGO press\n"
					"150 algo release\n"
					"\n"
					"200 PLAY press   # held 900 ms: long press at 1000\n"
					"1100 PLAY release\n"
					"1100 VIEW press\n"
					"1150 VIEW release\n");
	assert_int_equal(input_script.init(&board, path, 5000, &err), 0);
	unlink(path);
	assert_int_equal(input_script.read(5099, ev, INPUT_MAX_EVENTS, &err), 0);
	assert_int_equal(input_script.read(5100, ev, INPUT_MAX_EVENTS, &err), 1);
	assert_int_equal(ev[0].button, CONTROL_BTN_ALGO);
	assert_int_equal(ev[0].kind, CONTROL_PRESS);
	assert_int_equal(ev[0].t_ms, 5100);
	assert_int_equal(input_script.read(5999, ev, INPUT_MAX_EVENTS, &err), 2); /* ALGO up, PLAY down */
	assert_int_equal(ev[1].kind, CONTROL_PRESS);
	assert_int_equal(input_script.read(6000, ev, INPUT_MAX_EVENTS, &err), 1);
	assert_int_equal(ev[0].button, CONTROL_BTN_PLAY);
	assert_int_equal(ev[0].kind, CONTROL_LONG);
	int n = input_script.read(9000, ev, INPUT_MAX_EVENTS, &err);
	assert_int_equal(n, 3);
	assert_int_equal(ev[0].kind, CONTROL_RELEASE);
	assert_int_equal(ev[1].button, CONTROL_BTN_VIEW);
	assert_int_equal(ev[1].kind, CONTROL_PRESS);
	assert_int_equal(ev[2].kind, CONTROL_RELEASE);
	assert_int_equal(input_script.read(99999, ev, INPUT_MAX_EVENTS, &err), 0);
	input_script.shutdown();
}

static void test_script_errors_name_file_and_line(void **state)
{
	(void)state;
	static const struct { const char *text; const char *want; } cases[] = {
		{ "100 ALGO press\n50 ALGO release\n", ":2: time 50 is before the previous line's 100" },
		{ "100 MENU press\n", ":1: unknown button 'MENU'" },
		{ "100 ALGO push\n", ":1: expected press or release, found 'push'" },
		{ "soon ALGO press\n", ":1: expected a time in ms >= 0, found 'soon'" },
		{ "# ok\n100 ALGO\n", ":2: expected 'TIME_MS BUTTON press|release'" },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		skp_error err;
		const char *path = write_script(cases[i].text);
		char want[256];
		snprintf(want, sizeof want, "%s%s", path, cases[i].want);
		int rc = input_script.init(&board, path, 0, &err);
		unlink(path);
		if (rc != -1 || strncmp(err.msg, want, strlen(want)) != 0)
			fail_msg("case %zu: rc %d, '%s' (want '%s')", i, rc, err.msg, want);
	}
	skp_error err;
	assert_int_equal(input_script.init(&board, "/nonexistent/s.txt", 0, &err), -1);
	assert_non_null(strstr(err.msg, "/nonexistent/s.txt: cannot open"));
}

static void test_find_backends(void **state)
{
	(void)state;
	const char *arg;
	assert_ptr_equal(input_find("gpio", &arg), &input_gpio);
	assert_null(arg);
	assert_ptr_equal(input_find("keyboard", &arg), &input_keyboard);
	assert_ptr_equal(input_find("none", &arg), &input_none);
	assert_ptr_equal(input_find("script:x.txt", &arg), &input_script);
	assert_string_equal(arg, "x.txt");
	assert_null(input_find("script:", &arg));
	assert_null(input_find("mouse", &arg));
	/* keyboard without a terminal: no events, no error */
	skp_error err;
	control_event ev[4];
	if (!isatty(STDIN_FILENO)) {
		assert_int_equal(input_keyboard.init(&board, NULL, 0, &err), 0);
		assert_int_equal(input_keyboard.read(0, ev, 4, &err), 0);
		input_keyboard.shutdown();
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_gpio_requests_lines_with_flags, setup, teardown),
		cmocka_unit_test_setup_teardown(test_gpio_bouncing_press_through_libgpiod, setup, teardown),
		cmocka_unit_test_setup_teardown(test_gpio_two_buttons_and_late_reads, setup, teardown),
		cmocka_unit_test_setup_teardown(test_gpio_errors_release_everything, setup, teardown),
		cmocka_unit_test_setup_teardown(test_script_events_at_their_times, setup, teardown),
		cmocka_unit_test_setup_teardown(test_script_errors_name_file_and_line, setup, teardown),
		cmocka_unit_test_setup_teardown(test_find_backends, setup, teardown),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
