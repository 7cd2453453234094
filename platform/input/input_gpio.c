/* Buttons on GPIO lines: one both-edge event request per button, the line
 * event fds polled by the main loop (no thread), each edge fed to the
 * button's debouncer with the kernel's timestamp. With ACTIVE_LOW the kernel
 * reports edges of the active level, so a rising edge is always "pressed".
 * The chip and line calls and the event decoding are libgpiod's, behind the
 * seam in input.h: input_gpiod1.c (libgpiod 1.6) or input_gpiod2.c (2.x),
 * chosen by the Makefile from the library's pkg-config version. */
#include "input.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>

#define CONSUMER "skinplay"

typedef struct gpio_button {
	int button;              /* control_button */
	void *line;
	int fd;
	debounce_config cfg;
	debounce_data deb;
} gpio_button;

static struct {
	const input_gpio_ops *ops;
	void *chip;
	gpio_button btn[CONTROL_BTN_COUNT];
	int count;
} g;

void input_gpio_set_ops(const input_gpio_ops *ops)
{
	g.ops = ops;
}

static const input_gpio_ops *ops(void)
{
	return g.ops ? g.ops : &input_gpio_libgpiod;
}

int input_gpio_flags(const board_button *b)
{
	int f = b->active_low ? INPUT_GPIO_ACTIVE_LOW : 0;
	switch (b->bias) {
	case BOARD_BIAS_DISABLE: return f | INPUT_GPIO_BIAS_DISABLE;
	case BOARD_BIAS_PULL_UP: return f | INPUT_GPIO_PULL_UP;
	case BOARD_BIAS_PULL_DOWN: return f | INPUT_GPIO_PULL_DOWN;
	default: return f;
	}
}

static void gpio_shutdown(void)
{
	for (int i = 0; i < g.count; i++)
		ops()->release(g.btn[i].line);
	g.count = 0;
	if (g.chip)
		ops()->close_chip(g.chip);
	g.chip = NULL;
}

static int request_button(const board_config *cfg, int b, uint64_t now_ms, skp_error *err)
{
	const board_button *bb = &cfg->button[b];
	gpio_button *gb = &g.btn[g.count];
	gb->line = ops()->request(g.chip, bb->line, input_gpio_flags(bb), CONSUMER);
	if (!gb->line)
		return skp_fail(err, SKP_ERR_IO, 0, "%s line %u (%s button): %s", cfg->chip, bb->line,
				control_button_name(b), strerror(errno)), -1;
	g.count++;
	gb->button = b;
	gb->cfg = bb->deb;
	gb->fd = ops()->event_fd(gb->line);
	int level = ops()->get_value(gb->line);
	if (gb->fd < 0 || level < 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s line %u: no event fd or value: %s", cfg->chip, bb->line,
				strerror(errno)), -1;
	/* the main loop must never block on a line */
	int fl = fcntl(gb->fd, F_GETFL);
	if (fl < 0 || fcntl(gb->fd, F_SETFL, fl | O_NONBLOCK) < 0)
		return skp_fail(err, SKP_ERR_IO, 0, "%s line %u: %s", cfg->chip, bb->line, strerror(errno)), -1;
	debounce_init(&gb->deb, level, now_ms);
	return 0;
}

static int gpio_init(const board_config *cfg, const char *arg, uint64_t now_ms, skp_error *err)
{
	(void)arg;
	g.count = 0;
	if (!cfg || !cfg->chip[0])
		return skp_fail(err, SKP_ERR_RANGE, 0, "no GPIO chip: give [input] chip = ... in the board config"), -1;
	g.chip = ops()->open_chip(cfg->chip);
	if (!g.chip)
		return skp_fail(err, SKP_ERR_IO, 0, "cannot open GPIO chip '%s': %s", cfg->chip, strerror(errno)), -1;
	for (int b = 0; b < CONTROL_BTN_COUNT; b++)
		if (cfg->button[b].present && request_button(cfg, b, now_ms, err) < 0)
			goto fail;
	if (g.count == 0) {
		skp_fail(err, SKP_ERR_RANGE, 0, "no [button.*] section with a line in the board config");
		goto fail;
	}
	return 0;
fail:
	gpio_shutdown();
	return -1;
}

/* A kernel timestamp far from now is from another clock (kernels before
 * 5.7 stamp v1 events with CLOCK_REALTIME): use the time of reading. */
static uint64_t event_ms(const input_gpio_edge *e, uint64_t now_ms)
{
	uint64_t t = e->ts_ns / 1000000u;
	return t + 10000 < now_ms || t > now_ms + 10000 ? now_ms : t;
}

/* Drains one line's fd while there is room for one edge's events. */
static int drain(gpio_button *gb, uint64_t now_ms, control_event *ev, int room, skp_error *err)
{
	input_gpio_edge e;
	int n = 0;
	while (room - n >= 3) {
		if (input_gpio_read_edge(gb->fd, &e) != 0) {
			if (errno == EAGAIN || errno == EWOULDBLOCK)
				break;
			return skp_fail(err, SKP_ERR_IO, 0, "reading %s button events: %s",
					control_button_name(gb->button), strerror(errno)), -1;
		}
		int level = e.rising;
		unsigned bits = debounce_update(&gb->cfg, &gb->deb, event_ms(&e, now_ms), level);
		n += input_emit(bits, gb->button, gb->deb.last_ms, ev + n);
	}
	return n;
}

static int gpio_read(uint64_t now_ms, control_event *ev, int max, skp_error *err)
{
	int n = 0;
	for (int i = 0; i < g.count; i++) {
		int k = drain(&g.btn[i], now_ms, ev + n, max - n, err);
		if (k < 0)
			return -1;
		n += k;
	}
	/* timers: a level that stayed quiet long enough, a long press */
	for (int i = 0; i < g.count && max - n >= 3; i++) {
		gpio_button *gb = &g.btn[i];
		unsigned bits = debounce_update(&gb->cfg, &gb->deb, now_ms, DEBOUNCE_TICK);
		n += input_emit(bits, gb->button, gb->deb.last_ms, ev + n);
	}
	return n;
}

const input_backend input_gpio = { "gpio", gpio_init, gpio_read, gpio_shutdown, NULL };
